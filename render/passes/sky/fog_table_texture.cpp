#include "render/passes/sky/fog_table_texture.h"

#include "physics/weather/fog_table.h"

#include <cstring>

namespace skyig::render {

FogTableTexture::FogTableTexture() {
  glCreateTextures(GL_TEXTURE_1D, 1, &id_);
  glTextureStorage1D(id_, 1, GL_RGBA32F, weather::kFogTableSize);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

FogTableTexture::~FogTableTexture() { glDeleteTextures(1, &id_); }

void FogTableTexture::use(const weather::FogLayers& layers, double heightM, GLuint unit) {
  // The layers hold doubles only (no padding): equal bytes, equal layers.
  if (heightM != heightM_ || std::memcmp(&layers, &layers_, sizeof layers) != 0) {
    const std::vector<glm::vec4> table = weather::fogTable(layers, heightM);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage1D(id_, 0, 0, weather::kFogTableSize, GL_RGBA, GL_FLOAT, table.data());
    layers_ = layers;
    heightM_ = heightM;
  }
  glBindTextureUnit(unit, id_);
}

}  // namespace skyig::render
