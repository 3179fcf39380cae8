// Star and planet pass: one instanced quad per source, sized to hold its point-spread function
// (a quad, not a GL point: points are discarded whole when their centre leaves the screen, so
// a star at the edge would pop; a quad's triangles are clipped pixel by pixel). The source's
// illuminance becomes a radiance per unit PSF weight by dividing by the solid angle of a pixel
// where it lands (physics/stars/star_psf.glsl).
#include "render/glsl/uniforms.h"
#include "physics/stars/star_psf.glsl"

layout(location = SKYIG_ATTRIB_STAR_DIRECTION) in vec3 aDirection;  // per instance: apparent ENU unit vector
layout(location = SKYIG_ATTRIB_STAR_REC709_LUX) in vec3 aRec709Lux;  // per instance: illuminance per channel at the eye

uniform mat3 uWorldToNdc;  // the inverse of ndcToWorld

flat out vec2 vCentrePx;
flat out vec3 vRadiancePerWeight;
flat out float vSigmaPx;

void main() {
  vec3 p = uWorldToNdc * aDirection;
  vCentrePx = vec2(0.0);
  vRadiancePerWeight = vec3(0.0);
  vSigmaPx = kStarPsfSigmaPx;
  if (p.z <= 0.0) {  // behind the eye: a degenerate quad outside the clip volume
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  vec2 ndc = p.xy / p.z;
  vCentrePx = (ndc * 0.5 + 0.5) * viewport.xy;
  vRadiancePerWeight = aRec709Lux / pixelSolidAngle(mat3(ndcToWorld), ndc, 4.0 * viewport.z * viewport.w);
  // Corners of a triangle strip beyond the PSF's cut, so every pixel it reaches is covered.
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  float halfSizePx = starPsfQuadHalfSizePx(kStarPsfSigmaPx);
  gl_Position = vec4(ndc + corner * halfSizePx * 2.0 * viewport.zw, 0.0, 1.0);
}
