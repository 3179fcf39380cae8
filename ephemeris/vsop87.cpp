#include "ephemeris/vsop87.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>
#include <cstddef>
#include <iterator>
#include <span>
#include <stdexcept>

#include "ephemeris/fast_sincos.h"

namespace skyig::ephemeris {

namespace {
struct VsopTerm {
  unsigned char coordinate;  // 0 = L, 1 = B, 2 = R
  unsigned char power;       // power of T
  double a, b, c;            // A T^power cos(B + C T)
};
#include "ephemeris/data/vsop87b_truncated.inc"

std::span<const VsopTerm> table(VsopBody body) {
  switch (body) {
    case VsopBody::Earth: return kVsopEarth;
    case VsopBody::Mercury: return kVsopMercury;
    case VsopBody::Venus: return kVsopVenus;
    case VsopBody::Mars: return kVsopMars;
    case VsopBody::Jupiter: return kVsopJupiter;
    case VsopBody::Saturn: return kVsopSaturn;
  }
  return kVsopEarth;
}

// The same series regrouped for speed: many terms of L, B, R and of different powers of T share
// a frequency C, so sin/cos(C T) is evaluated once per distinct frequency and each term uses
// A cos(B + C T) = (A cos B) cos(C T) - (A sin B) sin(C T). 1848 terms have 812 frequencies.
struct PreparedTerm {
  std::uint16_t frequency;  // index into PreparedSeries::frequencies
  unsigned char coordinate, power;
  double aCosB, aSinB, c;
};
struct PreparedSeries {
  std::vector<double> frequencies;
  std::vector<PreparedTerm> terms;
};

constexpr std::size_t kMaxFrequencies = 512;

PreparedSeries prepare(std::span<const VsopTerm> series) {
  PreparedSeries p;
  for (const VsopTerm& t : series) {
    std::size_t k = 0;
    while (k < p.frequencies.size() && p.frequencies[k] != t.c) ++k;
    if (k == p.frequencies.size()) {
      if (k == kMaxFrequencies) throw std::logic_error("VSOP87 table has more than 512 distinct frequencies");
      p.frequencies.push_back(t.c);
    }
    p.terms.push_back({static_cast<std::uint16_t>(k), t.coordinate, t.power, t.a * std::cos(t.b), t.a * std::sin(t.b), t.c});
  }
  return p;
}

const PreparedSeries& prepared(VsopBody body) {
  static const std::array<PreparedSeries, 6> kPrepared = {
      prepare(table(VsopBody::Earth)), prepare(table(VsopBody::Mercury)), prepare(table(VsopBody::Venus)),
      prepare(table(VsopBody::Mars)),  prepare(table(VsopBody::Jupiter)), prepare(table(VsopBody::Saturn))};
  return kPrepared[static_cast<std::size_t>(body)];
}
}  // namespace

const Mat3& vsopEclipticToFk5() {
  // VSOP87 notice (Bretagnon & Francou): dynamical ecliptic J2000 -> FK5 equator J2000.
  static const Mat3 kM{{1.000000000000, 0.000000440360, -0.000000190919,  //
                        -0.000000479966, 0.917482137087, -0.397776982902,   //
                        0.000000000000, 0.397776982902, 0.917482137087}};
  return kM;
}

StateVector vsop87Heliocentric(VsopBody body, double jdTdb) {
  const double t = (jdTdb - 2451545.0) / 365250.0;  // Julian millennia
  // sum[coordinate][power] and its time derivative per millennium.
  const PreparedSeries& series = prepared(body);
  double sinCt[kMaxFrequencies], cosCt[kMaxFrequencies];
  const std::size_t n = series.frequencies.size();  // <= kMaxFrequencies, checked by prepare()
  for (std::size_t k = 0; k < n; ++k) fastSinCos(series.frequencies[k] * t, sinCt[k], cosCt[k]);
  double sum[3][6] = {}, dsum[3][6] = {};
  for (const PreparedTerm& term : series.terms) {
    const double sc = sinCt[term.frequency], cc = cosCt[term.frequency];
    sum[term.coordinate][term.power] += term.aCosB * cc - term.aSinB * sc;               // A cos(B + C T)
    dsum[term.coordinate][term.power] -= term.c * (term.aSinB * cc + term.aCosB * sc);  // d/dT
  }
  double v[3] = {}, dv[3] = {};
  for (int k = 0; k < 3; ++k) {
    double tp = 1.0, tpm1 = 0.0;  // t^p and p t^(p-1)
    for (int p = 0; p < 6; ++p) {
      v[k] += sum[k][p] * tp;
      dv[k] += dsum[k][p] * tp + sum[k][p] * tpm1;
      tpm1 = (p + 1) * tp;
      tp *= t;
    }
  }
  const double l = v[0], b = v[1], r = v[2];
  const double cl = std::cos(l), sl = std::sin(l), cb = std::cos(b), sb = std::sin(b);
  const Vec3 pos{r * cb * cl, r * cb * sl, r * sb};
  constexpr double kPerDay = 1.0 / 365250.0;
  const double dl = dv[0] * kPerDay, db = dv[1] * kPerDay, dr = dv[2] * kPerDay;
  const Vec3 vel{dr * cb * cl - r * sb * db * cl - r * cb * sl * dl,
                 dr * cb * sl - r * sb * db * sl + r * cb * cl * dl, dr * sb + r * cb * db};
  const Mat3& m = vsopEclipticToFk5();
  return {m * pos, m * vel};
}

}  // namespace skyig::ephemeris
