#pragma once
// The moon's GL pass (shaders/passes/moon.*): a quad around the disc, added onto the HDR target
// after the sky pass, from the same numbers as the CPU side (render/night/moon_disc.h).
#include "render/channel.h"
#include "render/extinction_texture.h"
#include "render/gl_program.h"
#include "render/night/moon_disc.h"

#include <glm/mat3x3.hpp>

#include <memory>

namespace skyig::render {

struct SkyState;

class MoonPass {
 public:
  // Needs the GL context current; uploads the albedo map (MoonAlbedo::standard()).
  MoonPass();
  ~MoonPass();
  MoonPass(const MoonPass&) = delete;
  MoonPass& operator=(const MoonPass&) = delete;

  // Adds the state's moon (SkyState::moonDisc) to the bound target; nothing without one. The frame block
  // (shaders/common/uniforms.h) of `channel` must be bound.
  void draw(const SkyState& state, const ChannelConfig& channel);
  // The same for a given disc and the channel's eq. 22 matrix (ndcToWorld).
  void draw(const MoonDisc& disc, const glm::dmat3& ndcToWorld, const ChannelConfig& channel);

 private:
  GlProgram program_;
  GLuint albedoTexture_ = 0;
  ExtinctionTexture extinction_;
  GLuint emptyVao_ = 0;
};

}  // namespace skyig::render
