#include "ephemeris/elp82b.h"

#include <cmath>

#include "ephemeris/fast_sincos.h"
#include "ephemeris/vsop87.h"

namespace skyig::ephemeris {

namespace {
struct ElpTerm {
  unsigned char coordinate;  // 0 = longitude V, 1 = latitude U (arcsec), 2 = distance r (km)
  unsigned char power;       // power of t
  double a;                  // A t^power sin(c0 + c1 t + c2 t^2 + c3 t^3 + c4 t^4)
  double c0, c1, c2, c3, c4;
};
#include "ephemeris/data/elp82b_truncated.inc"

// Mean longitude of the moon referred to the inertial J2000 departure point (ELP 2000-82B W1,
// with the DE200/LE200 corrections), radians and t in Julian centuries.
constexpr double kW1[5] = {(218.0 + 18.0 / 60.0 + 59.95571 / 3600.0) * kDegToRad,
                           1732559343.73604 * kArcsecToRad, -5.8883 * kArcsecToRad,
                           0.006604 * kArcsecToRad, -0.00003169 * kArcsecToRad};
constexpr double kA0OverAth = 384747.9806448954 / 384747.9806743165;
}  // namespace

Vec3 elp82bGeocentric(double jdTdb) {
  const double t = (jdTdb - 2451545.0) / 36525.0;
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  double sum[3][3] = {};
  for (const ElpTerm& term : kElpTerms) {
    double s = 0.0, c = 0.0;
    fastSinCos(term.c0 + term.c1 * t + term.c2 * t2 + term.c3 * t3 + term.c4 * t4, s, c);
    sum[term.coordinate][term.power] += term.a * s;
  }
  const double v = (sum[0][0] + t * (sum[0][1] + t * sum[0][2])) * kArcsecToRad + kW1[0] + kW1[1] * t +
                   kW1[2] * t2 + kW1[3] * t3 + kW1[4] * t4;
  const double u = (sum[1][0] + t * (sum[1][1] + t * sum[1][2])) * kArcsecToRad;
  const double r = (sum[2][0] + t * (sum[2][1] + t * sum[2][2])) * kA0OverAth;
  const double x0 = r * std::cos(u) * std::cos(v), y0 = r * std::cos(u) * std::sin(v), z0 = r * std::sin(u);
  // Laskar's precession of the ecliptic, mean ecliptic of date -> J2000 (ELP 2000-82B notice).
  const double p = (0.10180391e-4 + t * (0.47020439e-6 + t * (-0.5417367e-9 + t * (-0.2507948e-11 + t * 0.463486e-14)))) * t;
  const double q = (-0.113469002e-3 + t * (0.12372674e-6 + t * (0.1265417e-8 + t * (-0.1371808e-11 + t * -0.320334e-14)))) * t;
  const double ra = 2.0 * std::sqrt(1.0 - p * p - q * q);
  const double pq = 2.0 * p * q, p2 = 1.0 - 2.0 * p * p, q2 = 1.0 - 2.0 * q * q;
  const Vec3 ecl{p2 * x0 + pq * y0 + p * ra * z0, pq * x0 + q2 * y0 - q * ra * z0,
                 -p * ra * x0 + q * ra * y0 + (p2 + q2 - 1.0) * z0};
  return vsopEclipticToFk5() * ecl;
}

}  // namespace skyig::ephemeris
