// The goggle's photocathode (render/passes/goggle/goggle_pass.h): the channel's NVIS radiance, which
// the passes wrote into all three channels (render/glsl/band.glsl), as illuminance on the
// photocathode inside the tube's circular field; none outside it.
#include "render/glsl/uniforms.h"
#include "render/glsl/goggle_uniforms.h"

layout(binding = SKYIG_UNIT_GOGGLE_NVIS) uniform sampler2D nvisImage;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outCathode;

void main() {
  vec2 d = gl_FragCoord.xy - goggleTube.xy;
  float nvis = max(texelFetch(nvisImage, ivec2(gl_FragCoord.xy), 0).g, 0.0);
  outCathode = vec4(dot(d, d) <= goggleTube.z * goggleTube.z ? nvis * goggleCathode.x : 0.0, 0.0, 0.0, 1.0);
}
