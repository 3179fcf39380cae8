#pragma once
// The weather layers' uniforms of a client's program that pastes skyig's aerial perspective
// (client_aerial_perspective.glsl, skyig_fog[]; the physics: physics/weather/fog_layer.glsl), located
// once per bind. The sky pass reads the layers from a table instead (render/passes/sky/fog_table_texture.h).
#include <glad/gl.h>

#include <array>

#include "physics/weather/fog_layer.h"

namespace skyig::render {

class FogUniforms {
 public:
  // The layers' array and the height's uniform are named `layers` and `height` in `program`.
  FogUniforms(GLuint program, const char* layers, const char* height);
  // Sets the layers (the haze below the tables' visibility, the ground fog, the precipitation)
  // and the camera's height above the ground on `program`.
  void set(GLuint program, const weather::FogLayers& layers, double cameraHeightM) const;

 private:
  struct Layer {
    GLint radius, bottom, top, extinction, asymmetry, groundAlbedo, irradiance, albedo, band, bottomBand;
  };
  std::array<Layer, weather::kFogLayerCount> at_{};
  GLint height_ = -1;
};

}  // namespace skyig::render
