#pragma once
// The moon's disc on the CPU (docs/night-sky.md "Moon"): its radiance along a view and its
// illuminance on the ground, from the same physics as the GL pass (physics/moon/moon.glsl).
// The disc's irradiance above the atmosphere is eq. 9 of Wang, Ji & Zhang 2011 (after Jensen
// et al. 2001, "A physically-based night sky model"; corrected: its phase law's last factor is
// ln(cot(phi/4)), printed with cos) for the sunlit part at every phase; the earthshine adds its
// own, physically lit, share.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <optional>

#include "ephemeris/ephemeris.h"
#include "ephemeris/refraction.h"
#include "physics/atmosphere/extinction_profile.h"
#include "physics/moon/moon_albedo.h"

namespace skyig::sky::night {

// Linear Rec.709 radiance (cd/m^2 per channel) and its luminance.
struct MoonRadiance {
  glm::dvec3 rec709{0.0};
  double luminanceCdM2 = 0.0;
};

// Where the moon is and how it is lit: from the ephemeris, or set by hand (tests).
struct MoonPlacement {
  double azimuthRad = 0.0;            // from north through east
  double altitudeRad = 0.0;           // airless
  double altitudeRefractedRad = 0.0;  // where it is seen
  double distanceKm = 384400.0;       // from the observer
  double phaseAngleRad = 0.0;         // sun-moon-observer; 0 = full
  double brightLimbAngleRad = 0.0;    // from the zenith direction, counterclockwise as seen
  double sunMoonDistanceKm = 149597870.7;
  // Orients the albedo map: the moon's axis stays within 1.5 deg of the ecliptic pole (Cassini's
  // laws); libration (up to 8 deg) is neglected. Unit vector, ENU.
  glm::dvec3 eclipticPoleEnu{0.0, 0.0, 1.0};
  double pressureHpa = ephemeris::kStandardPressureHpa;  // the air at the observer, for refraction
  double temperatureC = ephemeris::kStandardTemperatureC;
};

// Everything the disc needs per frame; the GL pass uploads the same numbers.
struct MoonDisc {
  glm::dvec3 centre{0.0, 0.0, 1.0};      // ENU unit vector, airless
  glm::dvec3 centreSeen{0.0, 0.0, 1.0};  // ENU unit vector, refracted
  double angularRadiusRad = 0.0;
  glm::dvec3 towardSun{0.0, 0.0, 1.0};   // from the moon to the sun, ENU
  glm::dvec3 north{0.0, 0.0, 1.0};       // the moon's north pole, ENU
  glm::dvec3 east{1.0, 0.0, 0.0};        // selenographic longitude +90 deg, ENU
  glm::dvec3 sunlitScale{0.0};           // cd/m^2 per unit albedo x Lommel-Seeliger factor
  glm::dvec3 earthshineScale{0.0};       // cd/m^2 per unit albedo x 1/2
  // Refraction near the disc as a function of apparent altitude h: (h0, R(h0), R'(h0), R''(h0)/2),
  // radians, for physics/common/refraction.glsl's unrefractView.
  glm::dvec4 refraction{0.0};
  glm::dvec3 irradianceRec709{0.0};      // the disc's irradiance above the atmosphere, lux per channel
  std::shared_ptr<const atmosphere::ExtinctionProfile> extinction;  // null: no atmosphere
  const MoonAlbedo* albedo = nullptr;
};

MoonPlacement moonPlacement(const ephemeris::SkyEphemeris& sky);

// Throws std::invalid_argument naming a non-finite or out-of-range placement value.
// Costs ~0.3 ms when the sun has moved in the moon's frame (the map's normalisation over the lit
// part, cached per thread), a few microseconds otherwise: once per state, not per pixel.
MoonDisc makeMoonDisc(const MoonPlacement& placement,
                      std::shared_ptr<const atmosphere::ExtinctionProfile> extinction,
                      const MoonAlbedo& albedo = MoonAlbedo::standard());

// Radiance seen along a view (ENU, need not be normalised) at the observer, after extinction;
// zero off the disc (a hard limb: no pixel footprint on the CPU).
MoonRadiance moonDiscRadiance(const MoonDisc& disc, const glm::dvec3& viewEnu);

// The moon's illuminance on a surface facing it at the observer, lux per linear Rec.709 channel,
// after extinction (along the airless direction); zero when the disc is seen below the horizon.
glm::dvec3 moonNormalIlluminanceRec709(const MoonDisc& disc);
// The moon's illuminance on a horizontal surface at the observer, lux, after extinction: the
// above times the sine of the disc's apparent altitude.
double moonIlluminanceLux(const MoonDisc& disc);

}  // namespace skyig::sky::night
