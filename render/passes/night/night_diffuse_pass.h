#pragma once
// The GL pass of the diffuse night light (render/passes/night/night_diffuse.frag): one full-screen
// triangle added onto the sky pass's float target. Its textures: the calibrated Milky Way
// (2048x1024 RGBA16F in S10, mipmapped), Leinert's zodiacal table (11x19 R32F, S10) and the
// state's extinction profile (512 RGB32F, re-uploaded when the profile changes).
#include "render/passes/common/cloud_field.h"
#include "render/passes/common/extinction_texture.h"
#include "render/gl/gl_program.h"
#include "render/gl/render_target.h"
#include "render/passes/common/night_layer.h"
#include "physics/night/night_diffuse.h"

#include <map>
#include <memory>
#include <utility>
#include <string>

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
  // Draws nothing for a state without an ephemeris (no J2000 frame). Through `clouds`' broken
  // decks (the sky pass's of this frame, PhysicalSkyPass::cloudField) where it has any: behind
  // their cloud or in their gaps, as the sky pass shows them.
  void draw(const skyig::sky::SkyState& state, const CloudFieldView& clouds = {});
  void draw(const skyig::sky::night::NightDiffuseSky& sky, const glm::dvec3& groundRadiance = glm::dvec3(0.0));
  // The sky's part of the same light above the atmosphere (no transmittance, no terrain), in the
  // eye's band, at the vertices of a grid of `scale`-pixel cells over the width x height channel
  // (render/passes/common/night_layer.h), for the physical sky pass to read bilinearly and complete per
  // pixel (SKYIG_NIGHT_LAYER): that target's texture (linear filtering, clamped), a second of the
  // same light dimmed by the transmittance at each vertex, the state's transmittance table and
  // its terrain's radiance; no texture for a state without an ephemeris. With `veil`, both
  // alphas hold the glare veil per lux of the tone block's first glare source, which must then be
  // bound. Leaves the targets bound; the frame block and a vertex array must be bound.
  NightLayer drawLayer(const skyig::sky::SkyState& state, int width, int height, int scale, bool veil = false);
  // The scale for a channel whose pixel at its centre spans `pixelRad`: the layer's texel about
  // the Milky Way map's (its finest structure), at least 1, at most 8.
  int layerScale(double pixelRad) const;

 private:
  // A variant of the pass's program and its per-frame uniforms.
  struct Program {
    explicit Program(const std::string& defines);
    GlProgram program;
    GLint enuToJ2000, sun, airglow, ground;
    CloudFieldLocations cloudField;  // SKYIG_CLOUD_COVER's
  };
  void drawWith(const Program& program, const skyig::sky::night::NightDiffuseSky& sky, const glm::dvec3& groundRadiance);
  // drawWith, added onto the bound target (blend ONE, ONE).
  void drawAdded(const Program& program, const skyig::sky::night::NightDiffuseSky& sky, const glm::dvec3& groundRadiance);
  Program program_;
  // SKYIG_CLOUD_COVER n (1-3 broken decks), the first time a frame looks through them.
  std::map<int, std::unique_ptr<Program>> cloudPrograms_;
  // SKYIG_NIGHT_LAYER by cell and veil, the first time a layer is drawn with them.
  std::map<std::pair<int, bool>, std::unique_ptr<Program>> layerPrograms_;
  std::unique_ptr<RenderTarget> layer_;
  std::unique_ptr<RenderTarget> layerTransmitted_;
  std::unique_ptr<TwoTargetFramebuffer> layerTargets_;
  GLuint milkyWay_ = 0;
  int milkyWayWidth_ = 0;  // texels around the sky
  GLuint zodiacal_ = 0;
  ExtinctionTexture extinction_;
};

}  // namespace skyig::render
