#include "ephemeris/low_precision_sun.h"

#include <cmath>
#include <numbers>

namespace skyig::ephemeris {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

double wrapTwoPi(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}
}  // namespace

EquatorialPosition lowPrecisionSunEquatorial(double jd) {
  const double t = (jd - 2451545.0) / 36525.0;  // Julian centuries from J2000.0 (eq. 25.1)
  const double l0 = 280.46646 + t * (36000.76983 + t * 0.0003032);             // eq. 25.2
  const double m = (357.52911 + t * (35999.05029 - t * 0.0001537)) * kDeg;     // eq. 25.3
  const double e = 0.016708634 - t * (0.000042037 + t * 0.0000001267);        // eq. 25.4
  const double c = (1.914602 - t * (0.004817 + t * 0.000014)) * std::sin(m) +  // equation of centre
                   (0.019993 - t * 0.000101) * std::sin(2.0 * m) + 0.000289 * std::sin(3.0 * m);
  const double trueLongitude = l0 + c;
  const double trueAnomaly = m + c * kDeg;
  const double radius = 1.000001018 * (1.0 - e * e) / (1.0 + e * std::cos(trueAnomaly));  // eq. 25.5
  // Nutation and aberration folded into the apparent longitude (p. 164).
  const double omega = (125.04 - 1934.136 * t) * kDeg;
  const double lambda = (trueLongitude - 0.00569 - 0.00478 * std::sin(omega)) * kDeg;
  // Mean obliquity (eq. 22.2) corrected for nutation as on p. 165.
  const double eps0 = 23.0 + 26.0 / 60.0 + 21.448 / 3600.0 -
                      t * (46.8150 + t * (0.00059 - t * 0.001813)) / 3600.0;
  const double eps = (eps0 + 0.00256 * std::cos(omega)) * kDeg;
  EquatorialPosition p;
  p.rightAscension = wrapTwoPi(std::atan2(std::cos(eps) * std::sin(lambda), std::cos(lambda)));  // eq. 25.6
  p.declination = std::asin(std::sin(eps) * std::sin(lambda));                                  // eq. 25.7
  p.distanceAu = radius;
  return p;
}

double greenwichMeanSiderealTime(double jdUt) {
  const double d = jdUt - 2451545.0;
  const double t = d / 36525.0;
  const double deg = 280.46061837 + 360.98564736629 * d + t * t * (0.000387933 - t / 38710000.0);
  return wrapTwoPi(deg * kDeg);
}

HorizontalPosition equatorialToHorizontal(const EquatorialPosition& eq, double gmst,
                                          double latitude, double longitude) {
  const double hourAngle = gmst + longitude - eq.rightAscension;
  const double sinAlt = std::sin(latitude) * std::sin(eq.declination) +
                        std::cos(latitude) * std::cos(eq.declination) * std::cos(hourAngle);
  // Meeus measures azimuth from the south; adding pi gives it from the north through east.
  const double azSouth = std::atan2(std::sin(hourAngle), std::cos(hourAngle) * std::sin(latitude) -
                                                              std::tan(eq.declination) * std::cos(latitude));
  HorizontalPosition h;
  h.altitude = std::asin(std::fmax(-1.0, std::fmin(1.0, sinAlt)));
  h.azimuth = wrapTwoPi(azSouth + std::numbers::pi);
  return h;
}

HorizontalPosition lowPrecisionSunHorizontal(const UtcTime& utc, double latitude, double longitude) {
  const double jd = julianDateUtc(utc);
  return equatorialToHorizontal(lowPrecisionSunEquatorial(jd), greenwichMeanSiderealTime(jd),
                                latitude, longitude);
}

}  // namespace skyig::ephemeris
