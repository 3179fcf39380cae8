#include "tables/visibility_blend.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "physics/atmosphere/conditions.h"
#include "tables/parameter_hash.h"

namespace skyig::atmosphere {

// From the tables' lowest visibility up (below it the rest is a fog layer, physics/weather).
std::vector<double> defaultVisibilityStepsKm() { return {10.0, 20.0, 50.0, 150.0}; }

ModelConfig configAtVisibility(const ModelConfig& base, double km) {
  ModelConfig c = base;
  c.medium = withAerosolExtinction(base.medium, mieExtinctionForVisibility(base.medium, km));
  return c;
}

bool differOnlyInAerosols(const ModelConfig& a, const ModelConfig& b) {
  ModelConfig same = b;
  same.medium.mieExtinctionPerM = a.medium.mieExtinctionPerM;
  same.medium.mieSingleScatteringAlbedo = a.medium.mieSingleScatteringAlbedo;  // follows it (conditions.h)
  return parameterHash(same) == parameterHash(a);
}

std::optional<StepBracket> bracketSteps(const std::vector<ModelConfig>& steps, const ModelConfig& target) {
  if (steps.empty()) return std::nullopt;
  for (const ModelConfig& s : steps)
    if (!differOnlyInAerosols(s, target)) return std::nullopt;
  auto beta = [&](std::size_t i) { return steps[i].medium.mieExtinctionPerM; };
  const double b = target.medium.mieExtinctionPerM;
  std::optional<std::size_t> below, above;  // the nearest steps with beta_M <= and >= the target's
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (beta(i) <= b && (!below || beta(i) > beta(*below))) below = i;
    if (beta(i) >= b && (!above || beta(i) < beta(*above))) above = i;
  }
  if (!below) return StepBracket{*above, *above, 0.0, std::nullopt};  // clearer than every step
  if (!above) return StepBracket{*below, *below, 0.0, std::nullopt};  // hazier than every step
  if (beta(*above) == beta(*below)) return StepBracket{*below, *below, 0.0, std::nullopt};
  StepBracket bracket{*below, *above, (b - beta(*below)) / (beta(*above) - beta(*below)), std::nullopt};
  // The third: the next step on the hazy side (measured the better side), else the clear one.
  std::optional<std::size_t> hazier, clearer;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (beta(i) > beta(*above) && (!hazier || beta(i) < beta(*hazier))) hazier = i;
    if (beta(i) < beta(*below) && (!clearer || beta(i) > beta(*clearer))) clearer = i;
  }
  bracket.third = hazier ? hazier : clearer;
  return bracket;
}

namespace {

// Weights k of the steps (aerosol extinctions x) such that sum k_i phi(x_i) = phi(b) for the
// first n functions of {1, x, ln x}: log f blended with them is exact for every f = A exp(-c x)
// (two steps: a transmittance) and f = A x^d exp(-c x) (three: light scattered by the aerosols
// and attenuated on the way).
std::array<double, 3> stepWeights(const std::vector<double>& x, double b) {
  const std::size_t n = x.size();
  auto phi = [](std::size_t j, double v) { return j == 0 ? 1.0 : j == 1 ? v : std::log(v); };
  // Gaussian elimination with partial pivoting on the n x n system M k = r, M_ji = phi_j(x_i).
  std::array<std::array<double, 4>, 3> m{};
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) m[j][i] = phi(j, x[i]);
    m[j][3] = phi(j, b);
  }
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(m[r][c]) > std::abs(m[p][c])) p = r;
    std::swap(m[c], m[p]);
    if (m[c][c] == 0.0) throw std::invalid_argument("visibility blend: two steps have the same aerosol extinction");
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      const double f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < 4; ++k) m[r][k] -= f * m[c][k];
    }
  }
  std::array<double, 3> k{};
  for (std::size_t i = 0; i < n; ++i) k[i] = m[i][3] / m[i][i];
  return k;
}

struct Blender {
  std::array<double, 3> k;  // of the steps' logarithms
  std::size_t n;
  double w;                 // the weight of the second step when only the first two are used

  // Per channel: geometric where the steps are positive, held between the two steps around the
  // target (the three-step fit may overshoot them); the two steps alone where the third is below
  // float32's normal range (the tables are float32: a denormal has lost its digits; it
  // underflows in thick haze first); linear between them where one is zero (rays into the
  // ground, light behind the planet).
  glm::dvec4 operator()(const glm::dvec4* a) const {
    glm::dvec4 out;
    for (glm::length_t c = 0; c < 4; ++c) {
      const double a0 = a[0][c], a1 = a[1][c];
      if (!(a0 > 0.0 && a1 > 0.0)) {
        out[c] = (1.0 - w) * a0 + w * a1;
      } else if (n == 3 && a[2][c] >= static_cast<double>(std::numeric_limits<float>::min())) {
        const double log = k[0] * std::log(a0) + k[1] * std::log(a1) + k[2] * std::log(a[2][c]);
        out[c] = std::clamp(std::exp(log), std::min(a0, a1), std::max(a0, a1));
      } else {
        out[c] = std::exp((1.0 - w) * std::log(a0) + w * std::log(a1));
      }
    }
    return out;
  }
};

// The optical-depth table (transmittance.glsl): tau = tau_gas + x L is linear in the aerosol
// extinction x, so the two steps around the target blend it exactly.
struct DepthBlender {
  double w;
  glm::dvec4 operator()(const glm::dvec4* a) const { return (1.0 - w) * a[0] + w * a[1]; }
};

template <typename Texture, typename Get, typename Blend>
Texture blendTexture(const std::vector<const AtmosphereModel*>& steps, std::size_t group, Get get, const Blend& blender) {
  Texture out = get(steps[0]->tables(group));
  for (const AtmosphereModel* s : steps)
    if (get(s->tables(group)).texels.size() != out.texels.size())
      throw std::invalid_argument("visibility blend: tables of different sizes");
  std::array<glm::dvec4, 3> texel;
  for (std::size_t t = 0; t < out.texels.size(); ++t) {
    for (std::size_t i = 0; i < steps.size(); ++i) texel[i] = get(steps[i]->tables(group)).texels[t];
    out.texels[t] = blender(texel.data());
  }
  return out;
}

}  // namespace

AtmosphereModel blendModels(const AtmosphereModel& lower, const AtmosphereModel& upper, const AtmosphereModel* third,
                            const ModelConfig& target) {
  std::vector<const AtmosphereModel*> steps{&lower, &upper};
  if (third) steps.push_back(third);
  std::vector<double> x;
  for (const AtmosphereModel* s : steps) {
    if (!differOnlyInAerosols(s->config(), target))
      throw std::invalid_argument("visibility blend: the steps differ from the target in more than the aerosols");
    x.push_back(s->config().medium.mieExtinctionPerM);
  }
  const double b = target.medium.mieExtinctionPerM;
  if (!(x[1] > x[0]) || b < x[0] || b > x[1])
    throw std::invalid_argument("visibility blend: the target's aerosol extinction " + std::to_string(b) +
                                " m^-1 is not between the steps' " + std::to_string(x[0]) + " and " + std::to_string(x[1]));
  if (third && (x[2] > x[0]) == (x[2] < x[1]))
    throw std::invalid_argument("visibility blend: the third step lies between the other two");
  // The logarithm of a zero aerosol extinction (a clean-air step) leaves the {1, x} pair.
  const bool logBasis = third && x[0] > 0.0;
  if (!logBasis) steps.resize(2), x.resize(2);
  const double w = (b - x[0]) / (x[1] - x[0]);
  Blender blender{stepWeights(x, b), steps.size(), w};
  std::vector<GroupTables> tables(lower.groupCount());
  for (std::size_t g = 0; g < tables.size(); ++g) {
    using S2 = shader::cpu_texture::sampler2D;
    using S3 = shader::cpu_texture::sampler3D;
    tables[g].transmittance = blendTexture<S2>(steps, g, [](const GroupTables& t) -> const S2& { return t.transmittance; }, DepthBlender{w});
    tables[g].irradiance = blendTexture<S2>(steps, g, [](const GroupTables& t) -> const S2& { return t.irradiance; }, blender);
    tables[g].scattering = blendTexture<S3>(steps, g, [](const GroupTables& t) -> const S3& { return t.scattering; }, blender);
    tables[g].singleMie = blendTexture<S3>(steps, g, [](const GroupTables& t) -> const S3& { return t.singleMie; }, blender);
  }
  AtmosphereModel blended(target, std::move(tables));
  blended.setBlendOrigin({visibilityOf(lower.config().medium), visibilityOf(upper.config().medium), w});
  return blended;
}

AtmosphereModel nearestStepModel(const AtmosphereModel& step, const ModelConfig& target) {
  if (!differOnlyInAerosols(step.config(), target))
    throw std::invalid_argument("visibility blend: the step differs from the target in more than the aerosols");
  std::vector<GroupTables> tables;
  for (std::size_t g = 0; g < step.groupCount(); ++g) tables.push_back(step.tables(g));
  AtmosphereModel model(target, std::move(tables));
  const double km = visibilityOf(step.config().medium);
  model.setBlendOrigin({km, km, 0.0});
  return model;
}

}  // namespace skyig::atmosphere
