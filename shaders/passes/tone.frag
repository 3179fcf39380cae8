// Tone reproduction pass: HDR radiance in, display frame-buffer values out, with a triangular
// dither of +-1 LSB (common/dither.glsl) so the dark gradients of a night sky do not band in 8
// bits. For a projector the renderer sets the dither to 0 and draws into a float target: the
// warp-and-blend pass (passes/warp_blend.frag) dithers what it sends. The default mapping is the scene's
// histogram-adjusted curve (Ward Larson, Rushmeier & Piatko 1997), computed on the CPU from the
// model for every channel alike (sky/eye/tone_curve.h); Tumblin & Rushmeier 1993 is selectable.
// Stars and planets are not in the HDR image it maps: the displayed-star pass drew them, in
// display luminance, into pointSourceImage, added here before the display's encoding. The
// veiling glare of the sun and the moon (tone/glare.glsl) is added to the world's light first:
// it is the eye's, so it is shown but not written to the EXR.
// Variants (SkyRenderer compiles each): SKYIG_TONE_CURVE or SKYIG_TONE_TUMBLIN_RUSHMEIER, the
// display's operator (tone/display_curve.glsl); SKYIG_GLARE when a glare source gives light;
// SKYIG_PHOTOPIC when no part of the view is dim enough for rod vision. A uniform branch would
// cost llvmpipe both sides for every pixel.
#include "common/uniforms.h"
#include "tone/display_curve.glsl"
#include "tone/glare.glsl"
#include "common/dither.glsl"

layout(binding = SKYIG_UNIT_HDR_IMAGE) uniform sampler2D hdrImage;
// The displayed stars and planets (passes/star_display.vert): display cd/m^2 to add.
layout(binding = SKYIG_UNIT_POINT_SOURCES) uniform sampler2D pointSourceImage;
in vec2 vTexCoord;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outDisplay;

// The veil of the glare sources along this pixel's view.
vec3 glareVeil(vec3 view) {
  vec3 veil = vec3(0.0);
  for (int i = 0; i < 2; ++i) {
    if (max(glareLux[i].r, max(glareLux[i].g, glareLux[i].b)) <= 0.0) continue;
    // atan of |cross| over dot: accurate at the small angles where acos of a float is not.
    vec3 d = glareDirection[i].xyz;
    float thetaDeg = degrees(atan(length(cross(view, d)), dot(view, d)));
    veil += glareLux[i].rgb * veilingLuminancePerLux(thetaDeg, glareDirection[i].w, glareObserver.x, glareObserver.y);
  }
  return veil;
}

void main() {
  vec3 world = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
#ifdef SKYIG_GLARE
  world += glareVeil(normalize(mat3(ndcToWorld) * vec3(gl_FragCoord.xy * viewport.zw * 2.0 - 1.0, 1.0)));
#endif
  DisplayModel model = toneDisplayModel();
  vec3 ld = toneMapLinear(world) + texelFetch(pointSourceImage, ivec2(gl_FragCoord.xy), 0).rgb;
  vec3 n = displayValues(compressToDisplay(ld, rec709Luminance(ld), model.ambientLuminance + model.maxLuminance), model);
  outDisplay = vec4(clamp(n + ditherLsb(gl_FragCoord.xy, adaptation.y), 0.0, 1.0), 1.0);
}
