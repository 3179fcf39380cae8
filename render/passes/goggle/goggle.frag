// The goggle's screen (render/passes/goggle/goggle_pass.h, physics/goggle/intensifier.glsl): the
// photocathode's image through the tube's modulation transfer plus its halo, counted in
// photoelectrons with their shot noise and the microchannel plate's excess noise, amplified by
// the gain the automatic brightness control set (render/passes/goggle/goggle_abc.frag), and shown in the
// phosphor's colour on the channel's display as the goggle's screen looks to the eye (display
// luminance = the screen's, over the display's ambient). Outside the tube's circle: the
// housing, black. The noise is a hash of the pixel and the frame's seed, so a frame drawn again
// (a replay) is the same to the bit.
#include "render/glsl/uniforms.h"
#include "render/glsl/goggle_uniforms.h"
#include "physics/goggle/intensifier.glsl"
#include "render/glsl/display_curve.glsl"
#include "render/glsl/dither.glsl"

layout(binding = SKYIG_UNIT_GOGGLE_CATHODE) uniform sampler2D cathodeImage;  // lux
layout(binding = SKYIG_UNIT_GOGGLE_HALO) uniform sampler2D haloLogImage;     // ln lux, the halo (render/passes/goggle/goggle_halo.frag)
layout(binding = SKYIG_UNIT_GOGGLE_GAIN) uniform sampler2D gainImage;        // cd/m^2 per lux (render/passes/goggle/goggle_abc.frag)
uniform uint uSeed;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outDisplay;

// PCG's output permutation of a 32-bit state (O'Neill 2014, pcg32 "RXS M XS"): a well-mixed
// hash for a counter-based generator.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float uniform01(inout uint state) {
  state = pcgHash(state);
  return (float(state >> 8) + 0.5) / 16777216.0;
}
// The screen's light from a pixel of `mean` expected photoelectrons, in units of one
// electron's mean gain: a Poisson count k of electrons, each multiplied by the plate with an
// exponential gain (physics/goggle/intensifier.glsl: F = 2), so the sum is a Gamma(k) variate, minus
// the log of a product of k uniforms; mean `mean`, variance F mean. Below 30 electrons (a dark
// pixel, where the discreteness is the scintillation one sees) exactly so, with Knuth's product
// of uniforms for the count; above, the normal approximation of the same mean and variance
// (Box-Muller).
float amplifiedElectrons(float mean, inout uint state) {
  if (mean < 30.0) {
    float limit = exp(-mean);
    float product = uniform01(state);
    int k = 0;
    for (int i = 0; i < 80 && product > limit; ++i) {
      product *= uniform01(state);
      ++k;
    }
    float gains = 1.0;
    for (int i = 0; i < k; ++i) gains *= uniform01(state);
    return k > 0 ? -log(gains) : 0.0;
  }
  float u1 = uniform01(state), u2 = uniform01(state);
  return max(mean + sqrt(kExcessNoiseFactor * mean) * sqrt(-2.0 * log(u1)) * cos(6.28318530717959 * u2), 0.0);
}

float cathodeAt(ivec2 p) {
  return texelFetch(cathodeImage, clamp(p, ivec2(0), textureSize(cathodeImage, 0) - 1), 0).r;
}

void main() {
  vec2 d = gl_FragCoord.xy - goggleTube.xy;
  if (dot(d, d) > goggleTube.z * goggleTube.z) {
    outDisplay = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  ivec2 p = ivec2(gl_FragCoord.xy);
  float sharp = goggleMtf.x * cathodeAt(p) +
                goggleMtf.y * (cathodeAt(p + ivec2(1, 0)) + cathodeAt(p - ivec2(1, 0)) + cathodeAt(p + ivec2(0, 1)) + cathodeAt(p - ivec2(0, 1))) +
                goggleMtf.z * (cathodeAt(p + ivec2(1, 1)) + cathodeAt(p - ivec2(1, 1)) + cathodeAt(p + ivec2(1, -1)) + cathodeAt(p + ivec2(-1, 1)));
  float halo = exp(texture(haloLogImage, gl_FragCoord.xy / (goggleCathode.w * vec2(textureSize(haloLogImage, 0)))).r);
  float lux = (1.0 - kHaloFraction) * sharp + kHaloFraction * halo;
  float g = texelFetch(gainImage, ivec2(0), 0).r;
  float electrons = lux * goggleCathode.y;
  uint state = pcgHash(uint(p.x) + pcgHash(uint(p.y) + pcgHash(uSeed)));
  float seen = electrons > 0.0 ? lux * amplifiedElectrons(electrons, state) / electrons : 0.0;
  float screen = min(g * seen, kScreenSaturationCdM2);
  vec3 rgb = gogglePhosphor.rgb * screen;
  if (goggleGain.z > 0.5) {
    outDisplay = vec4(rgb, 1.0);
    return;
  }
  DisplayModel model = toneDisplayModel();
  vec3 ld = rgb + vec3(model.ambientLuminance);
  float white = model.ambientLuminance + model.maxLuminance;
  vec3 n = displayValues(compressToDisplay(ld, rec709Luminance(ld), white), model);
  outDisplay = vec4(clamp(n + ditherLsb(gl_FragCoord.xy, adaptation.y), 0.0, 1.0), 1.0);
}
