#pragma once
// The moon's GL pass (render/passes/night/moon.*): a quad around the disc, added onto the HDR target
// after the sky pass, from the same numbers as the CPU side (physics/moon/moon_disc.h).
#include "sky/channel.h"
#include "render/passes/common/extinction_texture.h"
#include "render/gl/gl_program.h"
#include "physics/moon/moon_disc.h"

#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include <memory>

namespace skyig::sky {
struct SkyState;
}

namespace skyig::render {

class MoonPass {
 public:
  // Needs the GL context current; uploads the albedo map (skyig::sky::night::MoonAlbedo::standard()).
  MoonPass();
  ~MoonPass();
  MoonPass(const MoonPass&) = delete;
  MoonPass& operator=(const MoonPass&) = delete;

  // Adds the state's moon (skyig::sky::SkyState::moonDisc) to the bound target; nothing without one. The frame block
  // (render/glsl/uniforms.h) of `channel` must be bound. Returns the pixels it may have
  // drawn: x, y, width, height, a rectangle holding the quad (width 0: none).
  glm::ivec4 draw(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                  const skyig::sky::ChannelConfig& channel);
  // The same for a given disc and the channel's eq. 22 matrix (ndcToWorld).
  glm::ivec4 draw(const skyig::sky::night::MoonDisc& disc, const glm::dmat3& ndcToWorld,
                  const skyig::sky::ChannelConfig& channel);

 private:
  GlProgram program_;
  GLuint albedoTexture_ = 0;
  ExtinctionTexture extinction_;
  GLuint emptyVao_ = 0;
};

}  // namespace skyig::render
