#include "ephemeris/earth_orientation.h"

#include <cmath>
#include <iterator>

#include "ephemeris/fast_sincos.h"

namespace skyig::ephemeris {

namespace {
constexpr double kJ2000 = 2451545.0;
constexpr double kDaysPerCentury = 36525.0;

struct NutationTerm {
  int nl, nlp, nf, nd, nom;
  double ps, pst, pc, ec, ect, es;
};
constexpr NutationTerm kNutation2000B[] = {
#include "ephemeris/data/iau2000b_nutation.inc"
};

double centuries(double jdTt) { return (jdTt - kJ2000) / kDaysPerCentury; }
}  // namespace

Nutation nutation2000B(double jdTt) {
  const double t = centuries(jdTt);
  constexpr double kTurnAs = 1296000.0;
  // Delaunay arguments, Simon et al. (1994), as IAU 2000B uses them (linear in t).
  const double el = std::fmod(485868.249036 + 1717915923.2178 * t, kTurnAs) * kArcsecToRad;
  const double elp = std::fmod(1287104.79305 + 129596581.0481 * t, kTurnAs) * kArcsecToRad;
  const double f = std::fmod(335779.526232 + 1739527262.8478 * t, kTurnAs) * kArcsecToRad;
  const double d = std::fmod(1072260.70369 + 1602961601.2090 * t, kTurnAs) * kArcsecToRad;
  const double om = std::fmod(450160.398036 - 6962890.5431 * t, kTurnAs) * kArcsecToRad;
  double dp = 0.0, de = 0.0;
  for (auto it = std::rbegin(kNutation2000B); it != std::rend(kNutation2000B); ++it) {  // small first
    const double arg = it->nl * el + it->nlp * elp + it->nf * f + it->nd * d + it->nom * om;
    double s = 0.0, c = 0.0;
    fastSinCos(arg, s, c);
    dp += (it->ps + it->pst * t) * s + it->pc * c;
    de += (it->ec + it->ect * t) * c + it->es * s;
  }
  constexpr double kUnit = kArcsecToRad / 1e7;  // 0.1 microarcsec
  // Fixed offsets in lieu of the planetary terms (-0.135 mas, +0.388 mas).
  return {dp * kUnit - 0.135e-3 * kArcsecToRad, de * kUnit + 0.388e-3 * kArcsecToRad};
}

double meanObliquity2006(double jdTt) {
  const double t = centuries(jdTt);
  return (84381.406 + t * (-46.836769 + t * (-0.0001831 + t * (0.00200340 + t * (-0.000000576 - 0.0000000434 * t))))) *
         kArcsecToRad;
}

void precessionAngles2006(double jdTt, double& gamb, double& phib, double& psib) {
  const double t = centuries(jdTt);
  gamb = (-0.052928 + t * (10.556378 + t * (0.4932044 + t * (-0.00031238 + t * (-0.000002788 + 0.0000000260 * t))))) *
         kArcsecToRad;
  phib = (84381.412819 + t * (-46.811016 + t * (0.0511268 + t * (0.00053289 + t * (-0.000000440 - 0.0000000176 * t))))) *
         kArcsecToRad;
  psib = (-0.041775 + t * (5038.481484 + t * (1.5584175 + t * (-0.00018522 + t * (-0.000026452 - 0.0000000148 * t))))) *
         kArcsecToRad;
}

double earthRotationAngle(double jdUt1) {
  // IERS Conventions 2010 eq. 5.15, split to keep the fraction of the day exact.
  const double du = jdUt1 - kJ2000;
  const double fraction = std::fmod(jdUt1, 1.0);
  return wrapTwoPi(kTwoPi * (fraction + 0.7790572732640 + 0.00273781191135448 * du));
}

EarthOrientation earthOrientation(double jdTt, double jdUt1) {
  return earthOrientation(jdTt, jdUt1, nutation2000B(jdTt));
}

EarthOrientation earthOrientation(double jdTt, double jdUt1, const Nutation& nutation) {
  EarthOrientation eo;
  const double t = centuries(jdTt);
  eo.nutation = nutation;
  eo.epsA = meanObliquity2006(jdTt);
  double gamb = 0.0, phib = 0.0, psib = 0.0;
  precessionAngles2006(jdTt, gamb, phib, psib);
  // NPB = R1(-(epsA + deps)) R3(-(psib + dpsi)) R1(phib) R3(gamb)  (IERS Conventions 2010 eq. 5.40)
  eo.npb = rotX(-(eo.epsA + eo.nutation.deps)) * rotZ(-(psib + eo.nutation.dpsi)) * rotX(phib) * rotZ(gamb);
  // GMST, IAU 2006 (IERS Conventions 2010 eq. 5.32).
  const double poly = (0.014506 + t * (4612.156534 + t * (1.3915817 + t * (-0.00000044 + t * (-0.000029956 - 0.0000000368 * t))))) *
                      kArcsecToRad;
  eo.gmst = wrapTwoPi(earthRotationAngle(jdUt1) + poly);
  // Equation of the equinoxes: dpsi cos(epsA) plus the largest complementary terms
  // (IERS Conventions 2010 table 5.2e; each omitted term is below 10 microarcseconds).
  const double om = (450160.398036 - 6962890.5431 * t) * kArcsecToRad;
  const double f = (335779.526232 + 1739527262.8478 * t) * kArcsecToRad;
  const double d = (1072260.70369 + 1602961601.2090 * t) * kArcsecToRad;
  const double ct = (2640.96e-6 * std::sin(om) + 63.52e-6 * std::sin(2.0 * om) +
                     11.75e-6 * std::sin(2.0 * f - 2.0 * d + 3.0 * om) +
                     11.21e-6 * std::sin(2.0 * f - 2.0 * d + om)) * kArcsecToRad;
  eo.gast = wrapTwoPi(eo.gmst + eo.nutation.dpsi * std::cos(eo.epsA) + ct);
  return eo;
}

}  // namespace skyig::ephemeris
