#include "physics/atmosphere/model.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::atmosphere {

namespace {

std::array<double, 4> groupWavelengths(const std::vector<double>& w, std::size_t group) {
  // The last group is padded by repeating the last wavelength.
  std::array<double, 4> out{};
  for (std::size_t i = 0; i < 4; ++i) out[i] = w[std::min(group * 4 + i, w.size() - 1)];
  return out;
}

bool sameSize(const shader::cpu_texture::sampler2D& t, double w, double h) {
  return t.width == static_cast<int>(w) && t.height == static_cast<int>(h) &&
         t.texels.size() == static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height);
}

bool sameSize(const shader::cpu_texture::sampler3D& t, const AtmosphereParameters& a) {
  return t.width == static_cast<int>(a.scattering_nu_size * a.scattering_mu_s_size) &&
         t.height == static_cast<int>(a.scattering_mu_size) &&
         t.depth == static_cast<int>(a.scattering_r_size) &&
         t.texels.size() == static_cast<std::size_t>(t.width) *
                                static_cast<std::size_t>(t.height) *
                                static_cast<std::size_t>(t.depth);
}

}  // namespace

AtmosphereModel::AtmosphereModel(const ModelConfig& config)
    : config_(config), converter_(config.wavelengthsNm) {
  setUp();
  tables_.resize(params_.size());
  for (std::size_t g = 0; g < params_.size(); ++g) {
    tables_[g] = precomputeGroup(params_[g], config_.options);
  }
}

AtmosphereModel::AtmosphereModel(const ModelConfig& config, std::vector<GroupTables> tables)
    : config_(config), converter_(config.wavelengthsNm), tables_(std::move(tables)) {
  setUp();
  if (tables_.size() != params_.size()) {
    throw std::invalid_argument("AtmosphereModel: " + std::to_string(tables_.size()) +
                                " table groups given, expected " +
                                std::to_string(params_.size()));
  }
  for (std::size_t g = 0; g < params_.size(); ++g) {
    const auto& a = params_[g];
    const auto& t = tables_[g];
    if (!sameSize(t.transmittance, a.transmittance_width, a.transmittance_height) ||
        !sameSize(t.irradiance, a.irradiance_width, a.irradiance_height) ||
        !sameSize(t.scattering, a) || !sameSize(t.singleMie, a)) {
      throw std::invalid_argument("AtmosphereModel: tables of group " + std::to_string(g) +
                                  " do not match the configured table sizes");
    }
  }
}

std::vector<AtmosphereParameters> groupParameters(const ModelConfig& config) {
  validate(config.medium);
  validate(config.sizes);
  const auto& w = config.wavelengthsNm;
  std::vector<AtmosphereParameters> params;
  for (std::size_t g = 0; g < (w.size() + 3) / 4; ++g)
    params.push_back(makeParameters(config.medium, groupWavelengths(w, g), config.sizes));
  return params;
}

void AtmosphereModel::setUp() { params_ = groupParameters(config_); }

template <typename Fn>
Spectrum AtmosphereModel::perGroup(Fn fn, Spectrum* second) const {
  const std::size_t n = config_.wavelengthsNm.size();
  Spectrum out(n);
  if (second) second->assign(n, 0.0);
  for (std::size_t g = 0; g < params_.size(); ++g) {
    glm::dvec4 extra(0.0);
    const glm::dvec4 v = fn(params_[g], tables_[g], extra);
    for (std::size_t i = 0; i < 4 && g * 4 + i < n; ++i) {
      out[g * 4 + i] = v[static_cast<glm::length_t>(i)];
      if (second) (*second)[g * 4 + i] = extra[static_cast<glm::length_t>(i)];
    }
  }
  return out;
}

Spectrum AtmosphereModel::skyRadiance(const glm::dvec3& camera, const glm::dvec3& view,
                                      const glm::dvec3& sun, Spectrum* transmittance) const {
  return perGroup(
      [&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4& tr) {
        return shader::skyRadiance(a, t.transmittance, t.scattering, t.singleMie, camera, view,
                                   sun, tr);
      },
      transmittance);
}

Spectrum AtmosphereModel::skyRadianceToPoint(const glm::dvec3& camera, const glm::dvec3& point,
                                             const glm::dvec3& sun,
                                             Spectrum* transmittance) const {
  return perGroup(
      [&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4& tr) {
        return shader::skyRadianceToPoint(a, t.transmittance, t.scattering, t.singleMie, camera,
                                          point, sun, tr);
      },
      transmittance);
}

Spectrum AtmosphereModel::groundRadiance(const glm::dvec3& camera, const glm::dvec3& groundPoint,
                                         const glm::dvec3& sun, Spectrum* transmittance) const {
  return perGroup(
      [&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4& tr) {
        return shader::groundRadiance(a, t.transmittance, t.scattering, t.singleMie,
                                      t.irradiance, camera, groundPoint, a.ground_albedo, sun,
                                      tr);
      },
      transmittance);
}

Spectrum AtmosphereModel::sunIrradiance(const glm::dvec3& point, const glm::dvec3& normal,
                                        const glm::dvec3& sun) const {
  return perGroup([&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4&) {
    glm::dvec4 sky;
    return shader::sunAndSkyIrradiance(a, t.transmittance, t.irradiance, point, normal, sun, sky);
  });
}

Spectrum AtmosphereModel::skyIrradiance(const glm::dvec3& point, const glm::dvec3& normal,
                                        const glm::dvec3& sun) const {
  return perGroup([&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4&) {
    glm::dvec4 sky;
    shader::sunAndSkyIrradiance(a, t.transmittance, t.irradiance, point, normal, sun, sky);
    return sky;
  });
}

Spectrum AtmosphereModel::transmittanceToTop(double r, double mu) const {
  return perGroup([&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4&) {
    if (shader::rayIntersectsGround(a, r, mu)) return glm::dvec4(0.0);
    return shader::transmittanceToTopAtmosphereBoundary(a, t.transmittance, r, mu);
  });
}

Spectrum AtmosphereModel::solarRadiance() const {
  return perGroup([&](const AtmosphereParameters& a, const GroupTables&, glm::dvec4&) {
    return shader::solarRadiance(a);
  });
}

Spectrum AtmosphereModel::sunDiscRadiance(const glm::dvec3& camera, const glm::dvec3& view,
                                          const glm::dvec3& sun) const {
  return perGroup([&](const AtmosphereParameters& a, const GroupTables& t, glm::dvec4&) {
    return shader::sunDiscRadiance(a, t.transmittance, camera, view, sun);
  });
}

glm::dvec3 observerPosition(const Medium& medium, double altitudeM) {
  return {0.0, 0.0, medium.bottomRadiusM + altitudeM};
}

glm::dvec3 directionFromAngles(double zenithRad, double azimuthRad) {
  return {std::sin(zenithRad) * std::cos(azimuthRad),
          std::sin(zenithRad) * std::sin(azimuthRad), std::cos(zenithRad)};
}

}  // namespace skyig::atmosphere
