#pragma once
// Branch-free sine and cosine for the series (tens of thousands per frame): Cody-Waite reduction
// to [-pi/4, pi/4] and Taylor polynomials to degree 15/16, truncation error < 5e-17. Arguments up
// to 1e7 rad lose < 2e-9 rad in the reduction (the series' largest arguments are ~1e5 rad).
#include <cstdint>

namespace skyig::ephemeris {

inline void fastSinCos(double x, double& s, double& c) {
  constexpr double kTwoOverPi = 0.63661977236758134308;
  // pi/2 split in three parts (Cody & Waite), each exact when multiplied by q < 2^27.
  constexpr double kP1 = 1.5707963267341256e+00;
  constexpr double kP2 = 6.0771005065061922e-11;
  constexpr double kP3 = 2.0222662487959506e-21;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  const double qd = (x * kTwoOverPi + kRound) - kRound;
  const double r = ((x - qd * kP1) - qd * kP2) - qd * kP3;
  const double r2 = r * r;
  const double sr =
      r * (1.0 + r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800 +
          r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0))))))));
  const double cr =
      1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 +
          r2 * (1.0 / 479001600.0 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0))))))));
  const auto q = static_cast<std::int64_t>(qd);
  const bool swap = (q & 1) != 0;
  const double ss = swap ? cr : sr;
  const double cc = swap ? sr : cr;
  s = (q & 2) != 0 ? -ss : ss;
  c = ((q + 1) & 2) != 0 ? -cc : cc;
}

}  // namespace skyig::ephemeris
