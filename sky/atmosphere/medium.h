#pragma once
// The physical medium of the atmosphere model, in SI units, with the defaults of Bruneton's
// 2017 implementation of Bruneton & Neyret 2008 (the Earth atmosphere of its demo,
// github.com/ebruneton/precomputed_atmospheric_scattering), and the spectral sampling it is
// evaluated at.
#include <string>
#include <vector>

namespace skyig::atmosphere {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;

struct Medium {
  // Spherical earth and the top of the atmosphere, m (paper section 2.1).
  double bottom_radius_m = 6360e3;
  double top_radius_m = 6420e3;
  // Molecules: scattering at the ground = beta_1um * (lambda / 1 um)^-4 (5.802, 13.558,
  // 33.100 e-6 m^-1 at 680/550/440 nm), scale height (paper eq. 1).
  double rayleigh_scattering_at_1um_per_m = 1.24062e-6;
  double rayleigh_scale_height_m = 8000.0;
  // Aerosols at the ground: extinction, single scattering albedo (scattering/extinction),
  // Angstrom exponent of the extinction (0 = grey), scale height, Cornette-Shanks g.
  double mie_extinction_per_m = 4.44e-6;
  double mie_single_scattering_albedo = 0.9;
  double mie_angstrom_exponent = 0.0;
  double mie_scale_height_m = 1200.0;
  double mie_phase_g = 0.8;
  // Ozone: column in Dobson units in a tent profile (zero at centre -/+ half width),
  // cross-sections at 233 K (spectral_data.h).
  double ozone_column_du = 300.0;
  double ozone_center_altitude_m = 25000.0;
  double ozone_half_width_m = 15000.0;
  // Lambertian ground, grey.
  double ground_albedo = 0.1;
  // Sun: angular radius, and a scale on the ASTM G-173 irradiance (1 = the real sun).
  double sun_angular_radius_rad = 0.2678 * kDegree;
  double solar_irradiance_scale = 1.0;
  // Largest sun zenith angle the scattering tables cover (twilight down to 18 deg below the
  // horizon needs more than 108 deg).
  double max_sun_zenith_rad = 120.0 * kDegree;

  bool operator==(const Medium&) const = default;
};

// Throws std::invalid_argument naming the first bad value.
void validate(const Medium& medium);

// One Dobson unit: 2.687e20 molecules m^-2 (WMO definition).
inline constexpr double kDobsonUnitPerM2 = 2.687e20;

// Peak ozone number density (m^-3) giving the medium's column with its tent profile.
double ozonePeakNumberDensity(const Medium& medium);

// Spectral coefficients of the medium at one wavelength, m^-1 at the ground (ozone: at the
// peak of its profile).
struct SpectralCoefficients {
  double rayleigh_scattering;
  double mie_scattering;
  double mie_extinction;
  double ozone_absorption;
  double solar_irradiance;  // W m^-2 nm^-1
};
SpectralCoefficients coefficientsAt(const Medium& medium, double wavelength_nm);

// Exponent alpha of the solar limb darkening I(mu)/I(1) = mu^alpha at a wavelength (nm):
// alpha = -0.023 + 0.292 / lambda[um] (Hestroffer & Magnan 1998, A&A 333, 338).
double limbDarkeningExponent(double wavelength_nm);

// skyig's wavelengths (nm): 16 samples from 360 to 830 nm, about 25-30 nm apart where the
// CIE colour matching functions are large, wider at the ends where they are nearly zero, and
// including 440, 550 and 680 nm, the paper's three.
std::vector<double> defaultWavelengths();

}  // namespace skyig::atmosphere
