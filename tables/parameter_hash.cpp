#include "tables/parameter_hash.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace skyig::atmosphere {

void Fnv1a64::bytes(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    state_ ^= p[i];
    state_ *= 1099511628211ull;
  }
}

void Fnv1a64::f64(double v) {
  if (std::isnan(v)) throw std::invalid_argument("parameter hash: NaN parameter");
  const auto bits = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) {  // little-endian order on every host
    const auto b = static_cast<unsigned char>((bits >> (8 * i)) & 0xffu);
    bytes(&b, 1);
  }
}

void Fnv1a64::i64(std::int64_t v) { f64(static_cast<double>(v)); }

std::uint64_t parameterHash(const ModelConfig& c) {
  Fnv1a64 h;
  h.i64(kPhysicsRevision);
  const Medium& m = c.medium;
  for (double v : {m.bottomRadiusM, m.topRadiusM, m.rayleighScatteringAt1umPerM,
                   m.rayleighScaleHeightM, m.mieExtinctionPerM,
                   m.mieSingleScatteringAlbedo, m.mieAngstromExponent, m.mieScaleHeightM,
                   m.miePhaseG, m.ozoneColumnDu, m.ozoneCentreAltitudeM,
                   m.ozoneHalfWidthM, m.groundAlbedo, m.sunAngularRadiusRad,
                   m.solarIrradianceScale, m.maxSunZenithRad}) {
    h.f64(v);
  }
  if (m.aerosolType != AerosolType::bruneton2017) {  // Bruneton's aerosol hashes as it always has
    h.i64(static_cast<std::int64_t>(m.aerosolType));
    h.f64(m.aerosolHumidity);
  }
  h.i64(static_cast<std::int64_t>(c.wavelengthsNm.size()));
  for (double w : c.wavelengthsNm) h.f64(w);
  const TableSizes& s = c.sizes;
  for (int v : {s.transmittanceMu, s.transmittanceR, s.irradianceMuS, s.irradianceR,
                s.scatteringR, s.scatteringMu, s.scatteringMuS, s.scatteringNu}) {
    h.i64(v);
  }
  h.i64(c.options.scatteringOrders);  // the thread count does not change the tables
  h.i64(c.options.ordersTail ? 1 : 0);
  return h.value();
}

std::string hexHash(std::uint64_t hash) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

}  // namespace skyig::atmosphere
