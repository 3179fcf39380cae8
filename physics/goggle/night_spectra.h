#pragma once
// The spectra of the night's light sources from 360 to 930 nm, the visible band and the
// goggles' (nvis_response.h), each scaled to a luminance of 1 cd/m^2 above the atmosphere, and
// the integrals that turn a luminance into an NVIS radiance through the same spectral
// extinction (docs/nvis.md gives every source).
#include <array>
#include <utility>
#include <vector>

#include "physics/atmosphere/extinction_profile.h"

namespace skyig::sky::nvis {

// The common wavelength grid: 360, 365, ..., 930 nm (trapezoidal rule).
inline constexpr double kGridMinNm = 360.0;
inline constexpr double kGridStepNm = 5.0;
inline constexpr int kGridSize = 115;
double gridWavelength(int i);

// A spectral radiance (W m^-2 sr^-1 nm^-1) on the grid, plus emission lines (nm, W m^-2 sr^-1).
struct Spectrum {
  std::array<double, kGridSize> continuum{};
  std::vector<std::pair<double, double>> lines;
};

// Spectral transmittance on the grid; 1 without an atmosphere.
using Transmittance = std::array<double, kGridSize>;
Transmittance unitTransmittance();
// The profile's transmittance to space at an elevation (radians), interpolated linearly between
// its wavelengths, extended beyond its last one (830 nm: the medium's ozone table stops there,
// physics/spectrum/spectral_data.h) by the power law of its last two, and times the oxygen and
// water vapour bands the medium does not have (gas_bands.h), at the profile's altitude.
Transmittance transmittanceOf(const atmosphere::ExtinctionProfile& profile, double elevationRad);

// Class A and class B NVIS radiance (W m^-2 sr^-1) or irradiance (W m^-2).
struct NvisRadiance {
  double a = 0.0;
  double b = 0.0;
  NvisRadiance& operator+=(const NvisRadiance& o) {
    a += o.a;
    b += o.b;
    return *this;
  }
  friend NvisRadiance operator+(NvisRadiance x, const NvisRadiance& y) { return x += y; }
  friend NvisRadiance operator*(double k, const NvisRadiance& x) { return {k * x.a, k * x.b}; }
};

// 683 lm/W x integral of V S t, and the class A and B integrals of G S t (nvis_response.h).
struct BandIntegrals {
  double luminance = 0.0;
  NvisRadiance nvis;
};
BandIntegrals integrate(const Spectrum& s, const Transmittance& t);

// The NVIS radiance of a light of spectrum `s` above the atmosphere whose luminance after the
// transmittance `t` is `luminance` (cd/m^2; lux gives an irradiance in W m^-2): both are
// weighted by the same transmitted spectrum, so the goggle and the eye see one source.
NvisRadiance nvisFromLuminance(const Spectrum& s, const Transmittance& t, double luminance);

// The mean spectral radiance of `s` over [fromNm, toNm] (lines included), for broad-band
// magnitudes.
double bandMean(const Spectrum& s, double fromNm, double toNm);

// A blackbody of `temperatureK` (Planck's law).
Spectrum blackbodySpectrum(double temperatureK);
// Sunlight above the atmosphere (ASTM G-173 ETR, physics/spectrum/spectral_data.h).
const Spectrum& sunlightSpectrum();
// Moonlight: sunlight times the moon's reflectance rising into the infrared
// (physics/moon/moon_light.h moonReflectanceRelative).
const Spectrum& moonlightSpectrum();
// Zodiacal light: sunlight reddened by f(lambda) = 1 + 0.6 log10(lambda / 500 nm), the colour
// correction Leinert et al. (1998, A&AS 127, 1) give for the zodiacal light at elongations near
// 90 deg, as we recall it (stronger nearer the sun; not modelled); docs/nvis.md.
const Spectrum& zodiacalSpectrum();
// The integrated light of the Milky Way and the unresolved stars: the mean colour of the
// Galaxy's integrated starlight is that of a late-G/early-K star (Leinert et al. 1998); here,
// an estimate, a blackbody at the eq. 12 temperature of B-V = kIntegratedStarlightBMinusV.
inline constexpr double kIntegratedStarlightBMinusV = 0.85;
const Spectrum& integratedStarlightSpectrum();
// Airglow: the visible part physics/night/night_diffuse.h describes (the OI 557.7 nm line, the Na D
// lines, an equal-energy pseudo-continuum from 400 to 700 nm) plus the OH Meinel bands and the
// red part of the pseudo-continuum, which at the goggles' resolution are one envelope from
// 600 nm to 930 nm, linear in wavelength (the OH bands grow into the near infrared: in the UVES
// sky atlas of Hanuschik 2003, A&A 407, 1157, the bands near 840-890 nm outshine those near
// 650-700 nm). The envelope's two ends are fitted so that the dark sky's zenith (the budget
// below) has the colours V-R = 0.9 and R-I = 1.0 Benn & Ellison (1998, La Palma, solar minimum)
// measured: two numbers, two parameters; its level stays the eye's (V).
const Spectrum& airglowSpectrum();
inline constexpr double kOhEnvelopeStartNm = 600.0;
// The fitted envelope's spectral radiance just above 600 nm and at 930 nm, W m^-2 sr^-1 nm^-1
// per cd/m^2 of airglow.
struct OhEnvelope {
  double at600Nm = 0.0;
  double at930Nm = 0.0;
};
OhEnvelope ohEnvelope();
// Light scattered by air molecules: the source times (lambda / 550 nm)^-4 (Rayleigh). The
// moonlit and sunlit sky's spectrum until the atmosphere's tables reach 930 nm.
Spectrum rayleighScattered(const Spectrum& source);

// The dark sky's zenith budget the airglow is calibrated with (Roach & Gordon 1973, the split
// physics/night/night_diffuse.h uses, S10): airglow kAirglowZenithS10, zodiacal light 60,
// integrated starlight 15; and Benn & Ellison (1998)'s zenith sky in V, R and I
// (mag/arcsec^2). The bands are taken flat: V 501-589 nm, R 561-721 nm, I 721-875 nm (Bessell
// 1990's effective wavelengths and widths), with the Vega zero points of Bessell, Castelli &
// Plez (1998, table A2): 363.1, 217.7 and 112.6 x 1e-11 erg cm^-2 s^-1 A^-1.
inline constexpr double kBudgetZodiacalS10 = 60.0;
inline constexpr double kBudgetStarlightS10 = 15.0;
struct Band {
  double fromNm;
  double toNm;
  double zeroPointWm2Nm;  // spectral irradiance of magnitude 0, W m^-2 nm^-1
};
inline constexpr Band kBandV{501.0, 589.0, 3.631e-11};
inline constexpr Band kBandR{561.0, 721.0, 2.177e-11};
inline constexpr Band kBandI{721.0, 875.0, 1.126e-11};
inline constexpr double kDarkSkyV = 21.9;
inline constexpr double kDarkSkyR = 21.0;
inline constexpr double kDarkSkyI = 20.0;
// Spectral radiance (W m^-2 sr^-1 nm^-1) of a surface brightness in mag/arcsec^2, and back.
double spectralRadianceOfMagnitude(double magPerArcsec2, const Band& band);
double magnitudeOfSpectralRadiance(double radiance, const Band& band);

}  // namespace skyig::sky::nvis
