#include "physics/atmosphere/precompute/rec709_tables.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace skyig::atmosphere {

Rec709Tables combineToRec709(const AtmosphereModel& model) {
  const std::size_t n = model.wavelengths().size();
  Rec709Tables out{model.tables(0).scattering, model.tables(0).singleMie};
  for (auto& t : out.scattering.texels) t = glm::dvec4(0.0);
  for (auto& t : out.singleMie.texels) t = glm::dvec4(0.0);
  for (std::size_t g = 0; g < model.groupCount(); ++g) {
    // Rec.709 per unit spectral radiance of each of the group's wavelengths (padding: none).
    glm::dvec3 rgb[4];
    for (std::size_t i = 0; i < 4; ++i) {
      rgb[i] = g * 4 + i < n ? xyzToRec709(model.converter().weight(g * 4 + i)) : glm::dvec3(0.0);
    }
    const GroupTables& t = model.tables(g);
    for (std::size_t k = 0; k < out.scattering.texels.size(); ++k) {
      for (std::size_t i = 0; i < 4; ++i) {
        const auto c = static_cast<glm::length_t>(i);
        out.scattering.texels[k] += glm::dvec4(rgb[i] * t.scattering.texels[k][c], 0.0);
        out.singleMie.texels[k] += glm::dvec4(rgb[i] * t.singleMie.texels[k][c], 0.0);
      }
    }
  }
  return out;
}

glm::dvec3 skyRec709(const AtmosphereModel& model, const Rec709Tables& tables,
                     const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun) {
  return shader::skyRec709(model.parameters(0), tables.scattering, tables.singleMie, camera,
                           view, sun);
}

glm::dvec3 moonlitSkyRec709(const AtmosphereModel& model, const glm::dvec3& camera,
                            const glm::dvec3& view, const glm::dvec3& moonDirection,
                            const glm::dvec3& moonlightScale) {
  return model.converter().toRec709(model.skyRadiance(camera, view, moonDirection)) * moonlightScale;
}

namespace {

constexpr double kTableScale = 0.0625;  // REC709_TABLE_SCALE in rendering_rec709.glsl

double wavelengthValue(const glm::dvec4& v, std::size_t i) { return v[static_cast<glm::length_t>(i % 4)]; }

// Saturating: a value past the largest half float (65504) is held there, not turned into an
// infinity that the phase functions and blends then make NaN. Clear skies never reach it (the
// largest texel is about half of it); in haze of 2 km and less a few texels of the multiple
// scattering's forward peak (divided by the Rayleigh phase, as C* stores it) do: 4 of 16384 at
// 2 km, 226 at 0.5 km (docs/atmosphere.md).
std::uint16_t half(double v) {
  return static_cast<std::uint16_t>(glm::packHalf1x16(static_cast<float>(std::clamp(v, -65504.0, 65504.0))));
}

double fromHalf(std::uint16_t h) { return static_cast<double>(glm::unpackHalf1x16(h)); }

}  // namespace

Rec709Packer::Rec709Packer(const AtmosphereModel& model) : model_(model) {
  const std::size_t n = model.wavelengths().size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 xyz = model.converter().weight(i);
    rgb_.push_back(xyzToRec709(xyz));
    xyzSun_.push_back(xyz * wavelengthValue(model.parameters(i / 4).solar_irradiance, i));
  }
  for (std::size_t g = 1; g < model.groupCount(); ++g)
    if (model.parameters(g).ground_albedo.x != model.parameters(0).ground_albedo.x)
      throw std::invalid_argument("Rec709Packer: the ground albedo must be grey");
}

int Rec709Packer::slices() const { return model_.tables(0).scattering.depth; }

PackedRec709Tables Rec709Packer::packSmallTables() const {
  PackedRec709Tables out;
  const std::size_t n = xyzSun_.size();
  glm::dvec3 sunXyz(0.0), alpha(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    sunXyz += xyzSun_[i];
    alpha += xyzSun_[i] * wavelengthValue(model_.parameters(i / 4).limb_darkening_exponent, i);
  }
  out.solarIrradianceXyz = sunXyz;
  out.limbDarkeningXyz = alpha / sunXyz;
  out.groundAlbedo = model_.parameters(0).ground_albedo.x;
  out.transmittanceXyz = model_.tables(0).transmittance;
  out.irradianceXyz = model_.tables(0).irradiance;
  // The table holds optical depths (transmittance.glsl): per channel the depth whose exponential
  // is the sun-weighted mean of the wavelengths' transmittances, by log-sum-exp, so a 1000-deep
  // horizon in fog keeps its digits where exp(-tau) underflows.
  for (std::size_t k = 0; k < out.transmittanceXyz.texels.size(); ++k) {
    double tauMin = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) tauMin = std::min(tauMin, wavelengthValue(model_.tables(i / 4).transmittance.texels[k], i));
    glm::dvec3 t(0.0);
    for (std::size_t i = 0; i < n; ++i)
      t += xyzSun_[i] * std::exp(tauMin - wavelengthValue(model_.tables(i / 4).transmittance.texels[k], i));
    const glm::dvec3 tau = tauMin - glm::log(glm::max(t / sunXyz, glm::dvec3(std::numeric_limits<double>::min())));
    // Float, as uploaded; alpha is a depth of zero (a transmittance of one).
    out.transmittanceXyz.texels[k] = glm::dvec4(glm::dvec3(glm::vec3(tau)), 0.0);
  }
  for (std::size_t k = 0; k < out.irradianceXyz.texels.size(); ++k) {
    glm::dvec3 e(0.0);
    for (std::size_t i = 0; i < n; ++i)
      e += model_.converter().weight(i) * wavelengthValue(model_.tables(i / 4).irradiance.texels[k], i);
    out.irradianceXyz.texels[k] = glm::dvec4(glm::dvec3(glm::vec3(e)), 0.0);
  }
  return out;
}

void Rec709Packer::packSlice(int z, std::vector<std::uint16_t>& scattering,
                             std::vector<std::uint16_t>& singleMieRg) const {
  const auto& first = model_.tables(0).scattering;
  if (z < 0 || z >= first.depth) throw std::invalid_argument("Rec709Packer: slice " + std::to_string(z) + " out of range");
  const std::size_t texels = static_cast<std::size_t>(first.width) * static_cast<std::size_t>(first.height);
  const std::size_t offset = static_cast<std::size_t>(z) * texels;
  scattering.resize(texels * 4);
  singleMieRg.resize(texels * 2);
  const std::size_t n = rgb_.size();
  for (std::size_t k = 0; k < texels; ++k) {
    glm::dvec3 s(0.0), m(0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const GroupTables& t = model_.tables(i / 4);
      s += rgb_[i] * wavelengthValue(t.scattering.texels[offset + k], i);
      m += rgb_[i] * wavelengthValue(t.singleMie.texels[offset + k], i);
    }
    s *= kTableScale;
    m *= kTableScale;
    scattering[4 * k + 0] = half(s.x);
    scattering[4 * k + 1] = half(s.y);
    scattering[4 * k + 2] = half(s.z);
    scattering[4 * k + 3] = half(m.z);
    singleMieRg[2 * k + 0] = half(m.x);
    singleMieRg[2 * k + 1] = half(m.y);
  }
}

PackedRec709Tables packRec709(const AtmosphereModel& model) {
  const Rec709Packer packer(model);
  PackedRec709Tables out = packer.packSmallTables();
  const auto& first = model.tables(0).scattering;
  out.scattering = shader::cpu_texture::sampler3D(first.width, first.height, first.depth);
  out.singleMieRg = out.scattering;
  std::vector<std::uint16_t> s, m;
  const std::size_t texels = static_cast<std::size_t>(first.width) * static_cast<std::size_t>(first.height);
  for (int z = 0; z < first.depth; ++z) {
    packer.packSlice(z, s, m);
    for (std::size_t k = 0; k < texels; ++k) {
      const std::size_t at = static_cast<std::size_t>(z) * texels + k;
      out.scattering.texels[at] = {fromHalf(s[4 * k]), fromHalf(s[4 * k + 1]), fromHalf(s[4 * k + 2]), fromHalf(s[4 * k + 3])};
      out.singleMieRg.texels[at] = {fromHalf(m[2 * k]), fromHalf(m[2 * k + 1]), 0.0, 1.0};
    }
  }
  return out;
}

glm::dvec3 packedSkyRec709(const AtmosphereModel& model, const PackedRec709Tables& tables,
                           const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& light) {
  return shader::packedSkyRec709(model.parameters(0), tables.scattering, tables.singleMieRg, camera, view, light);
}

glm::dvec3 packedRadianceRec709(const AtmosphereModel& model, const PackedRec709Tables& tables,
                                const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun) {
  return shader::packedViewRec709(model.parameters(0), tables.transmittanceXyz, tables.scattering,
                                  tables.singleMieRg, tables.irradianceXyz, tables.solarIrradianceXyz,
                                  tables.limbDarkeningXyz, tables.groundAlbedo, camera, view, sun, true);
}

}  // namespace skyig::atmosphere
