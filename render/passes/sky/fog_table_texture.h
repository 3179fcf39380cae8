#pragma once
// The weather's table of one frame (physics/weather/fog_table.h) as the 1D texture the physical sky
// pass reads at SKYIG_UNIT_FOG_TABLE (RGBA32F: the layers' own light, the transmittance behind
// them). Filled on the CPU from the same GLSL the shader would otherwise run per pixel, whenever
// the layers or the eye's height change.
#include <glad/gl.h>

#include "physics/weather/fog_layer.h"

#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace skyig::render {

class FogTableTexture {
 public:
  FogTableTexture();  // needs the GL context current
  ~FogTableTexture();
  FogTableTexture(const FogTableTexture&) = delete;
  FogTableTexture& operator=(const FogTableTexture&) = delete;

  // The table of `layers` for an eye heightM above the ground, bound to `unit`: `precomputed`
  // (made with the sky state for those layers at that height) uploaded when it is not the one
  // already there; without it, made here whenever the layers or the height change.
  void use(const weather::FogLayers& layers, double heightM, GLuint unit,
           const std::shared_ptr<const std::vector<glm::vec4>>& precomputed = nullptr);
  GLuint id() const { return id_; }

 private:
  void upload(const std::vector<glm::vec4>& table);
  GLuint id_ = 0;
  weather::FogLayers layers_{};
  double heightM_ = -1.0;
  std::shared_ptr<const std::vector<glm::vec4>> uploaded_;  // held: its address cannot be reused meanwhile
};

}  // namespace skyig::render
