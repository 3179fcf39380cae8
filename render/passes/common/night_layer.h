#pragma once
// The night's own light as the physical sky pass adds it (render/passes/sky/physical_sky.frag,
// SKYIG_NIGHT_LAYER): drawn by NightDiffusePass::drawLayer, read by PhysicalSkyPass::draw.
#include <glad/gl.h>
#include <glm/vec3.hpp>

#include <string>

namespace skyig::render {

// Above this elevation (degrees) the sky pass reads the night's light already dimmed by the
// transmittance to space at the layer's texels (NightLayer::transmitted); below it, and on the
// terrain, it applies the transmittance per pixel. Bilinear interpolation of the transmittance
// t = exp(-tau m(e)), m ~ 1 / sin e, over a texel of h radians errs by h^2 / 8 |t'' / t| =
// h^2 / 8 |(ln t)'^2 + (ln t)''| ~ h^2 / 8 (tau^2 / e^4 - 2 tau / e^3) for small e. With the
// layer's texel at most the Milky Way map's 0.18 deg: at 8 deg, 0.25 % for tau = 1 (the blue's
// vertical optical depth in haze of 10 km visibility) and 0.002 % for a clear sky's 0.3; at 1 deg
// the interpolated transmittance would be off by a factor of several.
inline constexpr double kNightLayerBandDeg = 8.0;

// The layer is a grid of views through the channel's pixel corners every cellPx pixels, one
// texel a vertex (render/glsl/pixel_grid.glsl, render/passes/common/night_layer.glsl), like the glare
// veil's grid (render/passes/tone/tone_pass.h): read bilinearly at each pixel, up to the channel's edges.
struct NightLayer {
  GLuint texture = 0;               // the sky's part above the atmosphere, a few pixels a texel; 0: none
  GLuint transmitted = 0;           // the same dimmed by the transmittance at each texel (0: none)
  GLuint extinction = 0;            // the transmittance to space (ExtinctionTexture), applied per pixel
  glm::dvec3 groundRadiance{0.0};  // the terrain's, below the horizon (cd/m^2, linear Rec.709)
  int cellPx = 0;                   // the grid's cell, pixels
  bool veil = false;                // alpha holds the veil per lux of the tone block's glare source 0
};

// The define with which a shader reads the layer: its cell (render/passes/common/night_layer.glsl).
inline std::string nightLayerCellDefine(int cellPx) {
  return "#define SKYIG_NIGHT_LAYER_CELL_PX " + std::to_string(cellPx) + ".0\n";
}
inline std::string nightLayerCellDefine(const NightLayer& layer) { return nightLayerCellDefine(layer.cellPx); }

}  // namespace skyig::render
