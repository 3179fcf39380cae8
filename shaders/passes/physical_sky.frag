// Sky pass of the physical atmosphere (Bruneton & Neyret 2008, section 5 without light
// shafts): for each group of four wavelengths, the sky scattered into the view ray, the limb-
// darkened sun disc and, where the ray meets the ground, the Lambertian ground attenuated by
// the air in between; each group's spectral radiance goes to linear Rec.709 (cd/m^2) through
// the CIE 1931 weights of its wavelengths (groupToRec709, columns = wavelengths).
// (No common/uniforms.h here: its analytic-sky block's member names would clash with the
// atmosphere's functions; the vertex stage alone reads the frame block.)
#include "atmosphere/rendering.glsl"

#define MAX_GROUPS 4
uniform AtmosphereParameters atm[MAX_GROUPS];
uniform int groupCount;
uniform mat4 groupToRec709[MAX_GROUPS];
uniform vec3 camera;         // metres from the planet's centre, local frame: x east, y north, z up
uniform vec3 sunDirectionP;  // unit, same frame
layout(binding = 0) uniform sampler2D transmittanceTextures[MAX_GROUPS];
layout(binding = 4) uniform sampler3D scatteringTextures[MAX_GROUPS];
layout(binding = 8) uniform sampler3D singleMieTextures[MAX_GROUPS];
layout(binding = 12) uniform sampler2D irradianceTextures[MAX_GROUPS];

in vec3 vViewRay;
layout(location = 0) out vec4 outRadiance;

vec4 groupRadiance(IN(AtmosphereParameters) a, IN(sampler2D) t, IN(sampler3D) s, IN(sampler3D) m,
                   IN(sampler2D) e, IN(vec3) view) {
  vec4 transmittance;
  vec4 radiance = skyRadiance(a, t, s, m, camera, view, sunDirectionP, transmittance);
  radiance += sunDiscRadiance(a, t, camera, view, sunDirectionP);
  Float r = length(camera);
  Float rmu = dot(camera, view);
  Float discriminant = rmu * rmu - r * r + a.bottom_radius * a.bottom_radius;
  if (rmu < 0.0 && discriminant >= 0.0) {
    vec3 groundPoint = camera + view * (-rmu - sqrt(discriminant));
    vec4 skyIrradiance;
    vec4 sunIrradiance = sunAndSkyIrradiance(a, t, e, groundPoint, normalize(groundPoint), sunDirectionP,
                                             skyIrradiance);
    vec4 groundTransmittance;
    skyRadianceToPoint(a, t, s, m, camera, groundPoint, sunDirectionP, groundTransmittance);
    radiance += a.ground_albedo * (1.0 / ATMOSPHERE_PI) * (sunIrradiance + skyIrradiance) * groundTransmittance;
  }
  return radiance;
}

void main() {
  vec3 view = normalize(vViewRay);
  vec3 rgb = vec3(0.0);
  // Sampler arrays are indexed by constants, so each group is spelled out.
  rgb += (groupToRec709[0] * groupRadiance(atm[0], transmittanceTextures[0], scatteringTextures[0],
                                           singleMieTextures[0], irradianceTextures[0], view)).rgb;
  if (groupCount > 1)
    rgb += (groupToRec709[1] * groupRadiance(atm[1], transmittanceTextures[1], scatteringTextures[1],
                                             singleMieTextures[1], irradianceTextures[1], view)).rgb;
  if (groupCount > 2)
    rgb += (groupToRec709[2] * groupRadiance(atm[2], transmittanceTextures[2], scatteringTextures[2],
                                             singleMieTextures[2], irradianceTextures[2], view)).rgb;
  if (groupCount > 3)
    rgb += (groupToRec709[3] * groupRadiance(atm[3], transmittanceTextures[3], scatteringTextures[3],
                                             singleMieTextures[3], irradianceTextures[3], view)).rgb;
  outRadiance = vec4(max(rgb, vec3(0.0)), 1.0);
}
