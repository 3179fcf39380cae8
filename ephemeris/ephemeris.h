#pragma once
// skyig's precise ephemeris: apparent topocentric positions of the sun, moon and the five
// naked-eye planets, moon appearance, night-sky irradiances and the J2000 -> local east-north-up
// matrix for the stars, for 1900-2100 (docs/ephemeris.md gives the models and measured errors).
//
// Pipeline (all vectors in the GCRS/J2000 frame until the last step): VSOP87B earth and planets
// with light time, ELP 2000-82B moon, geodetic observer (WGS84, GeographicLib) rotated into the
// sky with GAST and the IAU 2006/2000B bias-precession-nutation matrix, annual + diurnal
// aberration, then true equator of date -> local east-north-up. Angles in radians; azimuth from
// north through east in [0, 2 pi).
#include <array>
#include <optional>
#include <string>

#include "ephemeris/refraction.h"
#include "ephemeris/bsc5.h"
#include "ephemeris/time.h"
#include "ephemeris/time_scales.h"
#include "ephemeris/vec3.h"

namespace skyig::ephemeris {

struct Observer {
  double latitudeRad = 0.0;   // geodetic (WGS84), [-pi/2, pi/2]
  double longitudeRad = 0.0;  // east positive
  double heightM = 0.0;       // above the WGS84 ellipsoid
  double pressureHpa = kStandardPressureHpa;    // refraction (ephemeris/refraction.h)
  double temperatureC = kStandardTemperatureC;
};

struct EphemerisOptions {
  std::optional<double> ttMinusUtcS;  // overrides TT - UTC (seconds)
  std::optional<double> dut1S;        // UT1 - UTC (seconds), default 0
};

struct BodyPosition {
  double azimuthRad = 0.0;            // from north through east, [0, 2 pi)
  double altitudeRad = 0.0;           // airless
  double altitudeRefractedRad = 0.0;  // with refraction (Saemundsson, scaled by P and T)
  double distanceKm = 0.0;            // from the observer
  double rightAscensionRad = 0.0;     // apparent topocentric, true equator and equinox of date
  double declinationRad = 0.0;
  Vec3 enu;                           // unit vector, local east-north-up (airless)
};

struct SunState : BodyPosition {
  double angularRadiusRad = 0.0;
  double irradianceWm2 = 0.0;  // Wang, Ji & Zhang 2011, eq. 11 (corrected), sun's V magnitude
};

struct MoonState : BodyPosition {
  double phaseAngleRad = 0.0;        // sun-moon-observer angle; 0 = full
  double illuminatedFraction = 0.0;  // (1 + cos phase) / 2
  // Position angle of the midpoint of the bright limb, measured from the direction towards the
  // zenith, counterclockwise as the observer sees the sky (towards the left), [0, 2 pi).
  double brightLimbAngleRad = 0.0;
  double angularRadiusRad = 0.0;
  double irradianceWm2 = 0.0;        // Wang, Ji & Zhang 2011, eq. 9 (corrected)
};

struct PlanetState : BodyPosition {
  const char* name = "";
  double magnitude = 0.0;            // apparent V (Mallama & Hilton 2018)
  double phaseAngleRad = 0.0;        // sun-planet-observer angle
  double illuminatedFraction = 0.0;
  double irradianceWm2 = 0.0;        // Wang, Ji & Zhang 2011, eq. 11 (corrected)
};

struct SkyEphemeris {
  TimeScales time;
  double gmstRad = 0.0;
  double gastRad = 0.0;
  SunState sun;
  MoonState moon;
  std::array<PlanetState, 5> planets;  // Mercury, Venus, Mars, Jupiter, Saturn
  // Stars: ENU direction = j2000ToEnu * normalize(u + aberrationJ2000) for a J2000 unit vector u
  // (proper motion applied with starDirectionAt). Row-major.
  Mat3 j2000ToEnu;
  Mat3 j2000ToTrueOfDate;  // bias-precession-nutation (IAU 2006/2000B)
  Vec3 aberrationJ2000;  // observer's barycentric velocity / c (annual + diurnal)
  // The recipe above neglects the sun's light deflection: 0.05" at 10 degrees from the sun,
  // 0.5" at 1 degree; starPosition includes it.
  Vec3 earthHeliocentricAu;  // J2000, for the light deflection
  Observer observer;
};

// Throws std::invalid_argument naming the bad value (latitude outside +-90 degrees, non-finite
// coordinates, height outside [-1000 m, 100 km], pressure or temperature out of range).
void checkObserver(const Observer& observer);

// Throws std::invalid_argument with a message naming the value for a bad date (invalid or outside
// 1900-2100), a latitude outside +-90 degrees, a non-finite coordinate, a height outside
// [-1000 m, 100 km], or a pressure/temperature out of range.
SkyEphemeris computeEphemeris(const UtcTime& utc, const Observer& observer,
                              const EphemerisOptions& options = {});

struct SeriesState;
// The cheap half of computeEphemeris: everything from the series state (see series_state.h).
SkyEphemeris assembleEphemeris(const TimeScales& time, const Observer& observer, const SeriesState& series);

enum class Body { Sun, Moon, Mercury, Venus, Mars, Jupiter, Saturn };

struct ApparentPlace {
  double rightAscensionRad = 0.0;  // true equator and equinox of date
  double declinationRad = 0.0;
  double distanceKm = 0.0;
  double phaseAngleRad = 0.0;               // moon only
  double brightLimbPositionAngleRad = 0.0;  // moon only, from north through east
};

// Apparent geocentric place at TT Julian date jdTt, as the Astronomical Almanac and Meeus'
// examples tabulate it (light time, aberration, precession-nutation; no parallax).
ApparentPlace apparentGeocentricPlace(Body body, double jdTt);

// Position angle of the moon's bright limb from north through east (Meeus eq. 48.5), radians.
double brightLimbPositionAngle(double moonRa, double moonDec, double sunRa, double sunDec);

// A star seen from the observer: airless and refracted altitude, azimuth: the renderer's recipe
// plus the gravitational deflection of light by the sun (SOFA eraLd, as in eraAtci13).
BodyPosition starPosition(const Star& star, const SkyEphemeris& sky);

// Apparent direction (ENU) of a J2000 unit vector, with aberration.
Vec3 j2000DirectionToEnu(Vec3 directionJ2000, const SkyEphemeris& sky);

}  // namespace skyig::ephemeris
