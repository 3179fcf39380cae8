#pragma once
// SkyState: everything the renderer needs for a frame, computed once per host state on the
// worker thread (../shared/DESIGN.md) and shared, immutable, by every channel. Adaptation
// comes from the sky model, never from a channel's pixels, so a dome shows no exposure seam.
#include "ephemeris/ephemeris.h"
#include "ephemeris/ephemeris_cache.h"
#include "ephemeris/time.h"
#include "render/analytic_sky.h"
#include "render/atmosphere/extinction_profile.h"
#include "render/camera.h"
#include "render/sky_conditions.h"

#include <memory>
#include <optional>

namespace skyig::render {

// Where the ownship is, how it is oriented, and when: the host's state, as used for a frame.
struct ObserverState {
  double latitudeDeg = 47.2603;   // Innsbruck airport (LOWI), a valley the sky is framed by
  double longitudeDeg = 11.3439;
  double heightM = 581.0;         // above the WGS84 ellipsoid
  Attitude attitude{180.0, 5.0, 0.0};
  ephemeris::UtcTime utc{2026, 6, 21, 17 * 3600.0};  // 19:00 CEST on midsummer's day
};

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
  std::optional<ephemeris::SkyEphemeris> ephemeris;  // absent when the sun was overridden
  AnalyticSkyState sky;
  double adaptationLuminance = 1.0;  // the eye's world adaptation, cd/m^2
  // Transmittance to space by elevation at the observer, for everything beyond the atmosphere
  // (moon, planets, stars, Milky Way, zodiacal light): the physical model's medium, or the
  // default medium under an analytic sky. Shared between states of nearly the same altitude.
  std::shared_ptr<const atmosphere::ExtinctionProfile> extinction;
  glm::dvec3 moonDirection{0.0, 0.0, -1.0};  // ENU, airless: lights the sky like the sun
  glm::dvec3 moonlightScale{0.0};            // moon / sun irradiance per Rec.709 channel; 0: no moonlit sky
};

// Throws std::invalid_argument naming the bad value (latitude out of range, NaN, a date
// outside the ephemeris' 1900-2100). The ephemeris is the precise one (ephemeris/ephemeris.h).
// `cache`: a per-thread ephemeris cache for frame-to-frame use (the worker's, 3 us instead of
// 28 us an update); without it every series is evaluated.
SkyState buildSkyState(const ObserverState& observer, const SkyConditions& conditions,
                       const std::optional<SunOverride>& sun = std::nullopt,
                       ephemeris::EphemerisCache* cache = nullptr);

}  // namespace skyig::render
