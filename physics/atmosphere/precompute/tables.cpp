#include "physics/atmosphere/precompute/tables.h"

#include <sstream>
#include <stdexcept>

namespace skyig::atmosphere {

TableSizes TableSizes::small() {
  TableSizes s;
  s.transmittanceMu = 128;
  s.transmittanceR = 32;
  s.irradianceMuS = 32;
  s.irradianceR = 8;
  s.scatteringR = 8;
  s.scatteringMu = 32;
  s.scatteringMuS = 16;
  s.scatteringNu = 4;
  return s;
}

TableSizes TableSizes::medium() {
  TableSizes s;
  s.scatteringR = 16;
  s.scatteringMu = 64;
  return s;
}

TableSizes TableSizes::named(const std::string& name) {
  if (name == "small") return small();
  if (name == "medium") return medium();
  if (name == "default") return TableSizes{};
  throw std::invalid_argument("table size \"" + name + "\": expected \"small\", \"medium\" or \"default\"");
}

std::size_t TableSizes::scatteringTexels() const {
  return static_cast<std::size_t>(scatteringR) * static_cast<std::size_t>(scatteringMu) *
         static_cast<std::size_t>(scatteringMuS) * static_cast<std::size_t>(scatteringNu);
}

std::size_t TableSizes::bytesAtHalfFloat() const {
  const std::size_t texel = 4 * 2;  // RGBA16F
  const std::size_t t = static_cast<std::size_t>(transmittanceMu) *
                        static_cast<std::size_t>(transmittanceR);
  const std::size_t e = static_cast<std::size_t>(irradianceMuS) *
                        static_cast<std::size_t>(irradianceR);
  return texel * (t + e + 2 * scatteringTexels());
}

void validate(const TableSizes& s) {
  auto require = [](int v, int min, const char* name) {
    if (v < min || v > 4096) {
      std::ostringstream msg;
      msg << "atmosphere table size " << name << " = " << v << " is invalid (expected " << min
          << " to 4096)";
      throw std::invalid_argument(msg.str());
    }
  };
  require(s.transmittanceMu, 2, "transmittance_mu");
  require(s.transmittanceR, 2, "transmittance_r");
  require(s.irradianceMuS, 2, "irradiance_mu_s");
  require(s.irradianceR, 2, "irradiance_r");
  require(s.scatteringR, 2, "scattering_r");
  require(s.scatteringMu, 4, "scattering_mu");
  require(s.scatteringMuS, 2, "scattering_mu_s");
  require(s.scatteringNu, 2, "scattering_nu");
  if (s.scatteringMu % 2 != 0) {
    throw std::invalid_argument("atmosphere table size scattering_mu = " +
                                std::to_string(s.scatteringMu) +
                                " must be even (half the rows for rays hitting the ground)");
  }
}

}  // namespace skyig::atmosphere
