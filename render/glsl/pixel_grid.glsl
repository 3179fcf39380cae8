#ifndef SKYIG_COMMON_PIXEL_GRID_GLSL
#define SKYIG_COMMON_PIXEL_GRID_GLSL
// A grid of views through a channel's pixel corners, every cellPx pixels, held one texel a
// vertex in a small target and read bilinearly at each pixel: texel (i, j) is the view through
// the pixel corner (i, j) x cellPx, so a target of ceil(width / cellPx) + 1 by
// ceil(height / cellPx) + 1 texels covers the channel to its edges, with no texel clamped (a
// texel centre at its pixel would leave half a cell at each edge read from the edge texel).
// The glare veil's grid (render/passes/tone/glare_veil.frag, render/passes/tone/tone_pass.h) and the night's
// layer (render/passes/night/night_diffuse.frag, render/passes/common/night_layer.h) are such grids; GPU only.
#include "render/glsl/frame_uniforms.h"

// The view (unnormalised, ENU) of the texel a pass drawing the grid shades at `fragCoord`.
vec3 pixelGridView(vec2 fragCoord, float cellPx) {
  vec2 px = (fragCoord - 0.5) * cellPx;
  return mat3(ndcToWorld) * vec3(px * viewport.zw * 2.0 - 1.0, 1.0);
}

// The grid's value at the channel's pixel `fragCoord`, interpolated between its vertices.
vec4 pixelGridAt(sampler2D grid, vec2 fragCoord, float cellPx) {
  return texture(grid, (fragCoord / cellPx + 0.5) / vec2(textureSize(grid, 0)));
}

#endif
