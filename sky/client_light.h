#pragma once
// The light for a client image generator's own shading (terrain, models), from the same model and
// state skyig draws the sky with (docs/client-light.md): the sun and the moon as direct lights,
// the sky as ambient irradiance and as spherical harmonics for image-based lighting, the eye's
// adaptation, and the aerial perspective between the observer and a point. CPU only, no GL.
//
// Frame: the observer's local east-north-up frame (x east, y north, z up), unit directions.
// Units: illuminance in lux, radiance in cd/m^2, colours linear Rec.709 (a "colour" normalised
// so its Rec.709 luminance 0.2126729 R + 0.7151522 G + 0.0721750 B is 1, the weights of
// physics/common/color.glsl; a "Rec.709 lux" or "Rec.709 cd/m^2" triple is scaled so that its
// luminance is the photometric value).
#include <array>

#include <glm/vec3.hpp>

#include "physics/atmosphere/model.h"

namespace skyig::sky {

struct SkyState;

// A direct light (sun or moon) at the observer, after extinction by the atmosphere.
struct ClientDirectLight {
  glm::dvec3 direction{0.0, 0.0, -1.0};  // ENU unit vector towards the body (airless)
  double normalLux = 0.0;                // on a surface facing the body
  double horizontalLux = 0.0;            // on a horizontal surface (0 below the horizon)
  glm::dvec3 colour{1.0};                // linear Rec.709, luminance 1 ({1,1,1} when dark)
};

// The first nine real spherical-harmonic coefficients L_lm (bands l = 0..2) of a radiance over
// the sphere, per linear Rec.709 channel in cd/m^2, in Ramamoorthi & Hanrahan's (2001) order:
// L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (their eq. 3 basis with x, y, z = ENU).
using ShCoefficients = std::array<glm::dvec3, 9>;

struct ClientLight {
  ClientDirectLight sun;
  ClientDirectLight moon;
  // The sky (and, below the horizon, the lit ground with its aerial perspective: what skyig
  // draws there) without the sun's and moon's discs, which are the direct lights above; at
  // night also the night's own light (airglow, zodiacal light, the Milky Way's floor, and in
  // the horizontal figures the resolved stars).
  double ambientHorizontalLux = 0.0;          // sky irradiance on a horizontal surface
  glm::dvec3 ambientHorizontalRec709{0.0};    // the same per channel (luminance = the lux)
  ShCoefficients skySh{};                     // of the radiance over the whole sphere
  // The eye's adaptation for the frame (SkyState): world adaptation luminance (cd/m^2) and the
  // display gain of a not yet adapted eye; a client tone-mapping itself may use them.
  double adaptationLuminance = 1.0;
  double adaptationGain = 1.0;
};

// The light at `state`'s observer. `model` is the physical atmosphere the state is drawn with
// (state.conditions.atmosphere), or null under an analytic sky. The sun's horizontal lux is
// `skyig probe --irradiance`'s direct_sun_lux and the moon's its moon_lux (the same code). Costs
// ~2048 sky evaluations (a few ms with the physical model): once per frame, not per pixel.
ClientLight clientLight(const SkyState& state, const atmosphere::AtmosphereModel* model);

// The sky radiance skyig draws towards an ENU unit direction, without the discs: linear Rec.709
// cd/m^2 (the sunlit and moonlit sky of the physical model, or the analytic sky; below the
// horizon the ground with its aerial perspective). What hostLight integrates.
glm::dvec3 clientSkyRadiance(const SkyState& state, const atmosphere::AtmosphereModel* model, const glm::dvec3& viewEnu);

// Irradiance (Rec.709 lux) on a surface of ENU unit normal `normal` from radiance `sh`:
// Ramamoorthi & Hanrahan (2001), eq. 13 (the quadratic form with c1..c5 of their eq. 12).
glm::dvec3 shIrradiance(const ShCoefficients& sh, const glm::dvec3& normal);

// Aerial perspective between the observer and a point `offsetEnu` metres away (ENU): the client
// shades a surface of radiance L seen there as L * transmittance + inScattered. Bruneton &
// Neyret (2008) as Bruneton's 2017 GetSkyRadianceToPoint (atmosphere::AtmosphereModel::
// skyRadianceToPoint), lit by the sun and (scaled) by the moon. Needs the physical model.
struct ClientAerialPerspective {
  glm::dvec3 transmittance{1.0};  // per Rec.709 channel, 0..1
  glm::dvec3 inScattered{0.0};    // linear Rec.709 cd/m^2
};
ClientAerialPerspective clientAerialPerspective(const SkyState& state, const atmosphere::AtmosphereModel& model,
                                            const glm::dvec3& offsetEnu);

}  // namespace skyig::sky
