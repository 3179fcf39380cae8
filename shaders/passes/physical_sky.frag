// Sky pass of the physical atmosphere (Bruneton & Neyret 2008, section 5 without light
// shafts) from the tables folded into linear Rec.709 (atmosphere/rendering_rec709.glsl): the
// sky scattered into the view ray, the limb-darkened sun disc and, where the ray meets the
// ground, the Lambertian ground attenuated by the air in between; one lookup set per pixel
// whatever the number of wavelengths. A second light (the moon: Jensen et al. 2001, the same
// tables lit from its direction times its irradiance relative to the sun's) adds its sky and
// ground when moonlightOn, a uniform branch.
// (No common/uniforms.h here: its analytic-sky block's member names would clash with the
// atmosphere's functions; the vertex stage alone reads the frame block.)
#include "atmosphere/rendering_rec709.glsl"

uniform AtmosphereParameters atm;
uniform vec3 camera;         // metres from the planet's centre, local frame: x east, y north, z up
uniform vec3 sunDirectionP;  // unit, same frame
uniform vec3 solarIrradianceXyz;
uniform vec3 limbDarkeningXyz;
uniform float groundAlbedo;
uniform bool moonlightOn;
uniform vec3 moonDirectionP;  // unit, same frame
uniform vec3 moonlightScale;  // Rec.709, the moon's irradiance relative to the sun's
layout(binding = 0) uniform sampler2D transmittanceXyz;
layout(binding = 1) uniform sampler3D scatteringPacked;
layout(binding = 2) uniform sampler3D singleMieRG;
layout(binding = 3) uniform sampler2D irradianceXyz;

in vec3 vViewRay;
layout(location = 0) out vec4 outRadiance;

void main() {
  vec3 view = normalize(vViewRay);
  vec3 rgb = packedViewRec709(atm, transmittanceXyz, scatteringPacked, singleMieRG, irradianceXyz,
                              solarIrradianceXyz, limbDarkeningXyz, groundAlbedo, camera, view,
                              sunDirectionP, true);
  if (moonlightOn) {
    rgb += moonlightScale * packedViewRec709(atm, transmittanceXyz, scatteringPacked, singleMieRG,
                                             irradianceXyz, solarIrradianceXyz, limbDarkeningXyz,
                                             groundAlbedo, camera, view, moonDirectionP, false);
  }
  outRadiance = vec4(max(rgb, vec3(0.0)), 1.0);
}
