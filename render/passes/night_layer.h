#pragma once
// The night's own light as the physical sky pass adds it (passes/physical_sky.frag,
// SKYIG_NIGHT_LAYER): drawn by NightDiffusePass::drawLayer, read by PhysicalSkyPass::draw.
#include <glad/gl.h>
#include <glm/vec3.hpp>

namespace skyig::render {

struct NightLayer {
  GLuint texture = 0;               // the sky's part above the atmosphere, a few pixels a texel; 0: none
  GLuint extinction = 0;            // the transmittance to space (ExtinctionTexture), applied per pixel
  glm::dvec3 groundRadiance{0.0};  // the terrain's, below the horizon (cd/m^2, linear Rec.709)
};

}  // namespace skyig::render
