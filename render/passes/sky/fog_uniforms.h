#pragma once
// The fog layers' uniforms of the physical sky pass (physical_sky.frag, fogLayers[2]; the
// physics: physics/weather/fog_layer.glsl), located once per program and set per frame.
#include <glad/gl.h>

#include <array>

#include "physics/weather/fog_layer.h"

namespace skyig::render {

class FogUniforms {
 public:
  explicit FogUniforms(GLuint program);
  // Sets the two layers (the haze below the tables' visibility, the ground fog) and the camera's
  // height above the ground on `program`.
  void set(GLuint program, const std::array<weather::FogLayer, 2>& layers, double cameraHeightM) const;

 private:
  struct Layer {
    GLint radius, bottom, top, extinction, asymmetry, albedo, irradiance;
  };
  std::array<Layer, 2> at_{};
  GLint height_ = -1;
};

}  // namespace skyig::render
