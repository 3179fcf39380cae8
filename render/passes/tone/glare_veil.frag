// The glare veil (render/passes/tone/glare_veil.glsl) at the vertices of the tone pass's grid, one texel per
// vertex: texel (i, j) is the view through the channel's pixel corner (i, j) x
// SKYIG_GLARE_CELL_PX (render/glsl/pixel_grid.glsl, render/passes/tone/tone_pass.h). The tone pass reads
// it bilinearly away from the sources (render/passes/tone/tone.frag, SKYIG_GLARE_FROM_GRID).
#include "render/glsl/uniforms.h"
#include "render/glsl/pixel_grid.glsl"
#include "render/passes/tone/glare_veil.glsl"

layout(location = SKYIG_OUTPUT_COLOR) out vec4 outVeil;

void main() { outVeil = vec4(glareVeil(pixelGridView(gl_FragCoord.xy, SKYIG_GLARE_CELL_PX)), 0.0); }
