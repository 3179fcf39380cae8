#include "render/passes/night/night_diffuse_pass.h"

#include "render/gl/mip_chain.h"
#include "physics/night/zodiacal_light.h"
#include "sky/sky_state.h"
#include "render/glsl/bindings.h"

#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace skyig::render {

namespace {

GLuint uploadMilkyWay(const skyig::sky::night::MilkyWayMap& map) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, mipLevelCount(map.width(), map.height()), GL_RGBA16F, map.width(), map.height());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  forEachMipLevel(map.texels(), map.width(), map.height(),
                  [&](int level, int w, int h, const std::vector<glm::vec3>& texels) {
                    // Half floats hold S10 (0..~1000) to 0.05%; cd/m^2 (1e-4) would sit among
                    // the denormals.
                    std::vector<std::uint16_t> half;
                    half.reserve(texels.size() * 4);
                    for (const glm::vec3& t : texels)
                      for (float c : {t.r, t.g, t.b, 1.0f}) half.push_back(static_cast<std::uint16_t>(glm::packHalf1x16(c)));
                    glTextureSubImage2D(id, level, 0, 0, w, h, GL_RGBA, GL_HALF_FLOAT, half.data());
                  });
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return id;
}

GLuint uploadZodiacal() {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, GL_R32F, skyig::sky::night::kZodiacalColumns, skyig::sky::night::kZodiacalRows);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(id, 0, 0, 0, skyig::sky::night::kZodiacalColumns, skyig::sky::night::kZodiacalRows, GL_RED, GL_FLOAT,
                      skyig::sky::night::zodiacalTableS10().data());
  for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) glTextureParameteri(id, p, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return id;
}

}  // namespace

NightDiffusePass::Program::Program(const std::string& defines)
    : program("render/glsl/fullscreen.vert", "render/passes/night/night_diffuse.frag", defines),
      enuToJ2000(glGetUniformLocation(program.id(), "enuToJ2000")),
      sun(glGetUniformLocation(program.id(), "sunJ2000")),
      airglow(glGetUniformLocation(program.id(), "airglowZenith")),
      ground(glGetUniformLocation(program.id(), "nightGroundRadiance")),
      cloudField(program.id()) {
  const glm::vec3 sunlight(skyig::sky::night::sunlightRec709());
  glProgramUniform3fv(program.id(), glGetUniformLocation(program.id(), "sunlightRec709"), 1, glm::value_ptr(sunlight));
}

NightDiffusePass::NightDiffusePass() : program_("") {
  const skyig::sky::night::MilkyWayMap& map = *skyig::sky::night::MilkyWayMap::standard();
  milkyWay_ = uploadMilkyWay(map);
  milkyWayWidth_ = map.width();
  zodiacal_ = uploadZodiacal();
}

NightDiffusePass::~NightDiffusePass() {
  const GLuint textures[] = {milkyWay_, zodiacal_};
  glDeleteTextures(2, textures);
}

void NightDiffusePass::draw(const skyig::sky::SkyState& state, const CloudFieldView& clouds) {
  // The map is this pass's texture: the state's sky without it, no lock taken per frame.
  const auto sky = skyig::sky::nightDiffuseSky(state, false);
  if (!sky) return;
  const int broken = clouds.broken();
  const Program* program = &program_;
  if (broken > 0) {
    std::unique_ptr<Program>& p = cloudPrograms_[broken];
    if (!p) p = std::make_unique<Program>("#define SKYIG_CLOUD_COVER " + std::to_string(broken) + "\n");
    setCloudField(p->program.id(), p->cloudField, clouds.cover, clouds.layers, clouds.heightM, clouds.bottomRadiusM);
    glBindTextureUnit(SKYIG_UNIT_FOG_TABLE, clouds.cloudedTable);
    glBindTextureUnit(SKYIG_UNIT_FOG_CLEAR_TABLE, clouds.clearTable);
    program = p.get();
  }
  drawAdded(*program, *sky, state.nightGroundRadiance);
}

void NightDiffusePass::draw(const skyig::sky::night::NightDiffuseSky& sky, const glm::dvec3& groundRadiance) {
  drawAdded(program_, sky, groundRadiance);
}

void NightDiffusePass::drawAdded(const Program& program, const skyig::sky::night::NightDiffuseSky& sky,
                                 const glm::dvec3& groundRadiance) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  drawWith(program, sky, groundRadiance);
  glDisable(GL_BLEND);
}

int NightDiffusePass::layerScale(double pixelRad) const {
  const double texelRad = 2.0 * std::numbers::pi / milkyWayWidth_;
  return std::clamp(static_cast<int>(std::floor(texelRad / std::max(pixelRad, 1e-9))), 1, 8);
}

NightLayer NightDiffusePass::drawLayer(const skyig::sky::SkyState& state, int width, int height, int scale,
                                       bool veil) {
  const auto sky = skyig::sky::nightDiffuseSky(state, false);
  if (!sky) return {};
  // A texel a vertex of the grid through the pixel corners every `scale` pixels, to the
  // channel's far edges (render/glsl/pixel_grid.glsl).
  const int w = (width + scale - 1) / scale + 1, h = (height + scale - 1) / scale + 1;
  if (!layer_ || layer_->width() != w || layer_->height() != h) {
    // Float: the night's light is ~1e-4 cd/m^2, where half floats are denormal.
    layerTargets_.reset();
    layer_ = std::make_unique<RenderTarget>(w, h, GL_RGBA32F);
    layer_->readBilinear();
    layerTransmitted_ = std::make_unique<RenderTarget>(w, h, GL_RGBA32F);
    layerTransmitted_->readBilinear();
    layerTargets_ = std::make_unique<TwoTargetFramebuffer>(*layer_, *layerTransmitted_);
  }
  NightLayer layer{layer_->texture(), layerTransmitted_->texture(), extinction_.id(), state.nightGroundRadiance,
                   scale, veil};
  std::unique_ptr<Program>& program = layerPrograms_[{scale, veil}];
  if (!program)
    program = std::make_unique<Program>("#define SKYIG_NIGHT_LAYER\n" + nightLayerCellDefine(layer) +
                                        (veil ? "#define SKYIG_GLARE 1\n" : ""));
  layerTargets_->bindForDrawing();
  glDisable(GL_BLEND);
  drawWith(*program, *sky, glm::dvec3(0.0));
  return layer;
}

void NightDiffusePass::drawWith(const Program& v, const skyig::sky::night::NightDiffuseSky& sky,
                                const glm::dvec3& groundRadiance) {
  extinction_.use(sky.extinction);
  const GLuint p = v.program.id();
  const glm::mat3 m(sky.enuToJ2000);
  glProgramUniformMatrix3fv(p, v.enuToJ2000, 1, GL_FALSE, glm::value_ptr(m));
  const glm::vec3 sun(sky.sunJ2000), airglow(sky.airglowZenith);
  glProgramUniform3fv(p, v.sun, 1, glm::value_ptr(sun));
  glProgramUniform3fv(p, v.airglow, 1, glm::value_ptr(airglow));
  const glm::vec3 ground(groundRadiance);
  glProgramUniform3fv(p, v.ground, 1, glm::value_ptr(ground));
  glBindTextureUnit(SKYIG_UNIT_MILKY_WAY, milkyWay_);
  glBindTextureUnit(SKYIG_UNIT_ZODIACAL, zodiacal_);
  extinction_.bind(SKYIG_UNIT_NIGHT_EXTINCTION);
  v.program.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace skyig::render
