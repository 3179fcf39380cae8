// Sky pass of the analytic models (CIE general sky, Preetham): absolute linear Rec.709
// radiance in cd/m^2 into a float target. The horizon and the sun's limb are shared by the
// pixels they cross (render/glsl/edge_coverage.glsl): analyticSkyRadiance's two edges, each
// pixel the mix of its sides by their areas (analyticSkyRadianceShared), so neither steps.
#include "render/glsl/uniforms.h"
#include "physics/analytic/analytic_sky.glsl"
#include "render/glsl/band.glsl"
#include "render/glsl/edge_coverage.glsl"

in vec3 vViewRay;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;

void main() {
  AnalyticSky sky = AnalyticSky(perezA.xyz, perezB.xyz, perezC.xyz, perezD.xyz, perezE.xyz,
                                perezK.xyz, zenith.xyz, skySunDirection.xyz, skySunDirection.w,
                                sunDirection.xyz, sunDirection.w, sunRadiance.rgb,
                                groundRadiance.rgb);
  vec3 view = normalize(vViewRay);
  float skyShare = pixelShareAbove(view.z);
  float discShare = pixelShareAbove(dot(view, sky.sunDirection) - sky.cosSunRadius);
  outRadiance = vec4(inBand(analyticSkyRadianceShared(sky, view, skyShare, discShare), lightWeights.x), 1.0);
}
