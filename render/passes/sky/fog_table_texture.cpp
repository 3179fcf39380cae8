#include "render/passes/sky/fog_table_texture.h"

#include "physics/weather/fog_table.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace skyig::render {

FogTableTexture::FogTableTexture() {
  glCreateTextures(GL_TEXTURE_1D, 1, &id_);
  glTextureStorage1D(id_, 1, GL_RGBA32F, weather::kFogTableSize);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

FogTableTexture::~FogTableTexture() { glDeleteTextures(1, &id_); }

void FogTableTexture::upload(const std::vector<glm::vec4>& table) {
  if (table.size() != static_cast<std::size_t>(weather::kFogTableSize))
    throw std::logic_error("FogTableTexture: a table of " + std::to_string(table.size()) + " texels");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage1D(id_, 0, 0, weather::kFogTableSize, GL_RGBA, GL_FLOAT, table.data());
}

void FogTableTexture::use(const weather::FogLayers& layers, double heightM, GLuint unit,
                          const std::shared_ptr<const std::vector<glm::vec4>>& precomputed) {
  if (precomputed) {
    if (precomputed != uploaded_) {  // a texel copy: no table made on this thread
      upload(*precomputed);
      uploaded_ = precomputed;
      heightM_ = -1.0;  // what is there is no longer a table this texture made
    }
  } else if (uploaded_ || heightM != heightM_ || std::memcmp(&layers, &layers_, sizeof layers) != 0) {
    // The layers hold doubles only (no padding): equal bytes, equal layers.
    upload(weather::fogTable(layers, heightM));
    uploaded_.reset();
    layers_ = layers;
    heightM_ = heightM;
  }
  glBindTextureUnit(unit, id_);
}

}  // namespace skyig::render
