// skyig's aerial perspective for a client's own shaders: the text skyig::SkyDraw::
// aerialPerspectiveGlsl() returns (docs/library.md), every name in it prefixed with skyig_ so it
// can be pasted into any program, and whose uniforms SkyDraw::bindAerialPerspective sets. The
// same figures as skyig::Sky::aerialPerspective (sky/client_light.cpp: clientAerialPerspective),
// from the tables the sky is drawn with: Bruneton & Neyret (2008) section 4, as Bruneton's 2017
// GetSkyRadianceToPoint (physics/atmosphere/aerial_perspective.glsl).
#include "physics/atmosphere/aerial_perspective.glsl"
#include "physics/weather/fog_layer.glsl"

// Wavelength groups of four (physics/atmosphere/model.h) the transmittance is summed over.
#define SKYIG_AERIAL_GROUPS 4

uniform AtmosphereParameters skyig_atm;
uniform sampler3D skyig_scattering;  // C*.rgb and C_M.b, Rec.709 (RGBA16F)
uniform sampler3D skyig_singleMie;   // C_M.rg (RG16F)
// The spectral transmittance tables, four wavelengths each (RGBA32F), and each wavelength's
// Rec.709 weight times the sun's spectral irradiance (zero for a group the model lacks).
uniform sampler2D skyig_transmittance[SKYIG_AERIAL_GROUPS];
uniform vec3 skyig_sunRec709[4 * SKYIG_AERIAL_GROUPS];
// The observer in metres from the planet's centre, on the east-north-up axes at the observer:
// (0, 0, bottom radius + height).
uniform vec3 skyig_camera;
uniform vec3 skyig_sunDirection;    // east-north-up unit vectors, airless
uniform vec3 skyig_moonDirection;
uniform vec3 skyig_moonlightScale;  // the moonlit sky's Rec.709 scale (0: none)
// The haze below the tables' visibility, the ground fog and the precipitation as the sky pass
// draws them (sky/fog_state.h), and the observer's height above the ground, metres.
uniform FogLayer skyig_fog[3];
uniform float skyig_cameraHeight;

// Between the observer and a point offsetEnuM metres from it (east, north, up): a surface of
// radiance L seen there is L * transmittance + the returned in-scattered radiance (linear
// Rec.709, cd/m^2), lit by the sun and the moon as Sky::aerialPerspective is. The
// transmittance is sunlight's per Rec.709 channel, as the CPU defines it: the Rec.709 of the
// sun's spectrum through the segment (every wavelength's own transmittance, Bruneton & Neyret
// 2008 section 4: T(x, x_p) = T(x, v) / T(x_p, v)) over the Rec.709 of the sun's spectrum. The fog
// layers on the segment then dim both and add their own light (physics/weather/fog_layer.glsl), as
// the CPU's does: a black target at the visibility keeps Koschmieder's 2% against the fog behind.
vec3 skyigAerialPerspective(vec3 offsetEnuM, out vec3 transmittance) {
  transmittance = vec3(1.0);
  vec3 camera;
  vec3 view_ray;
  Float r;
  Float mu;
  Float d;
  bool ground;
  if (!aerialSegment(skyig_atm, skyig_camera, offsetEnuM, camera, view_ray, r, mu, d, ground)) {
    return vec3(0.0);
  }
  vec3 before = vec3(0.0);
  vec3 after = vec3(0.0);
  for (int g = 0; g < SKYIG_AERIAL_GROUPS; ++g) {
    vec4 t = transmittanceAlongRay(skyig_atm, skyig_transmittance[g], r, mu, d, ground);
    for (int i = 0; i < 4; ++i) {
      before += skyig_sunRec709[4 * g + i];
      after += skyig_sunRec709[4 * g + i] * t[i];
    }
  }
  for (int c = 0; c < 3; ++c) {
    if (before[c] > 0.0) transmittance[c] = clamp(after[c] / before[c], 0.0, 1.0);
  }
  vec3 in_scattered = packedInScatteredRec709(skyig_atm, skyig_scattering, skyig_singleMie, camera,
                                              view_ray, r, mu, d, ground, skyig_sunDirection,
                                              transmittance);
  if (any(greaterThan(skyig_moonlightScale, vec3(0.0)))) {
    in_scattered += packedInScatteredRec709(skyig_atm, skyig_scattering, skyig_singleMie, camera,
                                            view_ray, r, mu, d, ground, skyig_moonDirection,
                                            transmittance) *
                    skyig_moonlightScale;
  }
  Float segment_length = length(offsetEnuM);
  Float mu_fog = segment_length > 0.0 ? offsetEnuM.z / segment_length : 1.0;
  for (int i = 0; i < 3; ++i) {
    in_scattered = throughFog(skyig_fog[i], in_scattered, skyig_cameraHeight, mu_fog, segment_length);
    transmittance *= fogTransmittance(skyig_fog[i], skyig_cameraHeight, mu_fog, segment_length);
  }
  return in_scattered;
}
