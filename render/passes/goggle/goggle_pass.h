#pragma once
// The image intensifier of a goggle channel (physics/goggle/intensifier.glsl, docs/nvis.md):
// the channel's NVIS radiance (the sky passes drew it in the goggle's band, sky/nvis_weights.h)
// in, the goggle's screen out, as display values or in cd/m^2. Six draws:
//   1. render/passes/goggle/goggle_input.frag: the photocathode's illuminance inside the tube's field;
//   2. render/passes/goggle/goggle_coarse.frag: its means over blocks of 8 x 8 pixels (fewer on a small
//      channel, to keep the halo round), then their mip chain;
//   3. render/passes/goggle/goggle_halo.frag, twice (rows, then columns): the halo, a Gaussian on the block
//      means (the halo is 1.8 deg across, some 50 pixels of a 1200-pixel goggle: smooth at that
//      resolution);
//   4. render/passes/goggle/goggle_abc.frag: the automatic brightness control's gain (one fragment);
//   5. render/passes/goggle/goggle.frag: the tube's modulation transfer (3 x 3), the halo, the photoelectrons'
//      noise, the gain and the phosphor, per pixel.
#include "render/gl/gl_program.h"
#include "render/gl/render_target.h"
#include "sky/channel.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>

namespace skyig::render {

// The tubes' photocathode sensitivity and gain are specified with CIE illuminant A, a Planckian
// radiator at 2856 K (CIE 15:2004).
inline constexpr double kIlluminantAKelvin = 2856.0;

// The linear Rec.709 colour of luminance 1 of a goggle's phosphor (CIE 1931 chromaticities in
// goggle_pass.cpp).
glm::dvec3 phosphorRec709(skyig::sky::Phosphor phosphor);

// What the goggle pass derives from the channel (for its block and the tests).
struct GoggleGeometry {
  double radiusPx = 0.0;          // the tube's field
  double fieldFraction = 0.0;     // of the channel's pixels inside it
  double pixelAngleRad = 0.0;     // at the centre
  double electronsPerLux = 0.0;   // photoelectrons per lux on the cathode, per pixel and frame
  double haloSigmaPx = 0.0;
  double mtfSigmaPx = 0.0;
};
// `channel` with its goggle's frustum (sky::goggleFrustum).
GoggleGeometry goggleGeometry(const skyig::sky::ChannelConfig& channel);

class GogglePass {
 public:
  GogglePass();
  ~GogglePass();
  GogglePass(const GogglePass&) = delete;
  GogglePass& operator=(const GogglePass&) = delete;

  // Draws the goggle of `channel` (its frustum the goggle's) from `nvisImage` (channel-sized,
  // W m^-2 sr^-1 in every channel) into `target`: display values through the bound tone
  // block's display (its dither amplitude too), or with `screenLuminance` the screen's linear
  // Rec.709 cd/m^2. `nvisPerCdM2OfIlluminantA` converts the goggle's class of NVIS radiance to
  // the cathode's calibration source; `seed` makes the frame's noise.
  void draw(GLuint nvisImage, const skyig::sky::ChannelConfig& channel, double nvisPerCdM2OfIlluminantA,
            std::uint32_t seed, const RenderTarget& target, bool screenLuminance = false);

  // The gain (cd/m^2 per lux) the last draw was shown with (read back: tests).
  double readGain() const;

 private:
  void ensureTargets(int width, int height, int block);
  GlProgram input_;
  GlProgram coarse_;
  GlProgram halo_;
  GlProgram abc_;
  GlProgram screen_;
  UniformBuffer block_;
  GLint seedLocation_ = -1;
  GLint abcLevelLocation_ = -1;
  GLint haloDirectionLocation_ = -1;
  GLint haloLogLocation_ = -1;
  GLuint emptyVao_ = 0;
  std::unique_ptr<RenderTarget> cathode_;
  std::unique_ptr<RenderTarget> coarseTarget_;
  std::unique_ptr<RenderTarget> haloRows_;  // the halo's first, horizontal pass
  std::unique_ptr<RenderTarget> haloTarget_;
  std::unique_ptr<RenderTarget> gainTarget_;  // 1 x 1
  int blockPx_ = 0;  // the coarse targets' block side, pixels
};

}  // namespace skyig::render
