// The photocathode's mean over blocks of 8 x 8 pixels (render/passes/goggle_pass.h): 16
// bilinear reads, each at the corner shared by 2 x 2 pixels, so each averages four. The
// pass's mip chain then reaches the whole field's mean (the automatic brightness control's)
// and the halo pass reads it.
#include "common/bindings.h"

layout(binding = SKYIG_UNIT_GOGGLE_CATHODE) uniform sampler2D cathodeImage;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outMean;

void main() {
  vec2 origin = floor(gl_FragCoord.xy) * 8.0;
  vec2 texel = 1.0 / vec2(textureSize(cathodeImage, 0));
  float sum = 0.0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) sum += texture(cathodeImage, (origin + vec2(2 * i + 1, 2 * j + 1)) * texel).r;
  outMean = vec4(sum / 16.0, 0.0, 0.0, 1.0);
}
