// Star and planet passes: the PSF weight of this pixel times the source's radiance per weight,
// added (blending ONE, ONE) to the sky's absolute radiance in cd/m^2 (render/passes/night/star.vert) or to
// the displayed stars in display cd/m^2 (render/passes/night/star_display.vert).
#include "render/glsl/bindings.h"
#include "physics/stars/star_psf.glsl"

flat in vec2 vCentrePx;
flat in vec3 vRadiancePerWeight;
flat in float vSigmaPx;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;

void main() {
  outRadiance = vec4(vRadiancePerWeight * starPsfPixelWeight(gl_FragCoord.xy - vCentrePx, vSigmaPx), 0.0);
}
