#pragma once
// Tabulated physical data the atmosphere needs, each with its source (see spectral_data.cpp):
// solar spectral irradiance at the top of the atmosphere, ozone absorption cross-sections and
// the CIE 1931 2-degree colour matching functions. Values between table entries are linearly
// interpolated; outside the table range the functions throw, naming the wavelength.
#include <glm/vec3.hpp>

namespace skyig::atmosphere {

// First and last wavelengths (nm) covered by every table below.
inline constexpr double kSpectralDataMinNm = 360.0;
inline constexpr double kSpectralDataMaxNm = 830.0;

// The solar spectrum alone reaches further, over the night-vision goggles' band (sky/nvis).
inline constexpr double kSolarSpectrumMaxNm = 940.0;

// Solar spectral irradiance at the top of the atmosphere, W m^-2 nm^-1 (ASTM G-173 ETR,
// averaged over 10 nm bins), from kSpectralDataMinNm to kSolarSpectrumMaxNm.
double solarIrradiance(double wavelengthNm);

// Ozone absorption cross-section at 233 K, m^2 per molecule (Serdyuchenko et al. 2014,
// averaged over 10 nm bins).
double ozoneCrossSection(double wavelengthNm);

// CIE 1931 2-degree colour matching functions xbar, ybar, zbar (dimensionless, ybar peaks at 1
// at 555 nm).
glm::dvec3 cie1931ColourMatching(double wavelengthNm);

}  // namespace skyig::atmosphere
