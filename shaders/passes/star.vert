// Star and planet pass: one point per source, sized to hold its point-spread function. The
// source's illuminance becomes a radiance per unit PSF weight by dividing by the solid angle
// of a pixel where it lands (shaders/night/star_psf.glsl).
#include "common/uniforms.h"
#include "night/star_psf.glsl"

layout(location = 0) in vec3 aDirection;  // apparent ENU unit vector
layout(location = 1) in vec3 aRec709Lux;  // illuminance per channel at the eye

uniform mat3 uWorldToNdc;  // the inverse of ndcToWorld

flat out vec2 vCentrePx;
flat out vec3 vRadiancePerWeight;

void main() {
  vec3 p = uWorldToNdc * aDirection;
  gl_PointSize = 2.0 * ceil(kStarPsfRadiusSigmas * kStarPsfSigmaPx) + 1.0;
  vCentrePx = vec2(0.0);
  vRadiancePerWeight = vec3(0.0);
  if (p.z <= 0.0) {  // behind the eye: outside the clip volume, discarded
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  vec2 ndc = p.xy / p.z;
  vCentrePx = (ndc * 0.5 + 0.5) * viewport.xy;
  vRadiancePerWeight = aRec709Lux / pixelSolidAngle(mat3(ndcToWorld), ndc, 4.0 * viewport.z * viewport.w);
  gl_Position = vec4(ndc, 0.0, 1.0);
}
