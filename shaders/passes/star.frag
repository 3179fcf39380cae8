// Star and planet passes: the PSF weight of this pixel times the source's radiance per weight,
// added (blending ONE, ONE) to the sky's absolute radiance in cd/m^2 (passes/star.vert) or to
// the displayed stars in display cd/m^2 (passes/star_display.vert).
#include "common/bindings.h"
#include "night/star_psf.glsl"

flat in vec2 vCentrePx;
flat in vec3 vRadiancePerWeight;
flat in float vSigmaPx;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;

void main() {
  outRadiance = vec4(vRadiancePerWeight * starPsfWeight(gl_FragCoord.xy - vCentrePx, vSigmaPx), 0.0);
}
