#include "physics/goggle/night_spectra.h"

#include "physics/goggle/gas_bands.h"

#include "physics/night/diffuse_physics.h"
#include "physics/spectrum/spectral_data.h"
#include "physics/moon/moon_light.h"
#include "physics/night/night_diffuse.h"
#include "physics/stars/star_colour.h"
#include "physics/goggle/nvis_response.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::sky::nvis {

namespace {

constexpr double kLumensPerWatt = 683.0;

double photopic(double wavelengthNm) {
  return wavelengthNm <= atmosphere::kSpectralDataMaxNm ? atmosphere::cie1931ColourMatching(wavelengthNm).y : 0.0;
}

// Trapezoid weights of the grid.
double gridWeight(int i) { return (i == 0 || i == kGridSize - 1) ? 0.5 * kGridStepNm : kGridStepNm; }

// Linear interpolation of a grid array (0 outside the grid).
double onGrid(const std::array<double, kGridSize>& values, double wavelengthNm) {
  const double x = (wavelengthNm - kGridMinNm) / kGridStepNm;
  if (x < 0.0 || x > kGridSize - 1) return 0.0;
  const auto i = std::min(static_cast<std::size_t>(x), static_cast<std::size_t>(kGridSize - 2));
  const double f = x - static_cast<double>(i);
  return values[i] * (1.0 - f) + values[i + 1] * f;
}

Spectrum withUnitLuminance(Spectrum s) {
  const double l = integrate(s, unitTransmittance()).luminance;
  for (double& v : s.continuum) v /= l;
  for (auto& line : s.lines) line.second /= l;
  return s;
}

template <class F>
Spectrum tabulate(F f) {
  Spectrum s;
  for (int i = 0; i < kGridSize; ++i) s.continuum[static_cast<std::size_t>(i)] = f(gridWavelength(i));
  return s;
}

constexpr double kArcsec2Sr = (std::numbers::pi / 648000.0) * (std::numbers::pi / 648000.0);

}  // namespace

double gridWavelength(int i) { return kGridMinNm + kGridStepNm * i; }

Transmittance unitTransmittance() {
  Transmittance t;
  t.fill(1.0);
  return t;
}

Transmittance transmittanceOf(const atmosphere::ExtinctionProfile& profile, double elevationRad) {
  const std::vector<double> values = profile.spectral(elevationRad);
  const std::vector<double>& w = profile.wavelengths();
  // Beyond the profile's last wavelength: its optical depth extended by the local power law of
  // its last two (Angstrom's law applied to the whole extinction: Rayleigh's lambda^-4 and the
  // aerosol's flatter one in their mixture's proportion), the exponent kept within [0, 4].
  const std::size_t n = w.size();
  double exponent = 0.0;
  if (n >= 2 && values[n - 1] > 0.0 && values[n - 2] > 0.0 && values[n - 1] < 1.0 && values[n - 2] < 1.0)
    exponent = std::clamp(std::log(std::log(values[n - 2]) / std::log(values[n - 1])) / std::log(w[n - 1] / w[n - 2]), 0.0, 4.0);
  Transmittance t{};
  for (int i = 0; i < kGridSize; ++i) {
    const double l = gridWavelength(i);
    const auto hi = std::lower_bound(w.begin(), w.end(), l);
    double v;
    if (hi == w.begin()) v = values.front();
    else if (hi == w.end()) v = values.back() > 0.0 ? std::exp(std::log(values.back()) * std::pow(l / w.back(), -exponent)) : 0.0;
    else {
      const auto k = static_cast<std::size_t>(hi - w.begin());
      const double f = (l - w[k - 1]) / (w[k] - w[k - 1]);
      v = values[k - 1] * (1.0 - f) + values[k] * f;
    }
    t[static_cast<std::size_t>(i)] = v * gasTransmittance(l, elevationRad, profile.altitudeM());
  }
  return t;
}

BandIntegrals integrate(const Spectrum& s, const Transmittance& t) {
  BandIntegrals out;
  for (int i = 0; i < kGridSize; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double l = gridWavelength(i);
    const double e = s.continuum[k] * t[k] * gridWeight(i);
    out.luminance += kLumensPerWatt * photopic(l) * e;
    out.nvis.a += nvisResponse(NvisClass::A, l) * e;
    out.nvis.b += nvisResponse(NvisClass::B, l) * e;
  }
  for (const auto& [l, power] : s.lines) {
    const double e = power * onGrid(t, l);
    out.luminance += kLumensPerWatt * photopic(l) * e;
    out.nvis.a += nvisResponse(NvisClass::A, l) * e;
    out.nvis.b += nvisResponse(NvisClass::B, l) * e;
  }
  return out;
}

NvisRadiance nvisFromLuminance(const Spectrum& s, const Transmittance& t, double luminance) {
  if (luminance == 0.0) return {};
  const BandIntegrals b = integrate(s, t);
  if (!(b.luminance > 0.0)) return {};  // no visible light left (a source far below the horizon)
  return (luminance / b.luminance) * b.nvis;
}

double bandMean(const Spectrum& s, double fromNm, double toNm) {
  if (!(toNm > fromNm)) throw std::invalid_argument("band " + std::to_string(fromNm) + "-" + std::to_string(toNm) + " nm is empty");
  double sum = 0.0;
  constexpr double kStep = 1.0;
  for (double l = fromNm + 0.5 * kStep; l < toNm; l += kStep) sum += onGrid(s.continuum, l) * kStep;
  for (const auto& [l, power] : s.lines)
    if (l >= fromNm && l < toNm) sum += power;
  return sum / (toNm - fromNm);
}

Spectrum blackbodySpectrum(double temperatureK) {
  if (!(temperatureK >= 500.0 && temperatureK <= 1e6))
    throw std::invalid_argument("blackbody temperature " + std::to_string(temperatureK) + " K is outside [500, 1e6]");
  constexpr double kC2 = 1.438776877e-2;  // hc/k, m K (CODATA 2018)
  return withUnitLuminance(tabulate([&](double l) {
    const double m = l * 1e-9;
    return 1.0 / (std::pow(m / 1e-6, 5.0) * std::expm1(kC2 / (m * temperatureK)));
  }));
}

const Spectrum& sunlightSpectrum() {
  static const Spectrum s = withUnitLuminance(tabulate([](double l) { return atmosphere::solarIrradiance(l); }));
  return s;
}

const Spectrum& moonlightSpectrum() {
  static const Spectrum s = withUnitLuminance(
      tabulate([](double l) { return atmosphere::solarIrradiance(l) * night::moonReflectanceRelative(l); }));
  return s;
}

const Spectrum& zodiacalSpectrum() {
  static const Spectrum s = withUnitLuminance(tabulate([](double l) {
    return atmosphere::solarIrradiance(l) * std::max(0.0, 1.0 + 0.6 * std::log10(l / 500.0));
  }));
  return s;
}

const Spectrum& integratedStarlightSpectrum() {
  static const Spectrum s = blackbodySpectrum(night::starTemperatureFromBv(kIntegratedStarlightBMinusV));
  return s;
}

Spectrum rayleighScattered(const Spectrum& source) {
  Spectrum s = source;
  for (int i = 0; i < kGridSize; ++i) s.continuum[static_cast<std::size_t>(i)] *= std::pow(gridWavelength(i) / 550.0, -4.0);
  for (auto& [l, power] : s.lines) power *= std::pow(l / 550.0, -4.0);
  return withUnitLuminance(s);
}

double spectralRadianceOfMagnitude(double magPerArcsec2, const Band& band) {
  return std::pow(10.0, -0.4 * magPerArcsec2) * band.zeroPointWm2Nm / kArcsec2Sr;
}

double magnitudeOfSpectralRadiance(double radiance, const Band& band) {
  return -2.5 * std::log10(radiance * kArcsec2Sr / band.zeroPointWm2Nm);
}

namespace {

struct AirglowFit {
  Spectrum spectrum;
  OhEnvelope envelope;
};

const AirglowFit& airglowFit() {
  static const AirglowFit fit = [] {
    // The visible part, luminance 1, in the shares of night_diffuse.h.
    Spectrum visible = withUnitLuminance(tabulate([](double l) { return l >= 400.0 && l <= 700.0 ? 1.0 : 0.0; }));
    const double continuumShare = 1.0 - night::kAirglowGreenLineShare - night::kAirglowSodiumShare;
    for (double& v : visible.continuum) v *= continuumShare;
    visible.lines = {{557.7, night::kAirglowGreenLineShare / (kLumensPerWatt * photopic(557.7))},
                     {589.3, night::kAirglowSodiumShare / (kLumensPerWatt * photopic(589.3))}};
    // The envelope: a step P and a ramp Q from 600 nm, 1 at 930 nm.
    const Spectrum step = tabulate([](double l) { return l > kOhEnvelopeStartNm ? 1.0 : 0.0; });
    const Spectrum ramp = tabulate([](double l) {
      return l > kOhEnvelopeStartNm ? (l - kOhEnvelopeStartNm) / (kNvisMaxNm - kOhEnvelopeStartNm) : 0.0;
    });
    const double s10 = shader::kS10CdM2;
    const auto mean = [](const Spectrum& s, const Band& b) { return bandMean(s, b.fromNm, b.toNm); };
    // The airglow's share of a band, per cd/m^2 of airglow: the sky of the measured colour
    // (band minus V) at the budget's own V level, less the budget's other parts.
    auto airglowShare = [&](const Band& b, double mag, double vModel) {
      return (spectralRadianceOfMagnitude(vModel + mag - kDarkSkyV, b) - kBudgetZodiacalS10 * s10 * mean(zodiacalSpectrum(), b) -
              kBudgetStarlightS10 * s10 * mean(integratedStarlightSpectrum(), b)) /
             (night::kAirglowZenithS10 * s10);
    };
    auto budgetV = [&](const Spectrum& airglow) {
      return magnitudeOfSpectralRadiance(s10 * (night::kAirglowZenithS10 * mean(airglow, kBandV) +
                                                kBudgetZodiacalS10 * mean(zodiacalSpectrum(), kBandV) +
                                                kBudgetStarlightS10 * mean(integratedStarlightSpectrum(), kBandV)),
                                         kBandV);
    };
    // (visible + p step + q ramp) / (1 + p nP + q nQ) has the shares xR and xI: two linear
    // equations in p and q; again at the V level the result gives, until it settles.
    const double nP = integrate(step, unitTransmittance()).luminance, nQ = integrate(ramp, unitTransmittance()).luminance;
    Spectrum airglow = visible;
    double p = 0.0, q = 0.0;
    for (int pass = 0; pass < 4; ++pass) {
      const double vModel = budgetV(airglow);
      const double xR = airglowShare(kBandR, kDarkSkyR, vModel), xI = airglowShare(kBandI, kDarkSkyI, vModel);
      const double a11 = mean(step, kBandR) - xR * nP, a12 = mean(ramp, kBandR) - xR * nQ, b1 = xR - mean(visible, kBandR);
      const double a21 = mean(step, kBandI) - xI * nP, a22 = mean(ramp, kBandI) - xI * nQ, b2 = xI - mean(visible, kBandI);
      const double det = a11 * a22 - a12 * a21;
      p = (b1 * a22 - a12 * b2) / det;
      q = (a11 * b2 - a21 * b1) / det;
      Spectrum s = visible;
      for (int i = 0; i < kGridSize; ++i) {
        const auto k = static_cast<std::size_t>(i);
        s.continuum[k] += p * step.continuum[k] + q * ramp.continuum[k];
      }
      airglow = withUnitLuminance(s);
    }
    const double norm = 1.0 + p * nP + q * nQ;
    return AirglowFit{airglow, OhEnvelope{p / norm, (p + q) / norm}};
  }();
  return fit;
}

}  // namespace

const Spectrum& airglowSpectrum() { return airglowFit().spectrum; }

OhEnvelope ohEnvelope() { return airglowFit().envelope; }

}  // namespace skyig::sky::nvis
