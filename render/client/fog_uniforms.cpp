#include "render/client/fog_uniforms.h"

#include <string>

namespace skyig::render {

FogUniforms::FogUniforms(GLuint program, const char* layers, const char* height) {
  for (std::size_t i = 0; i < at_.size(); ++i) {
    const std::string p = std::string(layers) + "[" + std::to_string(i) + "].";
    auto at = [&](const char* member) { return glGetUniformLocation(program, (p + member).c_str()); };
    at_[i] = {at("planet_radius"), at("bottom_height"), at("top_height"), at("extinction"), at("asymmetry"),
              at("ground_albedo"), at("top_irradiance"), at("albedo"), at("band_height"),
              at("bottom_band_height")};
  }
  height_ = glGetUniformLocation(program, height);
}

void FogUniforms::set(GLuint program, const weather::FogLayers& layers, double cameraHeightM) const {
  glProgramUniform1f(program, height_, static_cast<float>(cameraHeightM));
  for (std::size_t i = 0; i < at_.size(); ++i) {
    const Layer& l = at_[i];
    const weather::FogLayer& f = layers[i];
    glProgramUniform1f(program, l.radius, static_cast<float>(f.planet_radius));
    glProgramUniform1f(program, l.bottom, static_cast<float>(f.bottom_height));
    glProgramUniform1f(program, l.top, static_cast<float>(f.top_height));
    glProgramUniform1f(program, l.extinction, static_cast<float>(f.extinction));
    glProgramUniform1f(program, l.asymmetry, static_cast<float>(f.asymmetry));
    glProgramUniform1f(program, l.groundAlbedo, static_cast<float>(f.ground_albedo));
    glProgramUniform1f(program, l.band, static_cast<float>(f.band_height));
    glProgramUniform1f(program, l.bottomBand, static_cast<float>(f.bottom_band_height));
    const glm::vec3 irradiance(f.top_irradiance), albedo(f.albedo);
    glProgramUniform3f(program, l.irradiance, irradiance.x, irradiance.y, irradiance.z);
    glProgramUniform3f(program, l.albedo, albedo.x, albedo.y, albedo.z);
  }
}

}  // namespace skyig::render
