#include "render/passes/common/extinction_texture.h"

#include <glm/vec3.hpp>

#include <vector>

namespace skyig::render {

ExtinctionTexture::ExtinctionTexture() {
  glCreateTextures(GL_TEXTURE_1D, 1, &id_);
  glTextureStorage1D(id_, 1, GL_RGB32F, atmosphere::ExtinctionProfile::kSamples);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

ExtinctionTexture::~ExtinctionTexture() { glDeleteTextures(1, &id_); }

void ExtinctionTexture::use(const std::shared_ptr<const atmosphere::ExtinctionProfile>& profile) {
  if (uploaded_ && profile == profile_) return;
  std::vector<glm::vec3> table(atmosphere::ExtinctionProfile::kSamples, glm::vec3(1.0f));
  if (profile) {
    table = profile->rec709Table();
  } else {  // the lower half of the samples is below the horizon
    for (int i = 0; i < atmosphere::ExtinctionProfile::kSamples / 2; ++i) table[static_cast<std::size_t>(i)] = glm::vec3(0.0f);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage1D(id_, 0, 0, atmosphere::ExtinctionProfile::kSamples, GL_RGB, GL_FLOAT, table.data());
  profile_ = profile;
  uploaded_ = true;
}

}  // namespace skyig::render
