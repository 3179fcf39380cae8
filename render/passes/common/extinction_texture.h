#pragma once
// The observer's extinction profile (physics/atmosphere/extinction_profile.h) as a 1D texture,
// for the passes of what lies beyond the atmosphere (moon, Milky Way, zodiacal light, airglow):
// re-uploaded only when the state brings another profile.
#include "physics/atmosphere/extinction_profile.h"

#include <glad/gl.h>

#include <memory>

namespace skyig::render {

class ExtinctionTexture {
 public:
  // Needs the GL context current.
  ExtinctionTexture();
  ~ExtinctionTexture();
  ExtinctionTexture(const ExtinctionTexture&) = delete;
  ExtinctionTexture& operator=(const ExtinctionTexture&) = delete;

  // Holds `profile` (kept alive, so a new profile at the same address is still seen as new).
  // Null means no atmosphere: all that is above the horizon arrives, the ground hides the rest,
  // as a real profile's table does below the horizon.
  void use(const std::shared_ptr<const atmosphere::ExtinctionProfile>& profile);
  void bind(GLuint unit) const { glBindTextureUnit(unit, id_); }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
  std::shared_ptr<const atmosphere::ExtinctionProfile> profile_;
  bool uploaded_ = false;
};

}  // namespace skyig::render
