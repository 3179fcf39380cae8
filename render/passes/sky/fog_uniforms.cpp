#include "render/passes/sky/fog_uniforms.h"

#include <string>

namespace skyig::render {

FogUniforms::FogUniforms(GLuint program) {
  for (std::size_t i = 0; i < at_.size(); ++i) {
    const std::string p = "fogLayers[" + std::to_string(i) + "].";
    auto at = [&](const char* member) { return glGetUniformLocation(program, (p + member).c_str()); };
    at_[i] = {at("planet_radius"), at("bottom_height"), at("top_height"), at("extinction"), at("asymmetry"),
              at("ground_albedo"), at("top_irradiance")};
  }
  height_ = glGetUniformLocation(program, "cameraHeight");
}

void FogUniforms::set(GLuint program, const std::array<weather::FogLayer, 2>& layers, double cameraHeightM) const {
  glProgramUniform1f(program, height_, static_cast<float>(cameraHeightM));
  for (std::size_t i = 0; i < at_.size(); ++i) {
    const Layer& l = at_[i];
    const weather::FogLayer& f = layers[i];
    glProgramUniform1f(program, l.radius, static_cast<float>(f.planet_radius));
    glProgramUniform1f(program, l.bottom, static_cast<float>(f.bottom_height));
    glProgramUniform1f(program, l.top, static_cast<float>(f.top_height));
    glProgramUniform1f(program, l.extinction, static_cast<float>(f.extinction));
    glProgramUniform1f(program, l.asymmetry, static_cast<float>(f.asymmetry));
    glProgramUniform1f(program, l.albedo, static_cast<float>(f.ground_albedo));
    glProgramUniform3f(program, l.irradiance, static_cast<float>(f.top_irradiance.x),
                       static_cast<float>(f.top_irradiance.y), static_cast<float>(f.top_irradiance.z));
  }
}

}  // namespace skyig::render
