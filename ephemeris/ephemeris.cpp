#include "ephemeris/ephemeris.h"

#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ephemeris/earth_orientation.h"
#include "ephemeris/night_irradiance.h"
#include "ephemeris/planet_magnitude.h"
#include "ephemeris/refraction.h"
#include "ephemeris/series_state.h"
#include "ephemeris/vsop87.h"

namespace skyig::ephemeris {

namespace {
constexpr double kEarthRotationRadPerS = 7.292115e-5;  // IERS, nominal
constexpr double kKmPerAuPerDayToKmS = kAuKm / 86400.0;
}  // namespace

void checkObserver(const Observer& o) {
  const double latDeg = o.latitudeRad / kDegToRad, lonDeg = o.longitudeRad / kDegToRad;
  if (!(std::isfinite(o.latitudeRad) && std::fabs(latDeg) <= 90.0))
    throw std::invalid_argument("latitude " + std::to_string(latDeg) + " degrees is outside [-90, 90]");
  if (!std::isfinite(o.longitudeRad))
    throw std::invalid_argument("longitude " + std::to_string(lonDeg) + " degrees is not finite");
  if (!(std::isfinite(o.heightM) && o.heightM >= -1000.0 && o.heightM <= 100000.0))
    throw std::invalid_argument("height " + std::to_string(o.heightM) + " m is outside [-1000, 100000]");
  if (!(std::isfinite(o.pressureHpa) && o.pressureHpa >= 0.0 && o.pressureHpa < 2000.0))
    throw std::invalid_argument("pressure " + std::to_string(o.pressureHpa) + " hPa is outside [0, 2000)");
  if (!(std::isfinite(o.temperatureC) && o.temperatureC > -100.0 && o.temperatureC < 100.0))
    throw std::invalid_argument("temperature " + std::to_string(o.temperatureC) + " C is outside (-100, 100)");
}

namespace {

// Everything that turns a geocentric geometric J2000 vector into an apparent topocentric one.
struct Frame {
  Mat3 npb;            // J2000 -> true of date
  Mat3 todToEnu;       // true of date -> ENU
  Vec3 observerJ2000;  // km, geocentric
  Vec3 beta;           // observer velocity / c
  double latitude = 0.0;
  double lastRad = 0.0;  // local apparent sidereal time
  Observer observer;
};

Vec3 aberrate(Vec3 u, Vec3 beta) {
  // First-order aberration (Meeus ch. 23 in vector form); the neglected (v/c)^2 terms are below
  // 0.002 arcsec.
  return normalized(u + beta - dot(u, beta) * u);
}

BodyPosition apparent(const Frame& f, Vec3 geocentricJ2000Km) {
  const Vec3 topo = geocentricJ2000Km - f.observerJ2000;
  const double distance = norm(topo);
  const Vec3 u = f.npb * aberrate((1.0 / distance) * topo, f.beta);  // true equator of date
  BodyPosition p;
  p.distanceKm = distance;
  p.rightAscensionRad = wrapTwoPi(std::atan2(u.y, u.x));
  p.declinationRad = std::asin(std::clamp(u.z, -1.0, 1.0));
  p.enu = f.todToEnu * u;
  p.azimuthRad = wrapTwoPi(std::atan2(p.enu.x, p.enu.y));
  p.altitudeRad = std::atan2(p.enu.z, std::hypot(p.enu.x, p.enu.y));
  p.altitudeRefractedRad =
      p.altitudeRad + refractionSaemundsson(p.altitudeRad, f.observer.pressureHpa, f.observer.temperatureC);
  return p;
}

// Bright limb measured from the zenith: position angle (Meeus eq. 48.5) minus the parallactic
// angle (Meeus eq. 14.1).
double brightLimbFromZenith(const BodyPosition& moon, const BodyPosition& sun, const Frame& f) {
  const double chi = brightLimbPositionAngle(moon.rightAscensionRad, moon.declinationRad, sun.rightAscensionRad,
                                             sun.declinationRad);
  const double h = f.lastRad - moon.rightAscensionRad;
  const double q = std::atan2(std::sin(h), std::tan(f.latitude) * std::cos(moon.declinationRad) -
                                               std::sin(moon.declinationRad) * std::cos(h));
  return wrapTwoPi(chi - q);
}

// Sub-observer latitude of Saturn's ring plane (Meeus eq. 45.3), from the geocentric J2000
// equatorial vector; ring-pole elements referred to the mean ecliptic and equinox of date.
double saturnRingTilt(Vec3 geocentricJ2000, double jdTt) {
  const double t = (jdTt - 2451545.0) / 36525.0;
  const double eps0 = 84381.406 * kArcsecToRad;
  const Vec3 ecl = rotX(eps0) * geocentricJ2000;  // equator -> ecliptic J2000
  const double lambda = std::atan2(ecl.y, ecl.x) + (5028.796195 * t) * kArcsecToRad;  // to equinox of date
  const double beta = std::atan2(ecl.z, std::hypot(ecl.x, ecl.y));
  const double i = (28.075216 - 0.012998 * t + 0.000004 * t * t) * kDegToRad;
  const double node = (169.508470 + 1.394681 * t + 0.000412 * t * t) * kDegToRad;
  return std::asin(std::sin(i) * std::cos(beta) * std::sin(lambda - node) - std::cos(i) * std::sin(beta));
}

constexpr const char* kPlanetNames[5] = {"Mercury", "Venus", "Mars", "Jupiter", "Saturn"};
constexpr Planet kPlanets[5] = {Planet::Mercury, Planet::Venus, Planet::Mars, Planet::Jupiter, Planet::Saturn};
}  // namespace

namespace {
// geocentric: the observer sits at the earth's centre (no parallax, no diurnal aberration).
SkyEphemeris assemble(const TimeScales& time, const Observer& observer, const SeriesState& series, bool geocentric) {
  SkyEphemeris sky;
  sky.observer = observer;
  sky.time = time;
  const double jd = sky.time.jdTt;  // TDB - TT < 2 ms is neglected
  const EarthOrientation eo = earthOrientation(jd, sky.time.jdUt1, series.nutation);
  sky.gmstRad = eo.gmst;
  sky.gastRad = eo.gast;

  // Observer: WGS84 geodetic -> earth-fixed (polar motion neglected) -> true of date -> J2000.
  Frame f;
  f.observer = observer;
  f.npb = eo.npb;
  f.latitude = observer.latitudeRad;
  f.lastRad = wrapTwoPi(eo.gast + observer.longitudeRad);
  double x = 0.0, y = 0.0, z = 0.0;
  GeographicLib::Geocentric::WGS84().Forward(observer.latitudeRad / kDegToRad, observer.longitudeRad / kDegToRad,
                                             observer.heightM, x, y, z);
  const Vec3 ecefKm{x / 1000.0, y / 1000.0, z / 1000.0};
  const Mat3 todToEcef = rotZ(eo.gast);
  const Vec3 observerTod = geocentric ? Vec3{} : transposed(todToEcef) * ecefKm;
  const Vec3 observerVelTod{-kEarthRotationRadPerS * observerTod.y, kEarthRotationRadPerS * observerTod.x, 0.0};
  const Mat3 j2000ToTod = eo.npb;
  const Mat3 todToJ2000 = transposed(j2000ToTod);
  f.observerJ2000 = todToJ2000 * observerTod;
  const double sl = std::sin(observer.latitudeRad), cl = std::cos(observer.latitudeRad);
  const double so = std::sin(observer.longitudeRad), co = std::cos(observer.longitudeRad);
  const Mat3 ecefToEnu{{-so, co, 0.0, -sl * co, -sl * so, cl, cl * co, cl * so, sl}};
  f.todToEnu = ecefToEnu * todToEcef;

  const StateVector& earth = series.earth;
  f.beta = (1.0 / kLightKmPerS) * (kKmPerAuPerDayToKmS * earth.velocity + todToJ2000 * observerVelTod);
  sky.aberrationJ2000 = f.beta;
  sky.earthHeliocentricAu = earth.position;
  sky.j2000ToEnu = f.todToEnu * f.npb;
  sky.j2000ToTrueOfDate = f.npb;

  // Sun: heliocentric earth reversed; light time does not move the sun in this frame.
  const Vec3 sunGeo = -kAuKm * earth.position;
  static_cast<BodyPosition&>(sky.sun) = apparent(f, sunGeo);
  sky.sun.angularRadiusRad = std::asin(kSunRadiusKm / sky.sun.distanceKm);
  sky.sun.irradianceWm2 = irradianceFromMagnitude(-26.74 + 5.0 * std::log10(sky.sun.distanceKm / kAuKm));

  // Moon at the time its light left (the light time varies by 0.07 s: < 0.04 arcsec). The
  // astrometric vector is barycentric moon(t - tau) - earth(t) = geocentric moon(t - tau) -
  // tau * earth velocity; that term cancels most of the annual aberration, as it should for a
  // body that travels with the earth.
  const Vec3 moonGeo = series.moonGeocentricKm;
  const Vec3 moonAstrometric = moonGeo - (kMoonLightTimeDays * kAuKm) * earth.velocity;
  static_cast<BodyPosition&>(sky.moon) = apparent(f, moonAstrometric);
  sky.moon.distanceKm = norm(moonGeo - f.observerJ2000);  // geometric, not the aberration proxy
  const Vec3 moonToSun = sunGeo - moonGeo, moonToObserver = f.observerJ2000 - moonGeo;
  sky.moon.phaseAngleRad = angleBetween(moonToSun, moonToObserver);
  sky.moon.illuminatedFraction = 0.5 * (1.0 + std::cos(sky.moon.phaseAngleRad));
  sky.moon.brightLimbAngleRad = brightLimbFromZenith(sky.moon, sky.sun, f);
  sky.moon.angularRadiusRad = std::asin(kMoonRadiusKm / sky.moon.distanceKm);
  sky.moon.irradianceWm2 = moonIrradiance(sky.moon.phaseAngleRad, sky.moon.distanceKm, norm(moonToSun));

  for (int i = 0; i < 5; ++i) {
    const StateVector& p = series.planets[static_cast<std::size_t>(i)];
    // Light time by linear extrapolation of the heliocentric motion (two iterations; the
    // neglected acceleration moves Mercury by < 0.05 arcsec).
    Vec3 helio = p.position;
    for (int it = 0; it < 2; ++it) {
      const double tau = norm(helio - earth.position) * kLightTimeAuDays;
      helio = p.position - tau * p.velocity;
    }
    const Vec3 geo = helio - earth.position;
    PlanetState& ps = sky.planets[static_cast<std::size_t>(i)];
    static_cast<BodyPosition&>(ps) = apparent(f, kAuKm * geo);
    ps.name = kPlanetNames[i];
    ps.phaseAngleRad = angleBetween(-helio, -geo);
    ps.illuminatedFraction = 0.5 * (1.0 + std::cos(ps.phaseAngleRad));
    const double tilt = i == 4 ? saturnRingTilt(geo, jd) : 0.0;
    ps.magnitude = planetMagnitude(kPlanets[i], norm(helio), norm(geo), ps.phaseAngleRad, tilt);
    ps.irradianceWm2 = irradianceFromMagnitude(ps.magnitude);
  }
  return sky;
}
}  // namespace

SkyEphemeris assembleEphemeris(const TimeScales& time, const Observer& observer, const SeriesState& series) {
  return assemble(time, observer, series, false);
}

SkyEphemeris computeEphemeris(const UtcTime& utc, const Observer& observer, const EphemerisOptions& options) {
  checkObserver(observer);
  const TimeScales time = timeScales(utc, options.ttMinusUtcS, options.dut1S);
  return assemble(time, observer, evaluateSeries(time.jdTt), false);
}

ApparentPlace apparentGeocentricPlace(Body body, double jdTt) {
  TimeScales time;
  time.jdTt = jdTt;
  time.jdUt1 = jdTt;
  const SkyEphemeris sky = assemble(time, Observer{}, evaluateSeries(jdTt), true);
  const BodyPosition* p = &sky.sun;
  switch (body) {
    case Body::Sun: p = &sky.sun; break;
    case Body::Moon: p = &sky.moon; break;
    case Body::Mercury: p = &sky.planets[0]; break;
    case Body::Venus: p = &sky.planets[1]; break;
    case Body::Mars: p = &sky.planets[2]; break;
    case Body::Jupiter: p = &sky.planets[3]; break;
    case Body::Saturn: p = &sky.planets[4]; break;
  }
  ApparentPlace place{p->rightAscensionRad, p->declinationRad, p->distanceKm, 0.0, 0.0};
  if (body == Body::Moon) {
    place.phaseAngleRad = sky.moon.phaseAngleRad;
    place.brightLimbPositionAngleRad =
        brightLimbPositionAngle(sky.moon.rightAscensionRad, sky.moon.declinationRad, sky.sun.rightAscensionRad,
                                sky.sun.declinationRad);
  }
  return place;
}

double brightLimbPositionAngle(double moonRa, double moonDec, double sunRa, double sunDec) {
  // Meeus eq. 48.5
  const double da = sunRa - moonRa;
  return wrapTwoPi(std::atan2(std::cos(sunDec) * std::sin(da),
                              std::sin(sunDec) * std::cos(moonDec) - std::cos(sunDec) * std::sin(moonDec) * std::cos(da)));
}


Vec3 j2000DirectionToEnu(Vec3 directionJ2000, const SkyEphemeris& sky) {
  return sky.j2000ToEnu * aberrate(directionJ2000, sky.aberrationJ2000);
}

BodyPosition starPosition(const Star& star, const SkyEphemeris& sky) {
  BodyPosition p;
  Vec3 u = starDirectionAt(star, sky.time.jdTt);
  // Light deflection by the sun (SOFA eraLd with the star at infinity): p + (2GM/c^2 r)
  // (e - (p.e) p) / (1 + p.e), e the unit vector from the sun to the observer.
  constexpr double kSunSchwarzschildRadiusAu = 1.97412574336e-8;
  const double r = norm(sky.earthHeliocentricAu);
  const Vec3 e = (1.0 / r) * sky.earthHeliocentricAu;
  const double pe = dot(u, e);
  if (pe > -0.99999)  // not behind the sun's centre
    u = normalized(u + (kSunSchwarzschildRadiusAu / r / (1.0 + pe)) * (e - pe * u));
  p.enu = j2000DirectionToEnu(u, sky);  // aberration, then precession-nutation and rotation
  p.azimuthRad = wrapTwoPi(std::atan2(p.enu.x, p.enu.y));
  p.altitudeRad = std::atan2(p.enu.z, std::hypot(p.enu.x, p.enu.y));
  p.altitudeRefractedRad = p.altitudeRad + refractionSaemundsson(p.altitudeRad, sky.observer.pressureHpa,
                                                                 sky.observer.temperatureC);
  p.distanceKm = std::numeric_limits<double>::infinity();
  const Vec3 tod = sky.j2000ToTrueOfDate * aberrate(u, sky.aberrationJ2000);
  p.rightAscensionRad = wrapTwoPi(std::atan2(tod.y, tod.x));
  p.declinationRad = std::asin(std::clamp(tod.z, -1.0, 1.0));
  return p;
}

}  // namespace skyig::ephemeris
