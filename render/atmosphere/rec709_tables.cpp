#include "render/atmosphere/rec709_tables.h"

namespace skyig::atmosphere {

Rec709Tables combineToRec709(const AtmosphereModel& model) {
  const std::size_t n = model.wavelengths().size();
  Rec709Tables out{model.tables(0).scattering, model.tables(0).single_mie};
  for (auto& t : out.scattering.texels) t = glm::dvec4(0.0);
  for (auto& t : out.single_mie.texels) t = glm::dvec4(0.0);
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
        out.single_mie.texels[k] += glm::dvec4(rgb[i] * t.single_mie.texels[k][c], 0.0);
      }
    }
  }
  return out;
}

glm::dvec3 skyRec709(const AtmosphereModel& model, const Rec709Tables& tables,
                     const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun) {
  return shader::skyRec709(model.parameters(0), tables.scattering, tables.single_mie, camera,
                           view, sun);
}

}  // namespace skyig::atmosphere
