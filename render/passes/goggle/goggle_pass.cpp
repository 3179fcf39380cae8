#include "render/passes/goggle/goggle_pass.h"

#include "render/gl/mip_chain.h"
#include "render/glsl/bindings.h"
#include "render/glsl/uniforms.h"
#include "render/glsl/goggle_uniforms.h"
#include "physics/goggle/goggle_physics.h"
#include "physics/physics.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::render {

namespace {

// The side of the blocks the halo and the gain work on (render/passes/goggle/goggle_coarse.frag): the largest
// power of two up to 8 pixels that keeps the halo's sigma 1.5 blocks or more, so its Gaussian
// is sampled finely enough to stay round (a coarser grid drew a diamond on a small channel).
int coarseBlockPx(double haloSigmaPx) {
  int block = 1;
  while (block < 8 && 2 * block <= haloSigmaPx / 1.5) block *= 2;
  return block;
}

}  // namespace

glm::dvec3 phosphorRec709(skyig::sky::Phosphor phosphor) {
  // CIE 1931 chromaticities of the screens' emission, as the tube makers' data give them (as
  // we recall them; not re-read for this work): P43 (Gd2O2S:Tb, its 545 nm terbium line with
  // weaker ones at 490, 585 and 620 nm) x 0.333, y 0.556; P45 (Y2O2S:Tb, "white phosphor",
  // bluish) x 0.253, y 0.312. Both lie inside the Rec.709 gamut.
  const glm::dvec2 xy = phosphor == skyig::sky::Phosphor::P43 ? glm::dvec2(0.333, 0.556) : glm::dvec2(0.253, 0.312);
  const glm::dvec3 xyz(xy.x / xy.y, 1.0, (1.0 - xy.x - xy.y) / xy.y);
  return shader::xyzToRec709(xyz);
}

GoggleGeometry goggleGeometry(const skyig::sky::ChannelConfig& channel) {
  if (channel.width < 1 || channel.height < 1) throw std::invalid_argument("goggle: channel size must be positive");
  const double fov = channel.goggle.fieldOfViewDeg;
  if (!std::isfinite(fov) || fov <= 0.0 || fov >= 180.0)
    throw std::invalid_argument("goggle: field of view " + std::to_string(fov) + " deg is not in (0, 180)");
  GoggleGeometry g;
  const double half = fov / 2.0 * std::numbers::pi / 180.0;
  g.radiusPx = 0.5 * channel.height;  // sky::goggleFrustum: the field fills the height
  g.fieldFraction = std::min(1.0, std::numbers::pi * g.radiusPx * g.radiusPx / (static_cast<double>(channel.width) * channel.height));
  g.pixelAngleRad = 2.0 * std::tan(half) / channel.height;  // at the centre
  const double pixelOnCathodeM = shader::kObjectiveFocalLengthM * g.pixelAngleRad;
  g.electronsPerLux = shader::photoelectrons(1.0, pixelOnCathodeM * pixelOnCathodeM, shader::kFrameSeconds);
  g.haloSigmaPx = std::tan(shader::kHaloSigmaDeg * std::numbers::pi / 180.0) / std::tan(half) * g.radiusPx;
  g.mtfSigmaPx = shader::mtfSigmaRad() / g.pixelAngleRad;
  return g;
}

GogglePass::GogglePass()
    : input_("render/glsl/fullscreen.vert", "render/passes/goggle/goggle_input.frag"),
      coarse_("render/glsl/fullscreen.vert", "render/passes/goggle/goggle_coarse.frag"),
      halo_("render/glsl/fullscreen.vert", "render/passes/goggle/goggle_halo.frag"),
      abc_("render/glsl/fullscreen.vert", "render/passes/goggle/goggle_abc.frag"),
      screen_("render/glsl/fullscreen.vert", "render/passes/goggle/goggle.frag"),
      block_(SKYIG_BINDING_GOGGLE, sizeof(GoggleBlock)) {
  seedLocation_ = glGetUniformLocation(screen_.id(), "uSeed");
  abcLevelLocation_ = glGetUniformLocation(abc_.id(), "uLevel");
  haloDirectionLocation_ = glGetUniformLocation(halo_.id(), "uDirection");
  haloLogLocation_ = glGetUniformLocation(halo_.id(), "uWriteLog");
  glCreateVertexArrays(1, &emptyVao_);
}

GogglePass::~GogglePass() {
  glDeleteVertexArrays(1, &emptyVao_);
}

void GogglePass::ensureTargets(int width, int height, int block) {
  if (cathode_ && cathode_->width() == width && cathode_->height() == height && block == blockPx_) return;
  blockPx_ = block;
  cathode_ = std::make_unique<RenderTarget>(width, height, GL_R32F);
  const int cw = (width + block - 1) / block, ch = (height + block - 1) / block;
  coarseTarget_ = std::make_unique<RenderTarget>(cw, ch, GL_R32F, false, mipLevelCount(cw, ch));
  haloRows_ = std::make_unique<RenderTarget>(cw, ch, GL_R32F);
  haloTarget_ = std::make_unique<RenderTarget>(cw, ch, GL_R32F);
  gainTarget_ = std::make_unique<RenderTarget>(1, 1, GL_R32F);
  // Read bilinearly: the cathode between its pixels (the coarse pass), the halo up to the
  // channel's size; the block means and the halo's rows with zero beyond the channel (the
  // halo's Gaussian reaches past its edge), the means mip-mapped for the gain.
  cathode_->readBilinear();
  coarseTarget_->readBilinear(GL_CLAMP_TO_BORDER, GL_LINEAR_MIPMAP_NEAREST);
  haloRows_->readBilinear(GL_CLAMP_TO_BORDER);
  haloTarget_->readBilinear();
}

void GogglePass::draw(GLuint nvisImage, const skyig::sky::ChannelConfig& channel, double nvisPerCdM2OfIlluminantA,
                      std::uint32_t seed, const RenderTarget& target, bool screenLuminance) {
  if (!(nvisPerCdM2OfIlluminantA > 0.0) || !std::isfinite(nvisPerCdM2OfIlluminantA))
    throw std::invalid_argument("goggle: the illuminant's NVIS radiance per cd/m^2 must be positive");
  const GoggleGeometry g = goggleGeometry(channel);
  const int block = coarseBlockPx(g.haloSigmaPx);
  ensureTargets(channel.width, channel.height, block);

  GoggleBlock b{};
  b.goggleTube = glm::vec4(0.5f * static_cast<float>(channel.width), 0.5f * static_cast<float>(channel.height),
                     static_cast<float>(g.radiusPx), static_cast<float>(g.fieldFraction));
  b.goggleCathode = glm::vec4(static_cast<float>(shader::cathodeIlluminance(1.0 / nvisPerCdM2OfIlluminantA)),
                        static_cast<float>(g.electronsPerLux), static_cast<float>(g.haloSigmaPx),
                        static_cast<float>(block));
  const skyig::sky::GoggleParams& p = channel.goggle;
  b.goggleGain = glm::vec4(p.automaticGain ? 1.0f : 0.0f, static_cast<float>(p.gain), screenLuminance ? 1.0f : 0.0f, 0.0f);
  b.gogglePhosphor = glm::vec4(glm::vec3(phosphorRec709(p.phosphor)), 0.0f);
  // The 3 x 3 Gaussian of the tube's modulation transfer, normalised.
  const double s2 = std::max(g.mtfSigmaPx * g.mtfSigmaPx, 1e-6);
  const double edge = std::exp(-1.0 / (2.0 * s2)), corner = std::exp(-1.0 / s2);
  const double sum = 1.0 + 4.0 * edge + 4.0 * corner;
  b.goggleMtf = glm::vec4(static_cast<float>(1.0 / sum), static_cast<float>(edge / sum), static_cast<float>(corner / sum), 0.0f);
  block_.upload(b);
  block_.bind();

  glBindVertexArray(emptyVao_);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  cathode_->bindForDrawing();
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_NVIS, nvisImage);
  input_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);

  coarseTarget_->bindForDrawing();
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_CATHODE, cathode_->texture());
  coarse_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glGenerateTextureMipmap(coarseTarget_->texture());

  haloRows_->bindForDrawing();
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_COARSE, coarseTarget_->texture());
  glProgramUniform2f(halo_.id(), haloDirectionLocation_, 1.0f, 0.0f);
  glProgramUniform1i(halo_.id(), haloLogLocation_, 0);
  halo_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  haloTarget_->bindForDrawing();
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_COARSE, haloRows_->texture());
  glProgramUniform2f(halo_.id(), haloDirectionLocation_, 0.0f, 1.0f);
  glProgramUniform1i(halo_.id(), haloLogLocation_, 1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_COARSE, coarseTarget_->texture());

  // The control reads the finest level at most 32 texels across: its one fragment runs on one
  // llvmpipe thread, 20 bisections over the level. A bright source saturates its own pixels
  // but the control sees it diluted over a texel, where it may saturate the texel: with at
  // least a few hundred texels (or all 8 x 8 means of a small channel) one saturated texel
  // weighs a few percent of the mean at most.
  const int levels = mipLevelCount(coarseTarget_->width(), coarseTarget_->height());
  int level = 0;
  while (level + 1 < levels && (std::max(coarseTarget_->width(), coarseTarget_->height()) >> level) > 32) ++level;
  gainTarget_->bindForDrawing();
  glProgramUniform1i(abc_.id(), abcLevelLocation_, level);
  abc_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);

  target.bindForDrawing();
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_CATHODE, cathode_->texture());
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_HALO, haloTarget_->texture());
  glBindTextureUnit(SKYIG_UNIT_GOGGLE_GAIN, gainTarget_->texture());
  glProgramUniform1ui(screen_.id(), seedLocation_, seed);
  screen_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

double GogglePass::readGain() const {
  if (!gainTarget_) throw std::logic_error("readGain before any draw");
  float g = 0.0f;
  glGetTextureImage(gainTarget_->texture(), 0, GL_RED, GL_FLOAT, sizeof(float), &g);
  return static_cast<double>(g);
}

}  // namespace skyig::render
