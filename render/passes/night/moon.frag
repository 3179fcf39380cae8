// The moon's disc, added to the HDR target (cd/m^2): each fragment's view ray is un-refracted,
// met with the sphere, lit by the sun (Lommel-Seeliger) and the earth, textured with the albedo
// map and attenuated by the extinction at its elevation (physics/moon/moon.glsl).
#include "render/glsl/uniforms.h"
#include "physics/moon/moon.glsl"
#include "render/glsl/band.glsl"

uniform vec3 moonCentre;        // ENU unit vector, airless
uniform float moonSinRadius;
uniform vec3 towardSun;         // from the moon to the sun
uniform vec3 moonNorth;         // selenographic axes, ENU
uniform vec3 moonEast;
uniform vec3 sunlitScale;       // cd/m^2 (physics/moon/moon_disc.h)
uniform vec3 earthshineScale;
uniform vec4 refraction;        // apparent centre altitude, R, dR/dh, d2R/dh2 / 2 (radians)
layout(binding = SKYIG_UNIT_MOON_ALBEDO) uniform sampler2D moonAlbedo;  // relative albedo, mean 1 on the near side
layout(binding = SKYIG_UNIT_MOON_EXTINCTION) uniform sampler1D extinctionTable;  // ExtinctionProfile::rec709Table

layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;

void main() {
  vec2 ndc = gl_FragCoord.xy * viewport.zw * 2.0 - 1.0;
  vec3 seen = normalize(mat3(ndcToWorld) * vec3(ndc, 1.0));
  // The pixel's angular size, for the limb's coverage ramp.
  Float pixel = sqrt(length(dFdx(seen)) * length(dFdy(seen)));
  vec3 view = unrefractView(seen, refraction);
  vec3 q = moonDiscOffset(view, moonCentre, moonSinRadius);
  Float inside = (1.0 - length(q)) * moonSinRadius;
  Float coverage = moonLimbCoverage(inside, pixel);
  if (coverage <= 0.0 || dot(view, moonCentre) <= 0.0) discard;
  vec3 n = moonSurfaceNormal(q, moonCentre);
  vec2 uv = selenographicUv(n, -moonCentre, moonNorth, moonEast);
  // Mip-mapped: the disc is tens of pixels across, the map 1024 texels around. The longitude
  // wraps only on the far side, so the derivatives are smooth wherever the disc is seen.
  Float albedo = texture(moonAlbedo, uv).r;
  vec3 radiance = moonSurfaceRadiance(n, -moonCentre, towardSun, albedo, sunlitScale, earthshineScale);
  vec3 transmittance = texture(extinctionTable, extinctionCoordinate(asin(clamp(view.z, -1.0, 1.0)))).rgb;
  outRadiance = vec4(inBand(radiance * transmittance * coverage, lightWeights.y), 0.0);
}
