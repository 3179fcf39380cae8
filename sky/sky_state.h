#pragma once
// SkyState: everything the renderer needs for a frame, computed once per host state on the
// worker thread (docs/design.md) and shared, immutable, by every channel. Adaptation
// comes from the sky model, never from a channel's pixels, so a dome shows no exposure seam.
#include "ephemeris/ephemeris.h"
#include "ephemeris/ephemeris_cache.h"
#include "ephemeris/time.h"
#include "physics/analytic/analytic_sky.h"
#include "physics/atmosphere/extinction_profile.h"
#include "sky/camera.h"
#include "sky/channel.h"
#include "sky/fog_state.h"
#include "physics/eye/glare.h"
#include "physics/eye/tone_curve.h"
#include "sky/observer.h"
#include "sky/shown_layers.h"
#include "physics/atmosphere/model.h"
#include "physics/moon/moon_disc.h"
#include "physics/moon/moon_light.h"
#include "physics/night/night_diffuse.h"
#include "physics/stars/star_field.h"
#include "physics/common/sky_conditions.h"

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace skyig::sky {

// Overrides the ephemeris (degrees), for tests and for rendering a given sun.
struct SunOverride {
  double azimuthDeg = 180.0;
  double altitudeDeg = 45.0;
};

struct SkyState {
  ObserverState observer;
  SkyConditions conditions;
  double sunAzimuth = 0.0;           // radians, from north through east
  double sunAltitude = 0.0;          // radians, airless: lights the sky
  double sunApparentAltitude = 0.0;  // radians, refracted: where the disc is seen
  // The refraction about the disc's apparent centre (apparent altitude, R, dR/dh, d2R/dh2 / 2;
  // radians; ephemeris::refractionExpansion) the sun's disc is drawn through, refracted and
  // flattened (physics/common/refraction.glsl), as the moon's is.
  glm::dvec4 sunRefraction{0.0};
  std::optional<ephemeris::SkyEphemeris> ephemeris;  // absent when the sun was overridden
  AnalyticSkyState sky;
  // What the pilot can see over the whole view sphere (sky, terrain, sun and moon), and the eye:
  // the scene's own level (its solid-angle mean luminance without the discs), the level the eye is adapted to now (the
  // same unless the sky worker follows adaptation in time, physics/eye/adaptation.h) and the
  // display gain of the mismatch (1 when adapted).
  eye::LuminanceHistogram histogram;
  double sceneLuminance = 1.0;       // cd/m^2
  double worldAdaptationLuminance = 1.0;  // the eye's adaptation to the world, cd/m^2
  double adaptationGain = 1.0;
  // The display mapping for each display the state will be shown on, computed with the state
  // (toneCurveFor); a display without one is mapped on demand.
  std::vector<std::pair<DisplayParams, eye::ToneCurve>> toneCurves;
  // The view sphere's light by source, and which faint layers change what those displays show
  // (sky/shown_layers.h; mapForDisplays decides): the renderer draws only those. Both shown
  // until a state is mapped for its displays.
  std::shared_ptr<const std::vector<ViewCellLight>> viewLight;
  ShownLayers shown;
  // Transmittance to space by elevation at the observer, for everything beyond the atmosphere
  // (moon, planets, stars, Milky Way, zodiacal light): the physical model's medium, or the
  // default medium under an analytic sky. Shared between states of nearly the same altitude.
  std::shared_ptr<const atmosphere::ExtinctionProfile> extinction;
  // A second light for the physical sky (the moonlit sky, Jensen et al. 2001): unit direction
  // in the local east-north-up frame (x east, y north, z up), airless, and the moon's irradiance
  // relative to the sun's per linear Rec.709 channel; a zero scale (the default) turns it off.
  glm::dvec3 moonDirection{0.0, 0.0, -1.0};
  glm::dvec3 moonlightScale{0.0};
  // Stars and planets as seen at the observer's time and place (also when the sun is
  // overridden: the override moves the sun only).
  std::shared_ptr<const night::StarField> starField;
  // The moon's disc as the moon pass and the probe use it, built once per state here rather
  // than per channel on the render thread; null without an ephemeris (sun overridden).
  std::shared_ptr<const night::MoonDisc> moonDisc;
  // The terrain's radiance under the night's own light (linear Rec.709 cd/m^2): the airglow,
  // zodiacal light and stars on a horizontal Lambertian ground of the state's albedo,
  // albedo E / pi. ~5e-5 cd/m^2 on a moonless night at a dark site; without it a moonless
  // terrain would be black and the eye adapted to a sky over a void. Zero without an ephemeris.
  glm::dvec3 nightGroundRadiance{0.0};
  // The sun and the moon as glare sources for the display (physics/eye/glare.h).
  eye::GlareSources glare{};
  // Fog, mist and precipitation over the clear air (physical sky only): the haze below the
  // tables' visibility, the ground fog and the precipitation of conditions.haze, .fog and
  // .precipitation, lit by this state's sun and moon.
  FogState fog;
};

// The night's sources of a state, for the probe, the passes and tests: the moon's illuminance on
// the ground (0 without a moon), the moonlit sky along a view, and the diffuse night light
// (none without an ephemeris, when the sun was overridden; without the Milky Way map where
// `withMilkyWay` is false: the GPU passes read their own texture of it, and the render thread
// then never takes MilkyWayMap::standard()'s lock).
double moonIlluminanceLux(const SkyState& state);
night::MoonRadiance moonlitSkyRadiance(const atmosphere::AtmosphereModel& model, const SkyState& state,
                                       const glm::dvec3& viewEnu);
std::optional<night::NightDiffuseSky> nightDiffuseSky(const SkyState& state, bool withMilkyWay = true);

// What consecutive states of one observer share, owned by whoever builds them (the sky worker,
// node/frame/sky_worker.h): the ephemeris' frame-to-frame interpolation (3 us instead of 28 us an
// update) and the extinction profile (tens of milliseconds), computed at the nearest height of a
// fixed grid (25 m apart, 2 % above 1250 m) and reused while the observer stays nearest to it and
// the medium is unchanged: a state is a function of its own inputs, whatever was built before.
// Not shared between threads.
class SkyStateCaches {
 public:
  ephemeris::EphemerisCache ephemeris;
  std::shared_ptr<const atmosphere::ExtinctionProfile> extinction(const atmosphere::Medium& medium, double heightM);

 private:
  std::shared_ptr<const atmosphere::ExtinctionProfile> lastExtinction_;
  atmosphere::Medium lastMedium_;
};

// The state of `observer` under `conditions`. Throws std::invalid_argument naming the bad value
// (latitude out of range, NaN, a pressure or temperature refraction cannot use, a date outside
// the ephemeris' 1900-2100). The ephemeris is the precise one (ephemeris/ephemeris.h), at the
// observer's pressure and temperature. Without `caches` everything is computed afresh.
// The tone curve of `state` for `display` (Tumblin-Rushmeier displays get none: an empty curve).
eye::ToneCurve toneCurveFor(const SkyState& state, const DisplayParams& display);
// Computes state.toneCurves for each distinct display of `displays` (the sky worker does, for the
// node's channels).
void mapForDisplays(SkyState& state, const std::vector<DisplayParams>& displays);

SkyState buildSkyState(const ObserverState& observer, const SkyConditions& conditions,
                       const std::optional<SunOverride>& sun = std::nullopt, SkyStateCaches* caches = nullptr);

}  // namespace skyig::sky
