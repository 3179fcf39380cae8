// Sky pass of the analytic models (CIE general sky, Preetham): absolute linear Rec.709
// radiance in cd/m^2 into a float target.
#include "render/glsl/uniforms.h"
#include "physics/analytic/analytic_sky.glsl"
#include "render/glsl/band.glsl"

in vec3 vViewRay;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;

void main() {
  AnalyticSky sky = AnalyticSky(perezA.xyz, perezB.xyz, perezC.xyz, perezD.xyz, perezE.xyz,
                                perezK.xyz, zenith.xyz, skySunDirection.xyz, skySunDirection.w,
                                sunDirection.xyz, sunDirection.w, sunRadiance.rgb,
                                groundRadiance.rgb);
  outRadiance = vec4(inBand(analyticSkyRadiance(sky, normalize(vViewRay)), lightWeights.x), 1.0);
}
