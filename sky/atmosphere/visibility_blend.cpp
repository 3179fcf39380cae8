#include "sky/atmosphere/visibility_blend.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sky/atmosphere/conditions.h"
#include "sky/atmosphere/parameter_hash.h"

namespace skyig::atmosphere {

std::vector<double> defaultVisibilityStepsKm() { return {2.0, 5.0, 10.0, 20.0, 50.0}; }

ModelConfig configAtVisibility(const ModelConfig& base, double km) {
  ModelConfig c = base;
  c.medium.mieExtinctionPerM = mieExtinctionForVisibility(base.medium, km);
  return c;
}

bool differOnlyInAerosols(const ModelConfig& a, const ModelConfig& b) {
  ModelConfig same = b;
  same.medium.mieExtinctionPerM = a.medium.mieExtinctionPerM;
  return parameterHash(same) == parameterHash(a);
}

std::optional<StepBracket> bracketSteps(const std::vector<ModelConfig>& steps, const ModelConfig& target) {
  if (steps.empty()) return std::nullopt;
  for (const ModelConfig& s : steps)
    if (!differOnlyInAerosols(s, target)) return std::nullopt;
  const double beta = target.medium.mieExtinctionPerM;
  std::optional<std::size_t> below, above;  // the nearest steps with beta_M <= and >= the target's
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double b = steps[i].medium.mieExtinctionPerM;
    if (b <= beta && (!below || b > steps[*below].medium.mieExtinctionPerM)) below = i;
    if (b >= beta && (!above || b < steps[*above].medium.mieExtinctionPerM)) above = i;
  }
  if (!below) return StepBracket{*above, *above, 0.0};  // clearer than every step
  if (!above) return StepBracket{*below, *below, 0.0};  // hazier than every step
  const double b0 = steps[*below].medium.mieExtinctionPerM, b1 = steps[*above].medium.mieExtinctionPerM;
  if (b1 == b0) return StepBracket{*below, *below, 0.0};
  return StepBracket{*below, *above, (beta - b0) / (b1 - b0)};
}

namespace {

// Per channel: geometric where both are positive (the exact rule for a transmittance), linear
// where either is zero (rays into the ground, light behind the planet), which then gives the
// other's share or zero.
glm::dvec4 blend(const glm::dvec4& a, const glm::dvec4& b, double w) {
  if (w == 0.0) return a;  // a step's own tables, bit for bit
  if (w == 1.0) return b;
  glm::dvec4 out;
  for (glm::length_t c = 0; c < 4; ++c) {
    if (a[c] > 0.0 && b[c] > 0.0) out[c] = std::exp((1.0 - w) * std::log(a[c]) + w * std::log(b[c]));
    else out[c] = (1.0 - w) * a[c] + w * b[c];
  }
  return out;
}

template <typename Texture>
Texture blendTexture(const Texture& a, const Texture& b, double w) {
  if (a.texels.size() != b.texels.size()) throw std::invalid_argument("visibility blend: tables of different sizes");
  Texture out = a;
  for (std::size_t i = 0; i < out.texels.size(); ++i) out.texels[i] = blend(a.texels[i], b.texels[i], w);
  return out;
}

}  // namespace

AtmosphereModel blendModels(const AtmosphereModel& lower, const AtmosphereModel& upper, double weight,
                            const ModelConfig& target) {
  if (!(weight >= 0.0 && weight <= 1.0))
    throw std::invalid_argument("visibility blend: weight " + std::to_string(weight) + " is outside [0, 1]");
  if (!differOnlyInAerosols(lower.config(), target) || !differOnlyInAerosols(upper.config(), target))
    throw std::invalid_argument("visibility blend: the steps differ from the target in more than the aerosols");
  std::vector<GroupTables> tables(lower.groupCount());
  for (std::size_t g = 0; g < tables.size(); ++g) {
    const GroupTables& a = lower.tables(g);
    const GroupTables& b = upper.tables(g);
    tables[g].transmittance = blendTexture(a.transmittance, b.transmittance, weight);
    tables[g].irradiance = blendTexture(a.irradiance, b.irradiance, weight);
    tables[g].scattering = blendTexture(a.scattering, b.scattering, weight);
    tables[g].singleMie = blendTexture(a.singleMie, b.singleMie, weight);
  }
  AtmosphereModel blended(target, std::move(tables));
  blended.setBlendOrigin({visibilityOf(lower.config().medium), visibilityOf(upper.config().medium), weight});
  return blended;
}

}  // namespace skyig::atmosphere
