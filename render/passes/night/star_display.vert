// Displayed-star pass: stars and planets as the eye sees them, drawn in display luminance
// (cd/m^2 on the screen) into the point-source target that the tone pass adds to the mapped
// sky (docs/night-sky-stars.md, "On the display"). Per star, here: its visibility against the
// sky it sits on (the HDR image at its pixel, which holds no stars), the same visibility on the
// display against the mapped sky there, a just-visible star at the display's threshold
// (physics/eye/point_source_visibility.glsl), and a PSF of a fixed angle integrated over each
// pixel, so that sum(display luminance x pixel solid angle) is the displayed illuminance at any
// resolution. The quad is star.vert's; star.frag draws the PSF.
#include "render/glsl/uniforms.h"
#include "physics/stars/star_psf.glsl"
#include "physics/eye/point_source_visibility.glsl"
#include "render/glsl/display_curve.glsl"

layout(location = SKYIG_ATTRIB_STAR_DIRECTION) in vec3 aDirection;  // per instance: apparent ENU unit vector
layout(location = SKYIG_ATTRIB_STAR_REC709_LUX) in vec3 aRec709Lux;  // per instance: illuminance per channel at the eye
layout(binding = SKYIG_UNIT_STAR_BACKGROUND) uniform sampler2D hdrImage;  // the sky without stars, cd/m^2

uniform mat3 uWorldToNdc;  // the inverse of ndcToWorld

flat out vec2 vCentrePx;
flat out vec3 vRadiancePerWeight;
flat out float vSigmaPx;

void main() {
  vec3 p = uWorldToNdc * aDirection;
  vCentrePx = vec2(0.0);
  vRadiancePerWeight = vec3(0.0);
  vSigmaPx = 1.0;
  gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // nothing to draw: a degenerate quad outside the clip volume
  if (p.z <= 0.0) return;                  // behind the eye
  vec2 ndc = p.xy / p.z;
  vCentrePx = (ndc * 0.5 + 0.5) * viewport.xy;
  ivec2 pixel = clamp(ivec2(vCentrePx), ivec2(0), ivec2(viewport.xy) - 1);
  vec3 background = texelFetch(hdrImage, pixel, 0).rgb;
  float white = display.y + display.x;
  float displayBackground = min(rec709Luminance(toneMapLinear(background)), white);
  float worldBackground = rec709Luminance(max(background, vec3(0.0)));
  float pixelSr = pixelSolidAngle(mat3(ndcToWorld), ndc, 4.0 * viewport.z * viewport.w);
  vSigmaPx = max(kDisplayedPsfSigmaRad / sqrt(pixelSr), kDisplayedPsfMinSigmaPx);
  // The display's threshold here: the viewer's own, or a brightest pixel a few codes over the
  // displayed sky, whichever is larger (physics/eye/point_source_visibility.glsl).
  float peakSr = starPsfPeakSolidAngle(pixelSr, vSigmaPx);
  float threshold = displayedThresholdLux(displayBackground, displayThresholdStep(displayBackground, display.y, display.x, display.z), peakSr);
  float exponent = displayedVisibilityExponent(maxDisplayVisibility(displayBackground, white, threshold, peakSr));
  float lux = displayedIlluminance(rec709Luminance(aRec709Lux), worldBackground, threshold, exponent);
  if (!(lux > 0.0)) return;  // below the eye's threshold: not shown
  vRadiancePerWeight = displayedPointSourceRec709(aRec709Lux, worldBackground, lux) / pixelSr;
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  float halfSizePx = starPsfQuadHalfSizePx(vSigmaPx);
  gl_Position = vec4(ndc + corner * halfSizePx * 2.0 * viewport.zw, 0.0, 1.0);
}
