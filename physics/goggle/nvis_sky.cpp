#include "physics/goggle/nvis_sky.h"

#include "physics/night/diffuse_physics.h"
#include "physics/common/hemisphere_grid.h"
#include "physics/night/milky_way_map.h"
#include "physics/night/night_diffuse.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::sky::nvis {

namespace {

double luminanceOf(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

NvisLight lightOf(const Spectrum& s, const Transmittance& t, double luminance) {
  return {luminance, nvisFromLuminance(s, t, luminance)};
}

}  // namespace

Transmittance transmittanceAlong(const atmosphere::ExtinctionProfile* extinction, const glm::dvec3& viewEnu) {
  const double n = glm::length(viewEnu);
  if (!std::isfinite(n) || n == 0.0) throw std::invalid_argument("NVIS: view direction is zero or not finite");
  const double z = std::clamp(viewEnu.z / n, -1.0, 1.0);
  if (!extinction) {
    Transmittance t{};
    if (z >= 0.0) t.fill(1.0);
    return t;
  }
  return transmittanceOf(*extinction, std::asin(z));
}

const Spectrum& moonlitSkySpectrum() {
  static const Spectrum s = rayleighScattered(moonlightSpectrum());
  return s;
}

const Spectrum& sunlitSkySpectrum() {
  static const Spectrum s = rayleighScattered(sunlightSpectrum());
  return s;
}

NvisLight pointSourceNvis(const night::PointSource& source, const atmosphere::ExtinctionProfile* extinction) {
  return lightOf(blackbodySpectrum(source.temperatureK), transmittanceAlong(extinction, source.direction),
                 source.illuminanceLux);
}

NvisLight pointSourcesNvis(const night::StarField& field, const atmosphere::ExtinctionProfile* extinction,
                           const glm::dvec3& direction, double coneRadiusRad) {
  const double length = glm::length(direction);
  if (!std::isfinite(length) || length <= 0.0) throw std::invalid_argument("NVIS star probe: direction is zero or not finite");
  const glm::dvec3 d = direction / length;
  const double cosRadius = std::cos(coneRadiusRad);
  const double solidAngle = 2.0 * std::numbers::pi * (1.0 - cosRadius);
  NvisLight out;
  for (const auto* list : {&field.stars, &field.planets})
    for (const night::PointSource& p : *list)
      if (glm::dot(p.direction, d) >= cosRadius) out += pointSourceNvis(p, extinction);
  out.luminance /= solidAngle;
  out.nvis = (1.0 / solidAngle) * out.nvis;
  return out;
}

NvisLight moonIrradiance(double moonLux, const atmosphere::ExtinctionProfile* extinction, const glm::dvec3& moonDirection) {
  return lightOf(moonlightSpectrum(), transmittanceAlong(extinction, moonDirection), moonLux);
}

NvisLight MoonlessSkyIrradiance::total() const {
  NvisLight t = airglow;
  t += zodiacal;
  t += integratedStarlight;
  t += stars;
  return t;
}

MoonlessSkyIrradiance moonlessSkyIrradiance(const ephemeris::SkyEphemeris& ephemeris,
                                            std::shared_ptr<const atmosphere::ExtinctionProfile> extinction,
                                            const night::StarField* stars) {
  MoonlessSkyIrradiance out;
  constexpr int kMu = 8, kPhi = 16;  // as nightDiffuseIlluminance
  const night::NightDiffuseSky sky = night::makeNightDiffuseSky(ephemeris, extinction, false);
  const double floorCdM2 = shader::s10ToCdM2(night::kPoleS10);
  const double weight = 2.0 * std::numbers::pi / (kMu * kPhi);
  forEachHemisphereDirection(kMu, kPhi, [&](const glm::dvec3& v) {
    const Transmittance t = transmittanceAlong(extinction.get(), v);
    const night::NightDiffuseRadiance r = night::nightDiffuseRadiance(sky, v);
    const double k = weight * v.z;
    out.airglow += lightOf(airglowSpectrum(), t, k * luminanceOf(r.airglow));
    out.zodiacal += lightOf(zodiacalSpectrum(), t, k * luminanceOf(r.zodiacal));
    out.integratedStarlight +=
        lightOf(integratedStarlightSpectrum(), t, k * floorCdM2 * luminanceOf(night::nightExtinction(sky, v)));
  });
  if (stars)
    for (const auto* list : {&stars->stars, &stars->planets})
      for (const night::PointSource& p : *list) {
        const NvisLight l = pointSourceNvis(p, extinction.get());
        const double c = std::max(p.direction.z, 0.0);
        out.stars += {c * l.luminance, c * l.nvis};
      }
  return out;
}

}  // namespace skyig::sky::nvis
