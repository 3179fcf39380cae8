#include "sky/nvis_weights.h"

#include "physics/goggle/nvis_sky.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace skyig::sky {

namespace {

double pick(const nvis::NvisRadiance& r, nvis::NvisClass c) { return c == nvis::NvisClass::A ? r.a : r.b; }

// NVIS radiance per cd/m^2 of a light of spectrum `s` above the air seen through `t`.
double perLuminance(const nvis::Spectrum& s, const nvis::Transmittance& t, nvis::NvisClass c) {
  return pick(nvis::nvisFromLuminance(s, t, 1.0), c);
}

// `v` (normalised) lifted to the horizon if it looks down: a light below it is not drawn, and
// the channel's centre may look at the ground, where the diffuse lights do not reach; their
// colour is then the horizon's (a zero transmittance would give no weight at all).
glm::dvec3 aboveHorizon(const glm::dvec3& v) {
  glm::dvec3 u = glm::length(v) > 0.0 ? glm::normalize(v) : glm::dvec3(0.0, 1.0, 0.0);
  u.z = std::max(u.z, 0.0);
  return glm::length(u) > 1e-9 ? glm::normalize(u) : glm::dvec3(0.0, 1.0, 0.0);
}

constexpr double kTableMinK = 1500.0;
constexpr double kTableMaxK = 50000.0;
constexpr int kTableSize = 256;

struct BlackbodyTable {
  std::array<std::array<double, kTableSize>, 2> perLux{};
  BlackbodyTable() {
    const nvis::Transmittance unit = nvis::unitTransmittance();
    for (int i = 0; i < kTableSize; ++i) {
      const double t = kTableMinK * std::pow(kTableMaxK / kTableMinK, static_cast<double>(i) / (kTableSize - 1));
      const nvis::NvisRadiance r = nvis::nvisFromLuminance(nvis::blackbodySpectrum(t), unit, 1.0);
      perLux[0][static_cast<std::size_t>(i)] = r.a;
      perLux[1][static_cast<std::size_t>(i)] = r.b;
    }
  }
};

}  // namespace

double nvisHazeExtinctionScale(nvis::NvisClass nvisClass) {
  constexpr double kAngstromExponent = 1.3;
  double weighted = 0.0, total = 0.0;
  for (double nm = nvis::kNvisMinNm; nm <= nvis::kNvisMaxNm; nm += 1.0) {
    const double g = nvis::nvisResponse(nvisClass, nm);
    weighted += nm * g;
    total += g;
  }
  return std::pow(weighted / total / 550.0, -kAngstromExponent);
}

weather::FogLayers goggleFogLayers(const SkyState& state, nvis::NvisClass nvisClass) {
  const FogState& fog = state.fog;
  const NvisWeights w = nvisWeights(nvisClass == nvis::NvisClass::A ? SpectralBand::NvisClassA : SpectralBand::NvisClassB,
                                    state, glm::dvec3(0.0, 0.0, 1.0));
  weather::FogLayers layers = fog.sunlit;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    // Grey droplets keep the spectrum of what lights the top: the direct light and its sky in
    // their shares of its lux (the sky's weights are along no view: they carry no transmittance).
    const double sun = fog.sunShare[i] * w.sunDisc + (1.0 - fog.sunShare[i]) * w.sunlitSky;
    const double moon = fog.moonShare[i] * w.moon + (1.0 - fog.moonShare[i]) * w.moonlitSky;
    layers[i].top_irradiance = sun * fog.sunlit[i].top_irradiance + moon * fog.moonIrradiance[i];
  }
  layers[0].extinction *= nvisHazeExtinctionScale(nvisClass);  // the haze below the tables (FogState's order)
  return layers;
}

std::shared_ptr<const std::vector<glm::vec4>> fogTableFor(const FogState& fog, SpectralBand band) {
  if (band == SpectralBand::Visible) return fog.tables.eye;
  return band == SpectralBand::NvisClassA ? fog.tables.nvisA : fog.tables.nvisB;
}

std::shared_ptr<const std::vector<glm::vec4>> clearFogTableFor(const FogState& fog, SpectralBand band) {
  if (band == SpectralBand::Visible) return fog.tables.clearEye;
  return band == SpectralBand::NvisClassA ? fog.tables.clearNvisA : fog.tables.clearNvisB;
}

nvis::NvisClass nvisClassOf(SpectralBand band) {
  if (band == SpectralBand::Visible) throw std::invalid_argument("nvisClassOf: the visible band has no NVIS class");
  return band == SpectralBand::NvisClassA ? nvis::NvisClass::A : nvis::NvisClass::B;
}

double nvisPerLuxOfBlackbody(double temperatureK, nvis::NvisClass nvisClass) {
  static const BlackbodyTable table;
  if (!std::isfinite(temperatureK)) throw std::invalid_argument("nvisPerLuxOfBlackbody: temperature is not finite");
  const double t = std::clamp(temperatureK, kTableMinK, kTableMaxK);
  const double x = std::log(t / kTableMinK) / std::log(kTableMaxK / kTableMinK) * (kTableSize - 1);
  const int i = std::min(static_cast<int>(x), kTableSize - 2);
  const double f = x - i;
  const auto& row = table.perLux[nvisClass == nvis::NvisClass::A ? 0 : 1];
  return row[static_cast<std::size_t>(i)] * (1.0 - f) + row[static_cast<std::size_t>(i + 1)] * f;
}

NvisWeights nvisWeights(SpectralBand band, const SkyState& state, const glm::dvec3& viewEnu) {
  if (band == SpectralBand::Visible) return {};
  const nvis::NvisClass c = nvisClassOf(band);
  const atmosphere::ExtinctionProfile* extinction = state.extinction.get();
  const nvis::Transmittance unit = nvis::unitTransmittance();
  const nvis::Transmittance alongView = nvis::transmittanceAlong(extinction, aboveHorizon(viewEnu));
  NvisWeights w;
  w.nvis = true;
  // As the probe weights them (sky/night_probe.cpp): the skies without a transmittance (their
  // light is scattered along the whole path), the discs and the diffuse night through the air.
  w.sunlitSky = perLuminance(nvis::sunlitSkySpectrum(), unit, c);
  w.moonlitSky = perLuminance(nvis::moonlitSkySpectrum(), unit, c);
  const glm::dvec3 sun = aboveHorizon(enuDirection(state.sunAzimuth, state.sunAltitude));
  w.sunDisc = perLuminance(nvis::sunlightSpectrum(), nvis::transmittanceAlong(extinction, sun), c);
  w.moon = perLuminance(nvis::moonlightSpectrum(), nvis::transmittanceAlong(extinction, aboveHorizon(state.moonDirection)), c);
  w.airglow = perLuminance(nvis::airglowSpectrum(), alongView, c);
  w.zodiacal = perLuminance(nvis::zodiacalSpectrum(), alongView, c);
  w.milkyWay = perLuminance(nvis::integratedStarlightSpectrum(), alongView, c);
  w.nightGround = w.airglow;
  return w;
}

}  // namespace skyig::sky
