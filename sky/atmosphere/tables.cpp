#include "sky/atmosphere/tables.h"

#include <sstream>
#include <stdexcept>

namespace skyig::atmosphere {

TableSizes TableSizes::small() {
  TableSizes s;
  s.transmittance_mu = 128;
  s.transmittance_r = 32;
  s.irradiance_mu_s = 32;
  s.irradiance_r = 8;
  s.scattering_r = 8;
  s.scattering_mu = 32;
  s.scattering_mu_s = 16;
  s.scattering_nu = 4;
  return s;
}

TableSizes TableSizes::medium() {
  TableSizes s;
  s.scattering_r = 16;
  s.scattering_mu = 64;
  return s;
}

TableSizes TableSizes::named(const std::string& name) {
  if (name == "small") return small();
  if (name == "medium") return medium();
  if (name == "default") return TableSizes{};
  throw std::invalid_argument("table size \"" + name + "\": expected \"small\", \"medium\" or \"default\"");
}

std::size_t TableSizes::scatteringTexels() const {
  return static_cast<std::size_t>(scattering_r) * static_cast<std::size_t>(scattering_mu) *
         static_cast<std::size_t>(scattering_mu_s) * static_cast<std::size_t>(scattering_nu);
}

std::size_t TableSizes::bytesAtHalfFloat() const {
  const std::size_t texel = 4 * 2;  // RGBA16F
  const std::size_t t = static_cast<std::size_t>(transmittance_mu) *
                        static_cast<std::size_t>(transmittance_r);
  const std::size_t e = static_cast<std::size_t>(irradiance_mu_s) *
                        static_cast<std::size_t>(irradiance_r);
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
  require(s.transmittance_mu, 2, "transmittance_mu");
  require(s.transmittance_r, 2, "transmittance_r");
  require(s.irradiance_mu_s, 2, "irradiance_mu_s");
  require(s.irradiance_r, 2, "irradiance_r");
  require(s.scattering_r, 2, "scattering_r");
  require(s.scattering_mu, 4, "scattering_mu");
  require(s.scattering_mu_s, 2, "scattering_mu_s");
  require(s.scattering_nu, 2, "scattering_nu");
  if (s.scattering_mu % 2 != 0) {
    throw std::invalid_argument("atmosphere table size scattering_mu = " +
                                std::to_string(s.scattering_mu) +
                                " must be even (half the rows for rays hitting the ground)");
  }
}

}  // namespace skyig::atmosphere
