// Tone reproduction pass: HDR radiance in, display frame-buffer values out, with a triangular
// dither of +-1 LSB so the dark gradients of a night sky do not band in 8 bits. The dither is
// a hash of the pixel, so frames are deterministic.
#include "common/uniforms.h"
#include "tone/tone_reproduction.glsl"

layout(binding = SKYIG_UNIT_HDR_IMAGE) uniform sampler2D hdrImage;
in vec2 vTexCoord;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outDisplay;

float hash12(vec2 p) {  // Hoskins, "Hash without sine" (2014), hash12
  vec3 p3 = fract(vec3(p.xyx) * 0.1031);
  p3 += dot(p3, p3.yzx + 33.33);
  return fract((p3.x + p3.y) * p3.z);
}

void main() {
  vec3 world = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
  DisplayModel model = DisplayModel(display.x, display.y, display.z, display.w);
  vec3 n = toneReproduce(world, adaptation.x, model);
  float dither = (hash12(gl_FragCoord.xy) + hash12(gl_FragCoord.xy + 71.7) - 1.0) * adaptation.y;
  outDisplay = vec4(clamp(n + dither / 255.0, 0.0, 1.0), 1.0);
}
