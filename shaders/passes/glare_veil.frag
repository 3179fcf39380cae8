// The glare veil (tone/glare_veil.glsl) at the vertices of the tone pass's grid, one texel per
// vertex: texel (i, j) is the view through the channel's pixel corner (i, j) x
// SKYIG_GLARE_CELL_PX (render/passes/tone_pass.h). The tone pass reads it bilinearly away from
// the sources (passes/tone.frag, SKYIG_GLARE_FROM_GRID).
#include "common/uniforms.h"
#include "tone/glare_veil.glsl"

layout(location = SKYIG_OUTPUT_COLOR) out vec4 outVeil;

void main() {
  vec2 px = (gl_FragCoord.xy - 0.5) * SKYIG_GLARE_CELL_PX;
  outVeil = vec4(glareVeil(mat3(ndcToWorld) * vec3(px * viewport.zw * 2.0 - 1.0, 1.0)), 0.0);
}
