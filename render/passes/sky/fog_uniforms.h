#pragma once
// The fog layers' uniforms of the physical sky pass (physical_sky.frag, fogLayers[]; the
// physics: physics/weather/fog_layer.glsl), located once per program and set per frame.
#include <glad/gl.h>

#include <array>

#include "physics/weather/fog_layer.h"

namespace skyig::render {

class FogUniforms {
 public:
  // The layers' array and the height's uniform are named `layers` and `height` in `program`.
  explicit FogUniforms(GLuint program, const char* layers = "fogLayers", const char* height = "cameraHeight");
  // Sets the layers (the haze below the tables' visibility, the ground fog, the precipitation)
  // and the camera's height above the ground on `program`.
  void set(GLuint program, const weather::FogLayers& layers, double cameraHeightM) const;

 private:
  struct Layer {
    GLint radius, bottom, top, extinction, asymmetry, groundAlbedo, irradiance, albedo;
  };
  std::array<Layer, weather::kFogLayerCount> at_{};
  GLint height_ = -1;
};

}  // namespace skyig::render
