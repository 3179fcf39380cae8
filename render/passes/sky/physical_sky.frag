// Sky pass of the physical atmosphere (Bruneton & Neyret 2008, section 5 without light
// shafts) from the tables folded into linear Rec.709 (physics/atmosphere/rendering_rec709.glsl): the
// sky scattered into the view ray, the limb-darkened sun disc and, where the ray meets the
// ground, the Lambertian ground attenuated by the air in between; one lookup set per pixel
// whatever the number of wavelengths. A second light, the moon (Jensen et al. 2001: the same
// tables lit from its direction times its irradiance relative to the sun's), adds its sky and
// ground.
// Variants, not branches: llvmpipe runs both sides of a branch for every pixel, so a frame pays
// only for what it shows by compiling this file several ways (PhysicalSkyPass builds each):
//   (none)          the sun's sky and ground, over the whole channel;
//   SKYIG_MOONLIT   the same with the moon's sky and ground, when the moon lights the sky;
//   SKYIG_SUNLESS   without the sun's sky and ground (and no disc quad), when the sun is so far
//                   below the horizon that its twilight changes no display code
//                   (sky/shown_layers.h): the night's pixels pay for the moon's and the night's
//                   light only;
//   SKYIG_SUN_DISC  with the disc, drawn again over a small quad around the sun
//                   (render/passes/sky/sun_disc.vert) after the variant without it drew the channel: the
//                   disc covers ~1e-5 of the pixels that would otherwise all evaluate its test
//                   (the quad's pixels are drawn twice, the sky and the disc summed before the
//                   clamp as everywhere, so an out-of-gamut red disc keeps the sky's blue);
//   SKYIG_GROUND    the rays that meet the ground only, drawn first on the cap of directions
//                   below the horizon (render/passes/sky/ground_cap.vert; a pixel whose ray misses the
//                   ground is discarded, so the cap's polygon need not be exact) writing depth;
//   SKYIG_SKY       the rays that miss it, drawn after over the whole channel where the ground
//                   variant wrote no depth: the sky's pixels never pay for the ground's
//                   reflection. Neither: both, for a target without depth.
//   SKYIG_NIGHT_LAYER the night's own light added (the eye's band only): the sky's part above the
//                   atmosphere read bilinearly from the small grid NightDiffusePass::drawLayer
//                   drew (render/passes/common/night_layer.glsl; it varies over the Milky Way map's 0.18 deg
//                   texels, coarser than a pixel), dimmed by the transmittance to space, and the
//                   terrain's below the horizon, both per pixel, as render/passes/night/night_diffuse.frag
//                   adds them over the whole channel: one full-screen pass instead of two; with
//                   SKYIG_GLARE_FROM_NIGHT_LAYER the same read gives the tone its glare veil;
//   SKYIG_NIGHT_LAYER_TRANSMITTED with it, the layer's light already dimmed at its texels, for
//                   the sky more than kNightLayerBandDeg above the horizon (render/passes/
//                   night_layer.h), where the transmittance is smooth over a texel: drawn after
//   SKYIG_HORIZON_BAND the sky below that elevation with the transmittance per pixel, a cap of
//                   directions like the ground's (render/passes/sky/ground_cap.vert) writing depth after the
//                   ground's (the define only names the program: it is SKYIG_SKY's code);
//   SKYIG_HORIZON_EDGE the pixels the horizon crosses, drawn last on a strip around it
//                   (render/passes/sky/horizon_strip.vert) with no depth test: the ground's and
//                   the sky's rays mixed by their shares of the pixel (docs/anti-aliasing.md), the
//                   disc with the sky's; a pixel wholly on one side is discarded, the parts' own;
//   SKYIG_FOLD_TONE with the tone pass's variant defines: the pass also writes what the display
//                   is sent (render/passes/tone/tone_display.glsl) at SKYIG_OUTPUT_FOLDED_DISPLAY, when it is
//                   the frame's last full-screen pass: no second pass reads every pixel back
//                   (SkyRenderer::drawChannel; the tone pass then runs only where later passes
//                   drew: the moon's quad, the displayed stars, the boxes of the exact veil).
// With the camera inside the atmosphere (every IG frame), r, u_r and u_mu_s are the same for
// every pixel and come from the CPU (PhysicalSkyPass::draw): the scattering tables are read
// from this frame's 2D slices (physical_sky_slice.frag); only u_mu and u_nu are per pixel.
// From space physical_sky_space.frag runs instead (a second program: a branch between the two
// costs llvmpipe the untaken side too).
// (No render/glsl/uniforms.h here: its analytic-sky block's member names would clash with the
// atmosphere's functions; the frame block, which the vertex stage and the night layer read, is
// in render/glsl/frame_uniforms.h, the tone block in render/glsl/tone_uniforms.h.)
#include "render/passes/sky/physical_sky_uniforms.glsl"
#include "render/glsl/band.glsl"
#include "render/glsl/edge_coverage.glsl"
#ifdef SKYIG_FOG
#include "physics/weather/fog_table.glsl"
// The haze below the tables' visibility, the ground fog and the precipitation (sky/fog_state.h)
// along this frame's views by their cosine to the vertical: their own light (rgb) and the
// transmittance of what lies behind them (a), composed on the CPU from physics/weather/fog_layer.glsl.
layout(binding = SKYIG_UNIT_FOG_TABLE) uniform sampler1D fogTable;
#ifdef SKYIG_CLOUD_COVER
// A broken cloud deck: fogTable holds the layers with its gaps filled, this one without it; the
// deck's field says how much of each the pixel's view meets, where the view crosses the deck's
// middle height (cloudShareAlong).
#include "render/passes/common/cloud_field.glsl"
layout(binding = SKYIG_UNIT_FOG_CLEAR_TABLE) uniform sampler1D fogClearTable;
#endif
#ifdef SKYIG_CLOUD_LIGHT
// The sun's (and the moon's) light each deck the eye is outside of scatters once towards it
// (physics/weather/cloud_sunlight.glsl), where the view meets the face it sees: its base from
// under it, its top from over it. The light reaches that point through the air (for the light's
// local elevation there: a low sun shines on a distant base from below, reddened), and the eye
// through the air and the weather's layers between (cloudLitSide.z, their vertical optical
// depth). The face is a sphere and the eye is on the vertical, so both transmittances are
// functions of one cosine each: rows of a small table the CPU fills from the model
// (PhysicalSkyPass::updateCloudLightTable), one read each instead of the transmittance table's
// geometry per pixel (8 times the sky pass's cost on llvmpipe).
#include "physics/weather/cloud_cover.glsl"
#include "physics/weather/cloud_sunlight.glsl"
#include "physics/weather/fog_layer.glsl"
uniform vec4 cloudLit[3];      // the face's height (m), the deck's optical depth, asymmetry, its broken index (-1: whole)
uniform vec4 cloudLitSide[3];  // 1: its base seen from under it, -1: its top from over it; its reflectance; the layers' depth between
uniform vec2 cloudLitEye;      // the eye above the ground (m), the ground's radius (m)
// Rows k < 3: deck k's face lit by the sun, linear Rec.709 lux normal to it, by fogTableU of
// mu_s (fine steps where the sun grazes the face's horizon: a sunset's light there changes by
// orders of magnitude and colour within a degree, which steps of 0.45 deg blended bluer);
// rows 3 + k: the air's transmittance from the eye to it (r), by fogTableU of the view's cosine.
layout(binding = SKYIG_UNIT_CLOUD_LIGHT_TABLE) uniform sampler2D cloudLightTable;

vec3 cloudSingleLight(vec3 view, vec3 light, vec3 scale) {
  vec3 sum = vec3(0.0);
  for (int k = 0; k < SKYIG_CLOUD_LIGHT; ++k) {  // the lit decks, 1-3: the variant's (as SKYIG_CLOUD_COVER)
    float d = distanceToHeight(cloudLitEye.y, cloudLitEye.x, view.z, cloudLit[k].x);
    if (d < 0.0) continue;
    vec3 p = camera + view * d;
    float r_p = length(p);
    vec3 n = (cloudLitSide[k].x > 0.0 ? -1.0 : 1.0) * (p / r_p);  // the face's outward normal
    float mu = dot(-view, n);
    float mu0 = dot(light, n);
    if (mu <= 0.0 || mu0 == 0.0) continue;
    float row = (float(k) + 0.5) / 6.0;
    vec3 e = texture(cloudLightTable, vec2(fogTableU(dot(p / r_p, light)), row)).rgb * scale;
    float tau = cloudLit[k].y;
    float g = cloudLit[k].z;
    float cos_theta = dot(view, light);
    float l = cloudSingleScattered(tau, g, mu0, mu, cos_theta);
    // A base lit from below (a sun under the deck's horizon there) diffuses that light too: the
    // two-stream's reflectance by the base's law; the table holds only the light from above.
    if (mu0 > 0.0 && cloudLitSide[k].x > 0.0) l += cloudLitSide[k].y * mu0 / PI * fogLimbLaw(2.0, mu);
    float share = 1.0;
#ifdef SKYIG_CLOUD_COVER
    if (cloudLit[k].w >= 0.0) share = dot(cloudShares, vec3(equal(vec3(cloudLit[k].w), vec3(0.0, 1.0, 2.0))));  // cloudShareAlong's
#endif
    float ta = texture(cloudLightTable, vec2(fogTableU(view.z), row + 0.5)).r;
    sum += e * (l * share * ta * exp(-cloudLitSide[k].z / max(abs(view.z), 0.02)));
  }
  return sum;
}
#endif
#endif
#ifdef SKYIG_NIGHT_LAYER
#include "render/glsl/frame_uniforms.h"
#include "physics/night/transmittance_to_space.glsl"
#include "render/passes/common/night_layer.glsl"
layout(binding = SKYIG_UNIT_NIGHT_LAYER_EXTINCTION) uniform sampler1D nightExtinction;
uniform vec3 nightGroundRadiance;  // linear Rec.709, cd/m^2: the terrain under the night's light
// This pixel's read of the layer: its alpha is the glare veil per lux where the layer holds it.
vec4 nightLayerHere;
#ifdef SKYIG_GLARE_FROM_NIGHT_LAYER
float nightLayerVeilPerLux(vec2 fragCoord) { return nightLayerHere.a; }
#endif
#endif
#ifdef SKYIG_FOLD_TONE
#include "render/passes/tone/tone_display.glsl"
layout(location = SKYIG_OUTPUT_FOLDED_DISPLAY) out vec4 outDisplay;
#endif

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

// The sun's disc this pixel sees (SKYIG_SUN_DISC), kept apart from the sky so that the weather's
// layers dim it by their own transmittance along the sun's ray (fogSunThrough) rather than by
// the table's share of the clear air's light, which a deck seen through the air in front of it
// keeps in part (physics/weather/fog_table.h).
vec3 sunDiscHere = vec3(0.0);
#ifdef SKYIG_SUN_DISC
float sunDiscX = 2.0;           // where the pixel's airless direction falls (sunDiscFraction)
vec2 sunDiscXStep = vec2(0.0);  // and its change to the next pixel (x, y)
#endif
#ifdef SKYIG_FOG
uniform float fogSunThrough;  // the layers' transmittance along the sun's apparent direction
#endif

// The night's own light from beyond a broken deck along this view over what the state's
// extinction profile lets through (cloudFieldFactor): behind a cloud or in a gap, as the stars.
float nightThroughClouds = 1.0;

// The air's light along `view`, taken as a ray that meets the ground or as one that misses it.
vec3 insideRec709(vec3 view, bool ground) {
  float rmu = dot(camera, view);
  float d;  // the distance the view ray goes on (to the ground, or out of the atmosphere)
  float u_mu = frameUMu(rmu, ground, d);
  float nu = dot(view, sunDirectionP);
#ifdef SKYIG_SUNLESS
  vec3 rgb = vec3(0.0);
#else
  vec3 rgb = sliceScatteredRec709(sunSliceScattering, sunSliceSingleMie, u_mu, nu);
  if (ground) {
    rgb += packedGroundReflectionRec709(atm, transmittanceXyz, irradianceXyz, solarIrradianceXyz,
                                        groundAlbedo, camera, view, d, sunDirectionP);
  }
#endif
#ifdef SKYIG_MOONLIT
  float nu_moon = dot(view, moonDirectionP);
  vec3 moon = sliceScatteredRec709(moonSliceScattering, moonSliceSingleMie, u_mu, nu_moon);
  if (ground) {
    moon += packedGroundReflectionRec709(atm, transmittanceXyz, irradianceXyz, solarIrradianceXyz,
                                         groundAlbedo, camera, view, d, moonDirectionP);
  }
  rgb += bandRatio(band.z) * moonlightScale * moon;
#endif
#ifdef SKYIG_SUN_DISC
  // The disc as seen: refracted and flattened (physics/common/refraction.glsl), where the airless
  // direction this pixel sees falls on the airless sun, within the cone (frameAngles.z) the
  // refracted disc can fall in.
  // The limb shared by the pixels it crosses (render/glsl/edge_coverage.glsl): the pixel's part on
  // the disc, shown at the middle of that part (its centre for a pixel within the disc, half the
  // part's depth inside the limb for one across it), so the limb neither steps nor moves.
  float share = pixelShareAbove(1.0 - sunDiscX, -sunDiscXStep);
  if (!ground && nu >= frameAngles.z && share > 0.0) {
    float x = min(sunDiscX, 1.0 - 0.5 * share * length(sunDiscXStep));
    sunDiscHere = share * bandRatio(band.y) *
                  xyzToRec709Linear(packedSunDiscAtXyz(atm, transmittanceXyz, solarIrradianceXyz, limbDarkeningXyz,
                                                       camera, view, x));
  }
#endif
  return rgb;
}

void main() {
  // In a goggle's band the sum is weighted as sunlit sky, its other parts scaled above by their
  // weights' ratios to it (render/glsl/band.glsl).
  vec3 view = normalize(vViewRay);
#ifdef SKYIG_SUN_DISC
  // Taken before any discard, as derivatives need the whole quad.
  sunDiscX = sunDiscFraction(unrefractView(view, sunRefraction), sunDirectionP, sin(atm.sun_angular_radius));
  sunDiscXStep = vec2(dFdx(sunDiscX), dFdy(sunDiscX));
#endif
#ifdef SKYIG_NIGHT_LAYER
  // The terrain under the night's light is below the geometric horizon (night_diffuse.frag's
  // edge), shared by its pixels as the air's horizon is; taken before any discard, as
  // derivatives need the whole quad.
  float nightGroundShare = 1.0 - pixelShareAbove(view.z);
#endif
  // The ray misses the ground where its cosine to the vertical (view.z: the camera is on the
  // model's +z axis) exceeds the horizon's, -rho / r (rayIntersectsGround).
#if defined(SKYIG_HORIZON_EDGE)
  // The pixels the horizon crosses, drawn over the parts: the ground's light and the sky's, each
  // by its share of the pixel's square (render/glsl/edge_coverage.glsl), so the horizon is as
  // sharp as the pixels allow and does not step. Every other pixel is the parts' own.
  float skyShare = pixelShareAbove(view.z + frameRadii.y / frameRadii.x);
  if (skyShare <= 0.0 || skyShare >= 1.0) discard;
  vec3 air = mix(insideRec709(view, true), insideRec709(view, false), skyShare);
  sunDiscHere *= skyShare;
#elif defined(SKYIG_SKY)
  vec3 air = insideRec709(view, false);
#else
  bool ground = rayIntersectsGround(atm, frameRadii.x, dot(camera, view) / frameRadii.x);
#if defined(SKYIG_GROUND)
  if (!ground) discard;
#endif
  vec3 air = insideRec709(view, ground);
#endif
  vec3 radiance = inBand(air, lightWeights.x);
  vec3 disc = inBand(sunDiscHere, lightWeights.x);
#ifndef SKYIG_FOG
  radiance = max(radiance + disc, vec3(0.0));  // summed before the clamp: a red disc keeps the sky's blue
#endif
  // Fog and mist in front of the air's light (physics/weather/fog_layer.glsl); the camera is on
  // the model's +z axis, so view.z is the cosine to its vertical. The night's layer below came
  // through the fog already (the state's extinction profile, sky/sky_state.cpp).
#ifdef SKYIG_FOG
  vec4 fog = texture(fogTable, fogTableU(view.z));
#ifdef SKYIG_CLOUD_COVER
  vec4 fogClear = texture(fogClearTable, fogTableU(view.z));
  float share = cloudShareAlong(view);
  nightThroughClouds = cloudFieldFactor(fogClear.a, fog.a, share);
  fog = mix(fogClear, fog, share);
#endif
  // A goggle's table holds the layers' NVIS radiance as its luminance (sky/nvis_weights.h,
  // goggleFogLayers: each layer's light weighted by the spectrum of what lights it).
  radiance = max(radiance * fog.a + inBand(fog.rgb, 1.0) + disc * fogSunThrough, vec3(0.0));
#ifdef SKYIG_CLOUD_LIGHT
  vec3 single = vec3(0.0);
#ifndef SKYIG_SUNLESS
  single += bandRatio(band.y) * cloudSingleLight(view, sunDirectionP, vec3(1.0));
#endif
#ifdef SKYIG_MOONLIT
  single += bandRatio(band.z) * cloudSingleLight(view, moonDirectionP, moonlightScale);
#endif
  radiance = max(radiance + inBand(single, lightWeights.x), vec3(0.0));
#endif
#endif
#ifdef SKYIG_NIGHT_LAYER
  nightLayerHere = nightLayerAt(gl_FragCoord.xy);
#if defined(SKYIG_NIGHT_LAYER_TRANSMITTED)
  radiance += nightThroughClouds * nightLayerHere.rgb + nightGroundShare * nightGroundRadiance;
#else
  radiance += nightThroughClouds * transmittanceToSpace(nightExtinction, view) * nightLayerHere.rgb +
              nightGroundShare * nightGroundRadiance;
#endif
#endif
  outRadiance = vec4(radiance, 1.0);
#ifdef SKYIG_FOLD_TONE
  outDisplay = toneDisplayValue(radiance, vec3(0.0), gl_FragCoord.xy);  // no point source drawn yet
#endif
}
