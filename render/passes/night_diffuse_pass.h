#pragma once
// The GL pass of the diffuse night light (shaders/passes/night_diffuse.frag): one full-screen
// triangle added onto the sky pass's float target. Its textures: the calibrated Milky Way
// (2048x1024 RGBA16F in S10, mipmapped), Leinert's zodiacal table (11x19 R32F, S10) and the
// state's extinction profile (512 RGB32F, re-uploaded when the profile changes).
#include "render/passes/extinction_texture.h"
#include "render/gl/gl_program.h"
#include "sky/night/night_diffuse.h"

#include <memory>

namespace skyig::sky {
struct SkyState;
}

namespace skyig::render {

class NightDiffusePass {
 public:
  // Needs the GL context current; loads the Milky Way map (MilkyWayMap::standard()).
  NightDiffusePass();
  ~NightDiffusePass();
  NightDiffusePass(const NightDiffusePass&) = delete;
  NightDiffusePass& operator=(const NightDiffusePass&) = delete;

  // Adds the state's diffuse night light to the bound target, and below the horizon the
  // terrain's radiance under it (SkyState::nightGroundRadiance); the frame block must be bound.
  // Draws nothing for a state without an ephemeris (no J2000 frame).
  void draw(const skyig::sky::SkyState& state);
  void draw(const skyig::sky::night::NightDiffuseSky& sky, const glm::dvec3& groundRadiance = glm::dvec3(0.0));

 private:
  GlProgram program_;
  GLint enuToJ2000Location_ = -1;
  GLint sunLocation_ = -1;
  GLint airglowLocation_ = -1;
  GLint groundLocation_ = -1;
  GLuint milkyWay_ = 0;
  GLuint zodiacal_ = 0;
  ExtinctionTexture extinction_;
};

}  // namespace skyig::render
