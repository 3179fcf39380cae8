// THE REFERENCE, FROZEN: do not edit. skyig's physical sky pass as it was on 2026-11-24
// (render/passes/sky/physical_sky.frag of that day, byte for byte below this comment), the pass
// measured at 0.38x of Bruneton & Neyret's 2017 demo pass per pixel (process CPU, interleaved
// runs, llvmpipe on one thread, 1280x1024; docs/performance.md, "Ratios against the reference").
// It is kept so that every later change of the live pass reports "x of the reference" in one
// run of `skyig bench --ratios` rather than an absolute time that a busy machine moves by 2x.
// It draws with the live pass's inputs (uniforms, this frame's slices, tables): PhysicalSkyPass
// builds it in place of physical_sky.frag for render/passes/sky/reference_sky_pass.h, and the test
// ReferenceSkyPass.ReferencePassDrawsTheSkyPassImage checks that both still draw the same image.
// Frozen is this file, the per-pixel work of the pass (which branches, which lookups); the
// physics functions it calls (physics/atmosphere/rendering_rec709.glsl, physics/common/refraction.glsl) are
// shared with the live pass, so a change there moves both and shows in the absolute ns/pixel.
//
// Sky pass of the physical atmosphere (Bruneton & Neyret 2008, section 5 without light
// shafts) from the tables folded into linear Rec.709 (physics/atmosphere/rendering_rec709.glsl): the
// sky scattered into the view ray, the limb-darkened sun disc and, where the ray meets the
// ground, the Lambertian ground attenuated by the air in between; one lookup set per pixel
// whatever the number of wavelengths. A second light (the moon: Jensen et al. 2001, the same
// tables lit from its direction times its irradiance relative to the sun's) adds its sky and
// ground when moonlightOn, a uniform branch.
// With the camera inside the atmosphere (every IG frame), r, u_r and u_mu_s are the same for
// every pixel and come from the CPU (PhysicalSkyPass::draw): the scattering tables are read
// from this frame's 2D slices (physical_sky_slice.frag); only u_mu and u_nu are per pixel.
// From space physical_sky_space.frag runs instead (a second program: a branch between the two
// costs llvmpipe the untaken side too).
// (No render/glsl/uniforms.h here: its analytic-sky block's member names would clash with the
// atmosphere's functions; the vertex stage alone reads the frame block.)
#include "render/passes/sky/physical_sky_uniforms.glsl"

// This frame's 2D slices of the scattering tables (physical_sky_slice.frag) for the sun and
// the moon: x = nu texel, y = u_mu.
layout(binding = SKYIG_UNIT_SUN_SLICE_SCATTERING) uniform sampler2D sunSliceScattering;
layout(binding = SKYIG_UNIT_SUN_SLICE_SINGLE_MIE) uniform sampler2D sunSliceSingleMie;
layout(binding = SKYIG_UNIT_MOON_SLICE_SCATTERING) uniform sampler2D moonSliceScattering;
layout(binding = SKYIG_UNIT_MOON_SLICE_SINGLE_MIE) uniform sampler2D moonSliceSingleMie;

// packedScatteredRec709 from a slice: GL's bilinear filter does the blend in nu by hand of
// lookupScatteringUvwz (the same weights: texel centres at (i + 0.5) / nu_size).
vec3 sliceScatteredRec709(sampler2D scattering, sampler2D singleMie, float u_mu, float nu) {
  float x = ((nu + 1.0) * 0.5 * (atm.scattering_nu_size - 1.0) + 0.5) / atm.scattering_nu_size;
  vec4 s = texture(scattering, vec2(x, u_mu));
  vec4 m = texture(singleMie, vec2(x, u_mu));
  return (s.xyz * rayleighPhaseFunction(nu) + vec3(m.x, m.y, s.w) * miePhaseFunction(atm, nu)) *
         (1.0 / REC709_TABLE_SCALE);
}


// u_mu of scatteringUvwzFromRMuMuSNu for this frame's radius; d: distance to the ground.
float frameUMu(float rmu, bool ground, out float d) {
  float r = frameRadii.x;
  float rho = frameRadii.y;
  float H = frameRadii.z;
  float discriminant = rmu * rmu - rho * rho;
  if (ground) {
    d = -rmu - sqrt(max(discriminant, 0.0));
    float d_min = r - atm.bottom_radius;
    return 0.5 - 0.5 * textureCoordFromUnitRange((d - d_min) / (rho - d_min), atm.scattering_mu_size / 2.0);
  }
  d = -rmu + sqrt(max(discriminant + H * H, 0.0));
  float d_min = atm.top_radius - r;
  return 0.5 + 0.5 * textureCoordFromUnitRange((d - d_min) / (rho + H - d_min), atm.scattering_mu_size / 2.0);
}

vec3 insideRec709(vec3 view) {
  float r = frameRadii.x;
  float rmu = dot(camera, view);
  bool ground = rayIntersectsGround(atm, r, rmu / r);
  float d;
  float u_mu = frameUMu(rmu, ground, d);
  float nu = dot(view, sunDirectionP);
  vec3 rgb = sliceScatteredRec709(sunSliceScattering, sunSliceSingleMie, u_mu, nu);
  if (ground) {
    rgb += packedGroundReflectionRec709(atm, transmittanceXyz, irradianceXyz, solarIrradianceXyz,
                                        groundAlbedo, camera, view, d, sunDirectionP);
  } else if (nu >= frameAngles.z) {
    // The disc as seen: refracted and flattened (physics/common/refraction.glsl), where the airless
    // direction this pixel sees falls on the airless sun.
    vec3 airless = unrefractView(view, sunRefraction);
    rgb += xyzToRec709Linear(packedRefractedSunDiscXyz(atm, transmittanceXyz, solarIrradianceXyz,
                                                       limbDarkeningXyz, camera, view, airless,
                                                       sunDirectionP));
  }
  if (moonlightOn) {
    float nu_moon = dot(view, moonDirectionP);
    vec3 moon = sliceScatteredRec709(moonSliceScattering, moonSliceSingleMie, u_mu, nu_moon);
    if (ground) {
      moon += packedGroundReflectionRec709(atm, transmittanceXyz, irradianceXyz, solarIrradianceXyz,
                                           groundAlbedo, camera, view, d, moonDirectionP);
    }
    rgb += moonlightScale * moon;
  }
  return rgb;
}

void main() {
  outRadiance = vec4(max(insideRec709(normalize(vViewRay)), vec3(0.0)), 1.0);
}
