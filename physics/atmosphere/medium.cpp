#include "physics/atmosphere/medium.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "physics/spectrum/spectral_data.h"

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
  require(m.bottomRadiusM > 0.0 && std::isfinite(m.bottomRadiusM), "bottom_radius_m",
          m.bottomRadiusM, "> 0");
  require(m.topRadiusM > m.bottomRadiusM && std::isfinite(m.topRadiusM), "top_radius_m",
          m.topRadiusM, "> bottom_radius_m");
  require(m.rayleighScatteringAt1umPerM >= 0.0 &&
              std::isfinite(m.rayleighScatteringAt1umPerM),
          "rayleigh_scattering_at_1um_per_m", m.rayleighScatteringAt1umPerM, ">= 0");
  require(m.rayleighScaleHeightM > 0.0, "rayleigh_scale_height_m", m.rayleighScaleHeightM,
          "> 0");
  require(m.mieExtinctionPerM >= 0.0 && std::isfinite(m.mieExtinctionPerM),
          "mie_extinction_per_m", m.mieExtinctionPerM, ">= 0");
  require(m.mieSingleScatteringAlbedo >= 0.0 && m.mieSingleScatteringAlbedo <= 1.0,
          "mie_single_scattering_albedo", m.mieSingleScatteringAlbedo, "in [0, 1]");
  require(std::isfinite(m.mieAngstromExponent) && std::abs(m.mieAngstromExponent) <= 4.0,
          "mie_angstrom_exponent", m.mieAngstromExponent, "in [-4, 4]");
  require(m.mieScaleHeightM > 0.0, "mie_scale_height_m", m.mieScaleHeightM, "> 0");
  require(m.miePhaseG > -1.0 && m.miePhaseG < 1.0, "mie_phase_g", m.miePhaseG,
          "in (-1, 1)");
  require(m.aerosolHumidity >= 0.0 && m.aerosolHumidity <= 0.99, "aerosol_humidity", m.aerosolHumidity,
          "in [0, 0.99]");
  require(m.ozoneColumnDu >= 0.0 && m.ozoneColumnDu <= 1000.0, "ozone_column_du",
          m.ozoneColumnDu, "in [0, 1000]");
  require(m.ozoneHalfWidthM > 0.0, "ozone_half_width_m", m.ozoneHalfWidthM, "> 0");
  require(m.ozoneCentreAltitudeM >= 0.0 &&
              m.ozoneCentreAltitudeM < m.topRadiusM - m.bottomRadiusM,
          "ozone_center_altitude_m", m.ozoneCentreAltitudeM, "inside the atmosphere");
  require(m.groundAlbedo >= 0.0 && m.groundAlbedo <= 1.0, "ground_albedo", m.groundAlbedo,
          "in [0, 1]");
  require(m.sunAngularRadiusRad > 0.0 && m.sunAngularRadiusRad < 0.1,
          "sun_angular_radius_rad", m.sunAngularRadiusRad, "in (0, 0.1)");
  require(m.solarIrradianceScale >= 0.0 && std::isfinite(m.solarIrradianceScale),
          "solar_irradiance_scale", m.solarIrradianceScale, ">= 0");
  require(m.maxSunZenithRad > kPi / 2.0 && m.maxSunZenithRad < kPi,
          "max_sun_zenith_rad", m.maxSunZenithRad, "in (pi/2, pi)");
}

double ozonePeakNumberDensity(const Medium& m) {
  // The tent profile integrates to its half width (peak density 1).
  return m.ozoneColumnDu * kDobsonUnitPerM2 / m.ozoneHalfWidthM;
}

SpectralCoefficients coefficientsAt(const Medium& m, double wavelengthNm) {
  const double lambdaUm = wavelengthNm * 1e-3;
  SpectralCoefficients c{};
  c.rayleighScattering = m.rayleighScatteringAt1umPerM * std::pow(lambdaUm, -4.0);
  // Angstrom's law, referred to 550 nm so the default (alpha = 0) is grey at every wavelength.
  c.mieExtinction = m.mieExtinctionPerM * std::pow(wavelengthNm / 550.0, -m.mieAngstromExponent);
  c.mieScattering = c.mieExtinction * m.mieSingleScatteringAlbedo;
  c.ozoneAbsorption = ozonePeakNumberDensity(m) * ozoneCrossSection(wavelengthNm);
  c.solarIrradiance = solarIrradiance(wavelengthNm) * m.solarIrradianceScale;
  return c;
}

double limbDarkeningExponent(double wavelengthNm) {
  return -0.023 + 0.292 / (wavelengthNm * 1e-3);
}

std::vector<double> defaultWavelengths() {
  return {360.0, 390.0, 420.0, 440.0, 470.0, 500.0, 525.0, 550.0,
          575.0, 600.0, 630.0, 655.0, 680.0, 710.0, 760.0, 830.0};
}

}  // namespace skyig::atmosphere
