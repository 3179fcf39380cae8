#pragma once
// The physical medium of the atmosphere model, in SI units, with the defaults of Bruneton's
// 2017 implementation of Bruneton & Neyret 2008 (the Earth atmosphere of its demo,
// github.com/ebruneton/precomputed_atmospheric_scattering), and the spectral sampling it is
// evaluated at.
#include <string>
#include <vector>

#include "physics/atmosphere/aerosol_type.h"

namespace skyig::atmosphere {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;

struct Medium {
  // Spherical earth and the top of the atmosphere, m (paper section 2.1).
  double bottomRadiusM = 6360e3;
  double topRadiusM = 6420e3;
  // Molecules: scattering at the ground = beta_1um * (lambda / 1 um)^-4 (5.802, 13.558,
  // 33.100 e-6 m^-1 at 680/550/440 nm), scale height (paper eq. 1).
  double rayleighScatteringAt1umPerM = 1.24062e-6;
  double rayleighScaleHeightM = 8000.0;
  // Aerosols at the ground: extinction, single scattering albedo (scattering/extinction),
  // Angstrom exponent of the extinction (0 = grey), scale height, Cornette-Shanks g.
  double mieExtinctionPerM = 4.44e-6;
  double mieSingleScatteringAlbedo = 0.9;
  double mieAngstromExponent = 0.0;
  double mieScaleHeightM = 1200.0;
  double miePhaseG = 0.8;
  // What the aerosol is: bruneton2017 is the grey, Cornette-Shanks aerosol above; an OPAC type
  // (aerosol_type.h) brings its own phase function, tabulated at aerosolHumidity, and
  // withAerosolType sets the albedo, exponent and scale height above to the type's.
  AerosolType aerosolType = AerosolType::bruneton2017;
  double aerosolHumidity = 0.5;
  // Ozone: column in Dobson units in a tent profile (zero at centre -/+ half width),
  // cross-sections at 233 K (spectral_data.h).
  double ozoneColumnDu = 300.0;
  double ozoneCentreAltitudeM = 25000.0;
  double ozoneHalfWidthM = 15000.0;
  // Lambertian ground, grey.
  double groundAlbedo = 0.1;
  // Sun: angular radius, and a scale on the ASTM G-173 irradiance (1 = the real sun).
  double sunAngularRadiusRad = 0.2678 * kDegree;
  double solarIrradianceScale = 1.0;
  // Largest sun zenith angle the scattering tables cover (twilight down to 18 deg below the
  // horizon needs more than 108 deg).
  double maxSunZenithRad = 120.0 * kDegree;

  bool operator==(const Medium&) const = default;
};

// Molecules as measured: Bodhaine, Wood, Dutton and Slusser 1999 ("On Rayleigh optical depth
// calculations", J. Atmos. Oceanic Technol. 16, 1854-1861, eq. 30) give a sea-level Rayleigh
// optical depth of 0.0971 at 550 nm (1013.25 hPa, 360 ppm CO2): over the 8 km scale height and
// with the lambda^-4 law this is 1.1103e-6 m^-1 at 1 um, within 2.5% of their eq. 30 from 440
// to 680 nm (theirs is steeper, about lambda^-4.08). Bruneton's 1.24062e-6 (the default, kept for the reference comparisons) is 11.7%
// more: a sky of Bruneton's molecules is a tenth too bright against a measured one.
inline constexpr double kBodhaineRayleighScatteringAt1umPerM = 1.1103e-6;

// Throws std::invalid_argument naming the first bad value.
void validate(const Medium& medium);

// One Dobson unit: 2.687e20 molecules m^-2 (WMO definition).
inline constexpr double kDobsonUnitPerM2 = 2.687e20;

// Peak ozone number density (m^-3) giving the medium's column with its tent profile.
double ozonePeakNumberDensity(const Medium& medium);

// Spectral coefficients of the medium at one wavelength, m^-1 at the ground (ozone: at the
// peak of its profile).
struct SpectralCoefficients {
  double rayleighScattering;
  double mieScattering;
  double mieExtinction;
  double ozoneAbsorption;
  double solarIrradiance;  // W m^-2 nm^-1
};
SpectralCoefficients coefficientsAt(const Medium& medium, double wavelengthNm);

// Exponent alpha of the solar limb darkening I(mu)/I(1) = mu^alpha at a wavelength (nm):
// alpha = -0.023 + 0.292 / lambda[um] (Hestroffer & Magnan 1998, A&A 333, 338).
double limbDarkeningExponent(double wavelengthNm);

// skyig's wavelengths (nm): 16 samples from 360 to 830 nm, about 25-30 nm apart where the
// CIE colour matching functions are large, wider at the ends where they are nearly zero, and
// including 440, 550 and 680 nm, the paper's three.
std::vector<double> defaultWavelengths();

}  // namespace skyig::atmosphere
