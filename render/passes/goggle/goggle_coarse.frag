// The photocathode's mean over blocks of goggleCathode.w pixels a side, a power of two up to 8
// (render/passes/goggle/goggle_pass.h): bilinear reads, each at the corner shared by 2 x 2 pixels, so
// each averages four (one texel read for 1 x 1 blocks). The halo and the automatic brightness
// control read these means and their mip chain.
#include "render/glsl/goggle_uniforms.h"

layout(binding = SKYIG_UNIT_GOGGLE_CATHODE) uniform sampler2D cathodeImage;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outMean;

void main() {
  int block = int(goggleCathode.w);
  if (block == 1) {
    outMean = vec4(texelFetch(cathodeImage, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0);
    return;
  }
  vec2 origin = floor(gl_FragCoord.xy) * float(block);
  vec2 texel = 1.0 / vec2(textureSize(cathodeImage, 0));
  int reads = block / 2;
  float sum = 0.0;
  for (int j = 0; j < reads; ++j)
    for (int i = 0; i < reads; ++i) sum += texture(cathodeImage, (origin + vec2(2 * i + 1, 2 * j + 1)) * texel).r;
  outMean = vec4(sum / float(reads * reads), 0.0, 0.0, 1.0);
}
