#include "ephemeris/elp82b.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "ephemeris/fast_sincos.h"
#include "ephemeris/vsop87.h"

namespace skyig::ephemeris {

namespace {
struct ElpTerm {
  unsigned char coordinate;  // 0 = longitude V, 1 = latitude U (arcsec), 2 = distance r (km)
  unsigned char power;       // power of t
  double a;                  // A t^power sin(phase + sum_j n_j F_j(t))
  double phase;
  signed char n[17];
};
#include "ephemeris/data/elp82b_truncated.inc"

constexpr int kArguments = 17;
constexpr std::size_t kMaxTable = 512;

// Mean longitude of the moon referred to the inertial J2000 departure point (ELP 2000-82B W1,
// with the DE200/LE200 corrections), radians and t in Julian centuries.
constexpr double kW1[5] = {(218.0 + 18.0 / 60.0 + 59.95571 / 3600.0) * kDegToRad,
                           1732559343.73604 * kArcsecToRad, -5.8883 * kArcsecToRad,
                           0.006604 * kArcsecToRad, -0.00003169 * kArcsecToRad};
constexpr double kA0OverAth = 384747.9806448954 / 384747.9806743165;

// Each term's argument is an integer combination of 17 fundamental arguments, so instead of one
// sine per term the evaluation raises e^{i F_j} to the needed integer powers once (by repeated
// multiplication) and forms each term's e^{i arg} as a product of a few of them.
struct PreparedTerm {
  unsigned char coordinate, power, factorCount;
  double re, im;  // A e^{i phase}
  std::array<std::uint16_t, kArguments> factors;
};
struct Prepared {
  std::array<int, kArguments> maxPower{};  // largest |n_j|
  std::array<int, kArguments> offset{};    // index of e^{i 0 F_j} in the table of powers
  int tableSize = 0;
  std::vector<PreparedTerm> terms;
};

const Prepared& prepared() {
  static const Prepared kPrepared = [] {
    Prepared p;
    for (const ElpTerm& t : kElpTerms)
      for (int j = 0; j < kArguments; ++j) p.maxPower[j] = std::max(p.maxPower[j], std::abs(static_cast<int>(t.n[j])));
    for (int j = 0; j < kArguments; ++j) {
      p.offset[j] = p.tableSize + p.maxPower[j];
      p.tableSize += 2 * p.maxPower[j] + 1;
    }
    if (p.tableSize > static_cast<int>(kMaxTable)) throw std::logic_error("ELP table needs more than 512 powers");
    for (const ElpTerm& t : kElpTerms) {
      PreparedTerm q{t.coordinate, t.power, 0, t.a * std::cos(t.phase), t.a * std::sin(t.phase), {}};
      for (int j = 0; j < kArguments; ++j)
        if (t.n[j] != 0) q.factors[q.factorCount++] = static_cast<std::uint16_t>(p.offset[j] + t.n[j]);
      p.terms.push_back(q);
    }
    return p;
  }();
  return kPrepared;
}
}  // namespace

Vec3 elp82bGeocentric(double jdTdb) {
  const double t = (jdTdb - 2451545.0) / 36525.0;
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  const Prepared& series = prepared();
  // Powers e^{i n F_j(t)}, n = -max..max, for every fundamental argument.
  std::array<double, kMaxTable> re{}, im{};  // series.tableSize <= kMaxTable, checked by prepared()
  for (int j = 0; j < kArguments; ++j) {
    const double* c = kElpArguments[j];
    double s1 = 0.0, c1 = 0.0;
    fastSinCos(c[0] + t * c[1] + t2 * c[2] + t3 * c[3] + t4 * c[4], s1, c1);
    const auto o = static_cast<std::size_t>(series.offset[j]);
    re[o] = 1.0;
    im[o] = 0.0;
    for (std::size_t n = 1; n <= static_cast<std::size_t>(series.maxPower[j]); ++n) {
      re[o + n] = re[o + n - 1] * c1 - im[o + n - 1] * s1;
      im[o + n] = re[o + n - 1] * s1 + im[o + n - 1] * c1;
      re[o - n] = re[o + n];
      im[o - n] = -im[o + n];
    }
  }
  double sum[3][3] = {};
  for (const PreparedTerm& term : series.terms) {
    double zr = term.re, zi = term.im;
    for (unsigned char f = 0; f < term.factorCount; ++f) {
      const std::size_t k = term.factors[f];
      const double nr = zr * re[k] - zi * im[k];
      zi = zr * im[k] + zi * re[k];
      zr = nr;
    }
    sum[term.coordinate][term.power] += zi;  // A sin(arg)
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
