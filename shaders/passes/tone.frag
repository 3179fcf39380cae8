// Tone reproduction pass: HDR radiance in, display frame-buffer values out, with a triangular
// dither of +-1 LSB so the dark gradients of a night sky do not band in 8 bits. The dither is
// a hash of the pixel, so frames are deterministic. The default mapping is the scene's
// histogram-adjusted curve (Ward Larson, Rushmeier & Piatko 1997), computed on the CPU from the
// model for every channel alike (sky/eye/tone_curve.h); Tumblin & Rushmeier 1993 is selectable.
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

float curvePoint(int i) { return curve[i >> 2][i & 3]; }

// The curve's display log10 luminance at a world luminance: linear between its 64 points,
// held at its ends (ToneCurve::displayLuminance on the CPU).
float curveAt(float worldLuminance) {
  float b = log(max(worldLuminance, 1e-30)) * 0.4342944819;
  float x = clamp((b - curveRange.x) / (curveRange.y - curveRange.x) * 63.0, 0.0, 63.0);
  int i = min(int(x), 62);
  return mix(curvePoint(i), curvePoint(i + 1), x - float(i));
}

void main() {
  vec3 world = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
  DisplayModel model = DisplayModel(display.x, display.y, display.z, display.w);
  vec3 n;
  if (adaptation.z > 0.5) {
    n = toneReproduce(world, adaptation.x, model);
  } else {
    vec3 xyY = mesopicxyY(rec709ToXyz(max(world, vec3(0.0))));
    n = displayValues(toneReproduceLinearWithCurve(xyY, curveAt(xyY.z), model), model);
  }
  float dither = (hash12(gl_FragCoord.xy) + hash12(gl_FragCoord.xy + 71.7) - 1.0) * adaptation.y;
  outDisplay = vec4(clamp(n + dither / 255.0, 0.0, 1.0), 1.0);
}
