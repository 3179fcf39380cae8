// The automatic brightness control (physics/goggle/intensifier.glsl): one fragment, the gain that puts
// the screen's mean at the control's level. The control senses the screen's current, and a
// bright source's pixels saturate (kScreenSaturationCdM2): the full moon in the field does not
// darken the whole scene by its radiance alone. So the gain g solves
//   mean over the field of min(g E, saturation) = kAbcScreenCdM2,
// found by bisection in log g on the block means' mip level `uLevel` (a few hundred texels;
// a bright source inside one of them is diluted there, which only lets it weigh less).
#include "render/glsl/uniforms.h"
#include "render/glsl/goggle_uniforms.h"
#include "physics/goggle/intensifier.glsl"

layout(binding = SKYIG_UNIT_GOGGLE_COARSE) uniform sampler2D coarseImage;
uniform int uLevel;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outGain;

float screenMean(float g) {
  ivec2 size = textureSize(coarseImage, uLevel);
  float sum = 0.0;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) sum += min(g * texelFetch(coarseImage, ivec2(x, y), uLevel).r, kScreenSaturationCdM2);
  return sum / (float(size.x * size.y) * goggleTube.w);
}

void main() {
  if (goggleGain.x < 0.5) {  // manual
    outGain = vec4(manualGain(goggleGain.y), 0.0, 0.0, 1.0);
    return;
  }
  float hi = kMaxLuminanceGain;
  if (screenMean(hi) <= kAbcScreenCdM2) {  // below the control's range: full gain
    outGain = vec4(hi, 0.0, 0.0, 1.0);
    return;
  }
  float lo = hi * 1e-9;
  for (int i = 0; i < 20; ++i) {  // 2^-20 of the 1e9 range: the gain to 2e-5
    float mid = sqrt(lo * hi);
    if (screenMean(mid) > kAbcScreenCdM2) hi = mid;
    else lo = mid;
  }
  outGain = vec4(sqrt(lo * hi), 0.0, 0.0, 1.0);
}
