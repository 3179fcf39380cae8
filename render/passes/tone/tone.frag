// Tone reproduction pass: HDR radiance in, display frame-buffer values out, with a triangular
// dither of +-1 LSB (render/glsl/dither.glsl) so the dark gradients of a night sky do not band in 8
// bits. For a projector the renderer sets the dither to 0 and draws into a float target: the
// warp-and-blend pass (render/passes/projector/warp_blend.frag) dithers what it sends. The default mapping is the scene's
// histogram-adjusted curve (Ward Larson, Rushmeier & Piatko 1997), computed on the CPU from the
// model for every channel alike (physics/eye/tone_curve.h); Tumblin & Rushmeier 1993 is selectable.
// Stars and planets are not in the HDR image it maps: the displayed-star pass drew them, in
// display luminance, into pointSourceImage, added here before the display's encoding. The
// veiling glare of the sun and the moon (physics/eye/glare.glsl) is added to the world's light first:
// it is the eye's, so it is shown but not written to the EXR.
// Variants (SkyRenderer compiles each): SKYIG_TONE_CURVE or SKYIG_TONE_TUMBLIN_RUSHMEIER, the
// display's operator (render/glsl/display_curve.glsl); SKYIG_GLARE N, the number of glare sources
// that give light (1 or 2), the veil per pixel, or with SKYIG_GLARE_FROM_GRID too, read
// bilinearly from its values at a grid's vertices (render/passes/tone/glare_veil.frag, render/passes/tone/tone_pass.h),
// or with SKYIG_GLARE_FROM_NIGHT_LAYER (one source) from the night's layer, which holds it;
// SKYIG_PHOTOPIC when no part of the view is dim enough for rod vision. A uniform branch would
// cost llvmpipe both sides for every pixel.
#include "render/glsl/uniforms.h"
#include "render/passes/tone/tone_display.glsl"
#ifdef SKYIG_GLARE_FROM_NIGHT_LAYER
#include "render/passes/common/night_layer.glsl"
float nightLayerVeilPerLux(vec2 fragCoord) { return nightLayerAt(fragCoord).a; }
#endif

layout(binding = SKYIG_UNIT_HDR_IMAGE) uniform sampler2D hdrImage;
// The displayed stars and planets (render/passes/night/star_display.vert): display cd/m^2 to add.
layout(binding = SKYIG_UNIT_POINT_SOURCES) uniform sampler2D pointSourceImage;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outDisplay;

// Any geometry: the whole channel (render/glsl/fullscreen.vert), or, where the sky pass mapped its
// own pixels, only where a later pass drew (the displayed stars' quads, render/passes/night/star_display.vert,
// and rectangles): it reads nothing but the fragment's position.
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  outDisplay = toneDisplayValue(texelFetch(hdrImage, pixel, 0).rgb, texelFetch(pointSourceImage, pixel, 0).rgb,
                                gl_FragCoord.xy);
}
