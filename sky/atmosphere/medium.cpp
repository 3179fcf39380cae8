#include "sky/atmosphere/medium.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sky/atmosphere/spectral_data.h"

namespace skyig::atmosphere {
namespace {

void require(bool ok, const char* name, double value, const char* expected) {
  if (!ok) {
    std::ostringstream msg;
    msg << "atmosphere medium: " << name << " = " << value << " is invalid (expected "
        << expected << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

void validate(const Medium& m) {
  require(m.bottom_radius_m > 0.0 && std::isfinite(m.bottom_radius_m), "bottom_radius_m",
          m.bottom_radius_m, "> 0");
  require(m.top_radius_m > m.bottom_radius_m && std::isfinite(m.top_radius_m), "top_radius_m",
          m.top_radius_m, "> bottom_radius_m");
  require(m.rayleigh_scattering_at_1um_per_m >= 0.0 &&
              std::isfinite(m.rayleigh_scattering_at_1um_per_m),
          "rayleigh_scattering_at_1um_per_m", m.rayleigh_scattering_at_1um_per_m, ">= 0");
  require(m.rayleigh_scale_height_m > 0.0, "rayleigh_scale_height_m", m.rayleigh_scale_height_m,
          "> 0");
  require(m.mie_extinction_per_m >= 0.0 && std::isfinite(m.mie_extinction_per_m),
          "mie_extinction_per_m", m.mie_extinction_per_m, ">= 0");
  require(m.mie_single_scattering_albedo >= 0.0 && m.mie_single_scattering_albedo <= 1.0,
          "mie_single_scattering_albedo", m.mie_single_scattering_albedo, "in [0, 1]");
  require(std::isfinite(m.mie_angstrom_exponent) && std::abs(m.mie_angstrom_exponent) <= 4.0,
          "mie_angstrom_exponent", m.mie_angstrom_exponent, "in [-4, 4]");
  require(m.mie_scale_height_m > 0.0, "mie_scale_height_m", m.mie_scale_height_m, "> 0");
  require(m.mie_phase_g > -1.0 && m.mie_phase_g < 1.0, "mie_phase_g", m.mie_phase_g,
          "in (-1, 1)");
  require(m.ozone_column_du >= 0.0 && m.ozone_column_du <= 1000.0, "ozone_column_du",
          m.ozone_column_du, "in [0, 1000]");
  require(m.ozone_half_width_m > 0.0, "ozone_half_width_m", m.ozone_half_width_m, "> 0");
  require(m.ozone_center_altitude_m >= 0.0 &&
              m.ozone_center_altitude_m < m.top_radius_m - m.bottom_radius_m,
          "ozone_center_altitude_m", m.ozone_center_altitude_m, "inside the atmosphere");
  require(m.ground_albedo >= 0.0 && m.ground_albedo <= 1.0, "ground_albedo", m.ground_albedo,
          "in [0, 1]");
  require(m.sun_angular_radius_rad > 0.0 && m.sun_angular_radius_rad < 0.1,
          "sun_angular_radius_rad", m.sun_angular_radius_rad, "in (0, 0.1)");
  require(m.solar_irradiance_scale >= 0.0 && std::isfinite(m.solar_irradiance_scale),
          "solar_irradiance_scale", m.solar_irradiance_scale, ">= 0");
  require(m.max_sun_zenith_rad > kPi / 2.0 && m.max_sun_zenith_rad < kPi,
          "max_sun_zenith_rad", m.max_sun_zenith_rad, "in (pi/2, pi)");
}

double ozonePeakNumberDensity(const Medium& m) {
  // The tent profile integrates to its half width (peak density 1).
  return m.ozone_column_du * kDobsonUnitPerM2 / m.ozone_half_width_m;
}

SpectralCoefficients coefficientsAt(const Medium& m, double wavelength_nm) {
  const double lambda_um = wavelength_nm * 1e-3;
  SpectralCoefficients c{};
  c.rayleigh_scattering = m.rayleigh_scattering_at_1um_per_m * std::pow(lambda_um, -4.0);
  // Angstrom's law, referred to 550 nm so the default (alpha = 0) is grey at every wavelength.
  c.mie_extinction = m.mie_extinction_per_m * std::pow(wavelength_nm / 550.0, -m.mie_angstrom_exponent);
  c.mie_scattering = c.mie_extinction * m.mie_single_scattering_albedo;
  c.ozone_absorption = ozonePeakNumberDensity(m) * ozoneCrossSection(wavelength_nm);
  c.solar_irradiance = solarIrradiance(wavelength_nm) * m.solar_irradiance_scale;
  return c;
}

double limbDarkeningExponent(double wavelength_nm) {
  return -0.023 + 0.292 / (wavelength_nm * 1e-3);
}

std::vector<double> defaultWavelengths() {
  return {360.0, 390.0, 420.0, 440.0, 470.0, 500.0, 525.0, 550.0,
          575.0, 600.0, 630.0, 655.0, 680.0, 710.0, 760.0, 830.0};
}

}  // namespace skyig::atmosphere
