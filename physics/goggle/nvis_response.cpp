#include "physics/goggle/nvis_response.h"

#include <cmath>

namespace skyig::sky::nvis {

namespace {

// The stand-in (nvis_response.h): a logistic filter edge, flat above it.
std::array<double, kNvisTableSize> standIn(double filterNm) {
  constexpr double kEdgeScaleNm = 5.0;
  std::array<double, kNvisTableSize> g{};
  for (int i = 0; i < kNvisTableSize; ++i) {
    const double w = kNvisMinNm + kNvisTableStepNm * i;
    g[static_cast<std::size_t>(i)] = 1.0 / (1.0 + std::exp(-(w - filterNm) / kEdgeScaleNm));
  }
  return g;
}

}  // namespace

const std::array<double, kNvisTableSize>& nvisResponseTable(NvisClass nvisClass) {
  static const std::array<double, kNvisTableSize> a = standIn(625.0);
  static const std::array<double, kNvisTableSize> b = standIn(665.0);
  return nvisClass == NvisClass::A ? a : b;
}

double nvisResponse(NvisClass nvisClass, double wavelengthNm) {
  if (!(wavelengthNm >= kNvisMinNm && wavelengthNm <= kNvisMaxNm)) return 0.0;
  const std::array<double, kNvisTableSize>& g = nvisResponseTable(nvisClass);
  const double x = (wavelengthNm - kNvisMinNm) / kNvisTableStepNm;
  const auto i = static_cast<std::size_t>(std::floor(x));
  if (i + 1 >= g.size()) return g.back();
  const double f = x - static_cast<double>(i);
  return g[i] * (1.0 - f) + g[i + 1] * f;
}

}  // namespace skyig::sky::nvis
