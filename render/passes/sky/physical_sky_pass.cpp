#include "render/passes/sky/physical_sky_pass.h"

#include "render/gl/gl_context.h"
#include "render/glsl/bindings.h"
#include "physics/atmosphere/atmosphere_physics.h"
#include "physics/atmosphere/segment_transmittance.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::render {

namespace {

GLuint createTexture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(id, p, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return id;
}

glm::vec3 f3(const glm::dvec3& v) { return glm::vec3(v); }

}  // namespace

// RGBA32F: the transmittance spans more orders of magnitude than half floats hold.
GLuint uploadTable2D(const shader::cpu_texture::sampler2D& s) {
  std::vector<float> texels;
  texels.reserve(s.texels.size() * 4);
  for (const glm::dvec4& t : s.texels)
    for (int c = 0; c < 4; ++c) texels.push_back(static_cast<float>(t[c]));
  const GLuint id = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(id, 1, GL_RGBA32F, s.width, s.height);
  glTextureSubImage2D(id, 0, 0, 0, s.width, s.height, GL_RGBA, GL_FLOAT, texels.data());
  return id;
}

PhysicalSkyPass::Program::Program(const char* vertex, const char* fragment, const std::string& defines)
    : program(vertex, fragment, defines),
      camera(glGetUniformLocation(program.id(), "camera")),
      sun(glGetUniformLocation(program.id(), "sunDirectionP")),
      sunRefraction(glGetUniformLocation(program.id(), "sunRefraction")),
      moonOn(glGetUniformLocation(program.id(), "moonlightOn")),
      moonDirection(glGetUniformLocation(program.id(), "moonDirectionP")),
      moonScale(glGetUniformLocation(program.id(), "moonlightScale")),
      radii(glGetUniformLocation(program.id(), "frameRadii")),
      angles(glGetUniformLocation(program.id(), "frameAngles")),
      groundCap(glGetUniformLocation(program.id(), "groundCap")),
      horizonStrip(glGetUniformLocation(program.id(), "horizonStrip")),
      nightGround(glGetUniformLocation(program.id(), "nightGroundRadiance")),
      cloudField(program.id()),
      lit(glGetUniformLocation(program.id(), "cloudLit")),
      litSide(glGetUniformLocation(program.id(), "cloudLitSide")),
      litEye(glGetUniformLocation(program.id(), "cloudLitEye")),
      sunThrough(glGetUniformLocation(program.id(), "fogSunThrough")) {}

PhysicalSkyPass::LitDecks PhysicalSkyPass::litDecks(double heightM) const {
  LitDecks out;
  int broken = 0;
  for (std::size_t k = 0; k < sky::kCloudLayers; ++k) {
    const weather::FogLayer& deck = fog_[weather::kWeatherLayerCount + k];
    const bool isBroken = cover_[k].broken && deck.extinction > 0.0;
    const int brokenIndex = isBroken ? broken++ : -1;
    if (deck.extinction <= 0.0) continue;
    const double base = deck.bottom_height - shader::fogBottomBand(deck), top = deck.top_height + deck.band_height;
    if (heightM >= base && heightM <= top) continue;  // inside: its field holds it
    const bool under = heightM < base;
    const double tau = shader::fogColumnDepth(deck);
    // From under a thick deck its single-scattered light is only a low light's on its base from
    // below (a light more than 3 deg up is over the base's horizon everywhere in view, and what it
    // sends through is exp(-tau) of it): the frame pays nothing for an overcast day.
    constexpr double kThickDeck = 20.0, kLowLight = 0.0523;  // sin 3 deg
    if (under && tau > kThickDeck && cloudLightLowestZ_ > kLowLight) continue;
    const double face = under ? base : top;
    double between = 0.0;  // the weather's layers between the eye and the face
    for (std::size_t i = 0; i < weather::kWeatherLayerCount; ++i)
      if (fog_[i].extinction > 0.0)
        between += std::abs(shader::fogDepthAbove(fog_[i], std::min(heightM, face)) - shader::fogDepthAbove(fog_[i], std::max(heightM, face)));
    out.lit[out.count] = glm::vec4(glm::dvec4(face, tau, deck.asymmetry, brokenIndex));
    out.side[out.count] = glm::vec4(glm::dvec4(under ? 1.0 : -1.0, shader::fogSlabReflectance(tau, deck.asymmetry), between, 0.0));
    ++out.count;
  }
  return out;
}

int PhysicalSkyPass::brokenDecks() const {
  return brokenDeckCount(cover_, fog_);
}

namespace {
constexpr int kCloudLightTableSize = 256;
}  // namespace

// The sun's light at each face by its cosine there, and the air's transmittance from the eye to
// it by the view's (render/passes/sky/physical_sky.frag, cloudSingleLight), from the model the
// frame draws: the sun's normal irradiance (the transmittance table, the disc's part above the
// horizon), and the segment's transmittance (physics/atmosphere/segment_transmittance.h).
void PhysicalSkyPass::updateCloudLightTable(const LitDecks& lit, double heightM) {
  const atmosphere::AtmosphereModel& model = *current_.model;
  std::array<double, sky::kCloudLayers + 2> key{};
  for (int k = 0; k < lit.count; ++k) key[static_cast<std::size_t>(k)] = lit.lit[static_cast<std::size_t>(k)].x;
  // The eye's height to the metre: a climbing or descending eye would otherwise remake the table
  // (768 spectral transmittances, on the render thread) every frame, for a change of the air's
  // transmittance to the face under 1e-4 a metre.
  const double eye = std::round(heightM);
  key[sky::kCloudLayers] = eye;
  key[sky::kCloudLayers + 1] = static_cast<double>(reinterpret_cast<std::uintptr_t>(&model));
  if (!cloudLightTable_) {
    glCreateTextures(GL_TEXTURE_2D, 1, &cloudLightTable_);
    glTextureStorage2D(cloudLightTable_, 1, GL_RGBA32F, kCloudLightTableSize, 6);
    glTextureParameteri(cloudLightTable_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(cloudLightTable_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(cloudLightTable_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(cloudLightTable_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    cloudLightKey_.fill(-1.0);
  }
  if (key != cloudLightKey_) {
    const double R = model.parameters(0).bottom_radius, r = R + eye;
    std::vector<glm::vec4> texels(static_cast<std::size_t>(kCloudLightTableSize) * 6, glm::vec4(0.0f));
    for (int k = 0; k < lit.count; ++k) {
      const double face = lit.lit[static_cast<std::size_t>(k)].x, rp = R + face;
      for (int i = 0; i < kCloudLightTableSize; ++i) {
        const double u = (i + 0.5) / kCloudLightTableSize;
        const double muS = shader::fogTableMu(u);
        const glm::dvec3 point(0.0, 0.0, rp), sun(std::sqrt(std::max(1.0 - muS * muS, 0.0)), 0.0, muS);
        const glm::dvec3 e = model.converter().toRec709(model.sunIrradiance(point, sun, sun));
        texels[static_cast<std::size_t>(k * kCloudLightTableSize + i)] = glm::vec4(glm::dvec4(e, 1.0));
        // The eye's view of the same cosine (rows 3 + k share the axis) meets the face d metres on.
        const double d = shader::distanceToHeight(R, eye, muS, face);
        const double t = d >= 0.0 ? atmosphere::luminanceTransmittance(model, r, muS, d) : 0.0;
        texels[static_cast<std::size_t>((3 + k) * kCloudLightTableSize + i)] = glm::vec4(static_cast<float>(t));
      }
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(cloudLightTable_, 0, 0, 0, kCloudLightTableSize, 6, GL_RGBA, GL_FLOAT, texels.data());
    cloudLightKey_ = key;
  }
  glBindTextureUnit(SKYIG_UNIT_CLOUD_LIGHT_TABLE, cloudLightTable_);
}

// The lit decks' and the broken decks' uniforms (render/passes/sky/physical_sky.frag).
void PhysicalSkyPass::setCloudUniforms(const Program& program, double heightM) const {
  const GLuint id = program.program.id();
  const float bottom = static_cast<float>(current_.model->parameters(0).bottom_radius);
  if (program.lit >= 0) {
    const LitDecks l = litDecks(heightM);
    glProgramUniform4fv(id, program.lit, l.count, &l.lit[0][0]);
    glProgramUniform4fv(id, program.litSide, l.count, &l.side[0][0]);
    glProgramUniform2f(id, program.litEye, static_cast<float>(heightM), bottom);
  }
  setCloudField(id, program.cloudField, cover_, fog_, heightM, bottom);
}

PhysicalSkyPass::PhysicalSkyPass(int slicesPerFrame, const char* insideFragment)
    : slicesPerFrame_(slicesPerFrame),
      space_("render/glsl/fullscreen.vert", "render/passes/sky/physical_sky_space.frag"),
      sliceProgram_("render/glsl/fullscreen.vert", "render/passes/sky/physical_sky_slice.frag"),
      sliceCoordsLocation_(glGetUniformLocation(sliceProgram_.id(), "sliceCoords")) {
  if (std::string(insideFragment) != kInsideFragment)
    reference_ = std::make_unique<Program>("render/glsl/fullscreen.vert", insideFragment);
  // The HDR variants every frame of a plain sky can need: the sun's and the moon's sky and
  // ground, and the disc's quad over both or over the sky.
  using Part = SkyVariant::Part;
  for (const bool moonlit : {false, true})
    for (const Part part : {Part::both, Part::sky, Part::ground}) {
      SkyVariant v;
      v.part = part;
      v.moonlit = moonlit;
      program(v);
      v.sunDisc = true;
      if (part != Part::ground) program(v);
    }
  if (slicesPerFrame < 1) throw std::invalid_argument("PhysicalSkyPass: slices per frame " + std::to_string(slicesPerFrame) + " must be at least 1");
}

PhysicalSkyPass::~PhysicalSkyPass() {
  if (cloudLightTable_) glDeleteTextures(1, &cloudLightTable_);
  releaseSlices();
  releaseSet(current_);
  if (pending_) releaseSet(pending_->set);
}

PhysicalSkyPass::TableSet PhysicalSkyPass::createSet(std::shared_ptr<const atmosphere::AtmosphereModel> model,
                                                     const atmosphere::Rec709Packer& packer) {
  TableSet set;
  set.model = std::move(model);
  set.small = packer.packSmallTables();
  set.transmittance = uploadTable2D(set.small.transmittanceXyz);
  set.irradiance = uploadTable2D(set.small.irradianceXyz);
  const auto& s = set.model->tables(0).scattering;
  set.scattering = createTexture(GL_TEXTURE_3D);
  glTextureStorage3D(set.scattering, 1, GL_RGBA16F, s.width, s.height, s.depth);
  set.singleMie = createTexture(GL_TEXTURE_3D);
  glTextureStorage3D(set.singleMie, 1, GL_RG16F, s.width, s.height, s.depth);
  const std::size_t texels3 = s.texels.size();
  set.bytes = 16 * (set.small.transmittanceXyz.texels.size() + set.small.irradianceXyz.texels.size()) + 8 * texels3 + 4 * texels3;
  return set;
}

void PhysicalSkyPass::releaseSet(TableSet& set) {
  const GLuint ids[] = {set.transmittance, set.irradiance, set.scattering, set.singleMie};
  if (set.model) glDeleteTextures(4, ids);
  set = TableSet{};
}

std::size_t PhysicalSkyPass::uploadSlices(const TableSet& set, const atmosphere::Rec709Packer& packer, int first,
                                          int count) {
  const auto& s = set.model->tables(0).scattering;
  std::vector<std::uint16_t> scattering, mie;
  std::size_t bytes = 0;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int z = first; z < first + count && z < s.depth; ++z) {
    packer.packSlice(z, scattering, mie);
    glTextureSubImage3D(set.scattering, 0, 0, 0, z, s.width, s.height, 1, GL_RGBA, GL_HALF_FLOAT, scattering.data());
    glTextureSubImage3D(set.singleMie, 0, 0, 0, z, s.width, s.height, 1, GL_RG, GL_HALF_FLOAT, mie.data());
    bytes += 2 * (scattering.size() + mie.size());
  }
  return bytes;
}

void PhysicalSkyPass::makeCurrent(TableSet set) {
  releaseSet(current_);
  current_ = std::move(set);
  std::vector<const Program*> programs = {&space_};
  if (reference_) programs.push_back(reference_.get());
  for (const auto& [variant, program] : programs_) programs.push_back(program.get());
  for (const Program* program : programs) setModelUniforms(*program);
}

void PhysicalSkyPass::setModelUniforms(const Program& program) const {
  const GLuint p = program.program.id();
  setAtmosphereUniforms(p, "atm", current_.model->parameters(0));
  glProgramUniform3fv(p, glGetUniformLocation(p, "solarIrradianceXyz"), 1, &f3(current_.small.solarIrradianceXyz)[0]);
  glProgramUniform3fv(p, glGetUniformLocation(p, "limbDarkeningXyz"), 1, &f3(current_.small.limbDarkeningXyz)[0]);
  glProgramUniform1f(p, glGetUniformLocation(p, "groundAlbedo"), static_cast<float>(current_.small.groundAlbedo));
}

const PhysicalSkyPass::Program& PhysicalSkyPass::program(const SkyVariant& v) {
  std::unique_ptr<Program>& p = programs_[v];
  if (!p) {
    p = std::make_unique<Program>(v.vertexShader(), kInsideFragment, v.defines());
    if (current_.model) setModelUniforms(*p);
  }
  return *p;
}

void PhysicalSkyPass::releaseSlices() {
  for (Slice* s : {&sunSlice_, &moonSlice_}) {
    if (s->framebuffer == 0) continue;
    glDeleteFramebuffers(1, &s->framebuffer);
    const GLuint ids[] = {s->scattering, s->singleMie};
    glDeleteTextures(2, ids);
    *s = Slice{};
  }
  sliceWidth_ = sliceHeight_ = 0;
}

void PhysicalSkyPass::ensureSlices() {
  const auto& t = current_.model->tables(0).scattering;
  const int width = static_cast<int>(current_.model->parameters(0).scattering_nu_size);
  const int height = t.height;
  if (width == sliceWidth_ && height == sliceHeight_) return;
  releaseSlices();
  for (Slice* s : {&sunSlice_, &moonSlice_}) {
    s->scattering = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(s->scattering, 1, GL_RGBA32F, width, height);
    s->singleMie = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(s->singleMie, 1, GL_RGBA32F, width, height);
    glCreateFramebuffers(1, &s->framebuffer);
    glNamedFramebufferTexture(s->framebuffer, GL_COLOR_ATTACHMENT0 + SKYIG_OUTPUT_SLICE_SCATTERING, s->scattering, 0);
    glNamedFramebufferTexture(s->framebuffer, GL_COLOR_ATTACHMENT0 + SKYIG_OUTPUT_SLICE_SINGLE_MIE, s->singleMie, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};  // fragment output i -> attachment i
    glNamedFramebufferDrawBuffers(s->framebuffer, 2, buffers);
  }
  sliceWidth_ = width;
  sliceHeight_ = height;
}

void PhysicalSkyPass::drawSlice(const Slice& slice, double uMuS, double uR) {
  glProgramUniform3f(sliceProgram_.id(), sliceCoordsLocation_, static_cast<float>(uMuS), static_cast<float>(uR),
                     static_cast<float>(sliceWidth_));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, slice.framebuffer);
  glViewport(0, 0, sliceWidth_, sliceHeight_);
  sliceProgram_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void PhysicalSkyPass::use(std::shared_ptr<const atmosphere::AtmosphereModel> model) {
  if (!model) throw std::invalid_argument("PhysicalSkyPass: no atmosphere model");
  if (model == current_.model) {
    if (pending_) releaseSet(pending_->set);
    pending_.reset();  // back to the model on screen: nothing to swap
    return;
  }
  if (pending_ && pending_->set.model == model) return;
  const atmosphere::Rec709Packer packer(*model);
  if (!current_.model) {  // nothing to draw yet: the whole set now
    TableSet set = createSet(model, packer);
    uploadSlices(set, packer, 0, packer.slices());
    makeCurrent(std::move(set));
    return;
  }
  if (pending_) releaseSet(pending_->set);  // the latest model wins
  pending_.reset(new Pending{TableSet{}, atmosphere::Rec709Packer(*model), 0});
  pending_->set.model = model;  // created by the first step, so use() itself stays cheap
}

int PhysicalSkyPass::framesUntilSwap() const {
  if (!pending_) return 0;
  const int left = pending_->packer.slices() - pending_->nextSlice;
  return std::max(1, (left + slicesPerFrame_ - 1) / slicesPerFrame_);
}

void PhysicalSkyPass::stepUpload() {
  lastUploadBytes_ = 0;
  lastUploadSeconds_ = 0.0;
  if (!pending_) return;
  const auto start = std::chrono::steady_clock::now();
  Pending& p = *pending_;
  if (p.set.scattering == 0) {
    p.set = createSet(p.set.model, p.packer);
    lastUploadBytes_ += p.set.bytes - 12 * p.set.model->tables(0).scattering.texels.size();
  }
  lastUploadBytes_ += uploadSlices(p.set, p.packer, p.nextSlice, slicesPerFrame_);
  p.nextSlice += slicesPerFrame_;
  if (p.nextSlice >= p.packer.slices()) {
    TableSet set = std::move(p.set);
    pending_.reset();
    makeCurrent(std::move(set));
  }
  lastUploadSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void PhysicalSkyPass::setFrameUniforms(const Program& program, const glm::dvec3& camera,
                                       const glm::dvec3& sunDirection, const glm::dvec4& sunRefraction,
                                       const glm::vec4& radii, const glm::vec3& angles) {
  const GLuint p = program.program.id();
  glProgramUniform4fv(p, program.radii, 1, &radii[0]);
  glProgramUniform3fv(p, program.angles, 1, &angles[0]);
  glProgramUniform3fv(p, program.camera, 1, &f3(camera)[0]);
  glProgramUniform3fv(p, program.sun, 1, &f3(sunDirection)[0]);
  const glm::vec4 refraction(sunRefraction);
  glProgramUniform4fv(p, program.sunRefraction, 1, &refraction[0]);
}

void PhysicalSkyPass::bindTables(const NightLayer& night) const {
  glBindTextureUnit(SKYIG_UNIT_SCATTERING, current_.scattering);
  glBindTextureUnit(SKYIG_UNIT_SINGLE_MIE, current_.singleMie);
  glBindTextureUnit(SKYIG_UNIT_TRANSMITTANCE, current_.transmittance);
  glBindTextureUnit(SKYIG_UNIT_IRRADIANCE, current_.irradiance);
  if (night.texture) {
    glBindTextureUnit(SKYIG_UNIT_NIGHT_LAYER, night.texture);
    glBindTextureUnit(SKYIG_UNIT_NIGHT_LAYER_EXTINCTION, night.extinction);
  }
}

// From space: the general program, the moon a uniform branch.
void PhysicalSkyPass::drawFromSpace(const glm::dvec3& camera, const glm::dvec3& sunDirection,
                                    const glm::dvec3& moonDirection, const glm::dvec3& moonlightScale,
                                    const glm::dvec4& sunRefraction) {
  const GLuint p = space_.program.id();
  setFrameUniforms(space_, camera, sunDirection, sunRefraction, glm::vec4(0.0f), glm::vec3(0.0f));
  glProgramUniform1i(p, space_.moonOn, moonlightScale != glm::dvec3(0.0) ? 1 : 0);
  glProgramUniform3fv(p, space_.moonDirection, 1, &f3(moonDirection)[0]);
  glProgramUniform3fv(p, space_.moonScale, 1, &f3(moonlightScale)[0]);
  space_.program.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

PhysicalSkyPass::Frame PhysicalSkyPass::frameInside(const glm::dvec3& camera, const glm::dvec3& sunDirection,
                                                    const glm::dvec3& moonDirection, const glm::dvec3& moonlightScale,
                                                    const glm::dvec4& sunRefraction, const NightLayer& night,
                                                    bool sunlit) const {
  const atmosphere::AtmosphereParameters& a = current_.model->parameters(0);
  const double r = glm::length(camera);
  const glm::dvec4 sunUvwz = shader::scatteringUvwzFromRMuMuSNu(a, r, 1.0, std::clamp(glm::dot(camera, sunDirection) / r, -1.0, 1.0), 0.0, false);
  const glm::dvec4 moonUvwz = shader::scatteringUvwzFromRMuMuSNu(a, r, 1.0, std::clamp(glm::dot(camera, moonDirection) / r, -1.0, 1.0), 0.0, false);
  const double rho = std::sqrt(std::max(r * r - a.bottom_radius * a.bottom_radius, 0.0));
  const double h = std::sqrt(a.top_radius * a.top_radius - a.bottom_radius * a.bottom_radius);
  // The cone the refracted disc can fall in, around the airless sun: its radius, the lift of
  // its centre and the change of that lift across it, with room to spare, and a pixel more for
  // the pixels whose centres lie outside the limb it crosses. Only the pixels within it take
  // unrefractView's transcendentals: the disc's quad covers it.
  const double radius = a.sun_angular_radius;
  const double reach = radius + std::abs(sunRefraction.y) +
                       2.0 * (std::abs(sunRefraction.z) * radius + std::abs(sunRefraction.w) * radius * radius);
  // The horizon's elevation: its cosine to the vertical is mu = -sqrt(1 - (Rg/r)^2).
  const double horizon = std::asin(-std::sqrt(std::max(0.0, 1.0 - (a.bottom_radius / r) * (a.bottom_radius / r))));
  Frame f;
  f.camera = camera;
  f.sunDirection = sunDirection;
  f.moonDirection = moonDirection;
  f.moonlightScale = moonlightScale;
  f.sunRefraction = sunRefraction;
  f.radii = glm::vec4(static_cast<float>(r), static_cast<float>(rho), static_cast<float>(h), static_cast<float>(sunUvwz.w));
  f.angles = glm::vec3(static_cast<float>(sunUvwz.y), static_cast<float>(moonUvwz.y), static_cast<float>(std::cos(1.1 * reach + pixelAngleRad_)));
  f.sunUvwz = sunUvwz;
  f.moonUvwz = moonUvwz;
  f.moon = moonlightScale != glm::dvec3(0.0);
  f.sunlit = sunlit;
  f.night = &night;
  f.horizon = horizon;
  return f;
}

GLint PhysicalSkyPass::drawSlices(const Frame& f) {
  ensureSlices();
  GLint target = 0;
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  glGetIntegerv(GL_VIEWPORT, viewport);
  if (f.sunlit || reference_) drawSlice(sunSlice_, f.sunUvwz.y, f.sunUvwz.w);
  if (f.moon) drawSlice(moonSlice_, f.moonUvwz.y, f.moonUvwz.w);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glBindTextureUnit(SKYIG_UNIT_SUN_SLICE_SCATTERING, sunSlice_.scattering);
  glBindTextureUnit(SKYIG_UNIT_SUN_SLICE_SINGLE_MIE, sunSlice_.singleMie);
  glBindTextureUnit(SKYIG_UNIT_MOON_SLICE_SCATTERING, moonSlice_.scattering);
  glBindTextureUnit(SKYIG_UNIT_MOON_SLICE_SINGLE_MIE, moonSlice_.singleMie);
  return target;
}

void PhysicalSkyPass::prepare(const Program& program, const Frame& f) const {
  setFrameUniforms(program, f.camera, f.sunDirection, f.sunRefraction, f.radii, f.angles);
  if (f.moon) {
    glProgramUniform3fv(program.program.id(), program.moonDirection, 1, &f3(f.moonDirection)[0]);
    glProgramUniform3fv(program.program.id(), program.moonScale, 1, &f3(f.moonlightScale)[0]);
  }
  if (f.night->texture) glProgramUniform3fv(program.program.id(), program.nightGround, 1, &f3(f.night->groundRadiance)[0]);
  setCloudUniforms(program, glm::length(f.camera) - current_.model->parameters(0).bottom_radius);
  if (program.sunThrough >= 0) glProgramUniform1f(program.program.id(), program.sunThrough, static_cast<float>(sunThroughFog_));
  program.program.use();
}

// The quad around the sun again with the disc (it clips away when the sun is behind the camera).
void PhysicalSkyPass::drawDisc(const Frame& f, const SkyVariant& base) {
  if (!f.sunlit) return;
  SkyVariant v = base;
  v.sunDisc = true;
  prepare(program(v), f);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

void PhysicalSkyPass::drawWithoutDepth(const Frame& f, const SkyVariant& base) {
  prepare(program(base), f);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  drawDisc(f, base);
  drawHorizonEdge(f, base);
}

// The strip a pixel and a half wide either side of the horizon (its pixels' centres lie within
// half a diagonal of the line, and an angle on the sphere is at least the difference of the
// elevations), with the disc where the sun is on it. Drawn last, over the parts' pixels: those
// it does not discard are the ones the horizon crosses. The caller leaves no depth test on.
void PhysicalSkyPass::drawHorizonEdge(const Frame& f, const SkyVariant& base) {
  constexpr int kSegments = 256;
  SkyVariant v = base;
  v.part = SkyVariant::Part::horizonEdge;
  v.sunDisc = f.sunlit;
  v.nightLayerTransmitted = false;
  const Program& edge = program(v);
  prepare(edge, f);
  const double margin = 1.5 * pixelAngleRad_ + 1e-5;
  const double half = 0.5 * std::numbers::pi - 1e-3;
  const double low = std::max(f.horizon - margin, -half), high = std::min(f.horizon + margin, half);
  glProgramUniform4f(edge.program.id(), edge.horizonStrip, static_cast<float>(std::sin(low)),
                     static_cast<float>(std::cos(low)), static_cast<float>(std::sin(high)), static_cast<float>(kSegments));
  glDrawArrays(GL_TRIANGLES, 0, 6 * kSegments);
}

// The ground, the band and the sky, each where the depth buffer still holds the clear's 1 (all
// at depth 0.5: early depth testing skips the pixels an earlier part drew). The sky writes no
// depth, so the disc's quad after it draws where the sky is; the horizon's edge last, over all.
void PhysicalSkyPass::drawParts(const Frame& f, const SkyVariant& base) {
  constexpr int kSegments = 256;
  using Part = SkyVariant::Part;
  const NightLayer& night = *f.night;
  const bool band = night.texture != 0 && night.transmitted != 0;
  SkyVariant v = base;
  v.part = Part::ground;
  const Program& ground = program(v);
  prepare(ground, f);
  // The ring a little above the horizon: 0.1 deg encloses its circle whatever the fan's chords
  // cut ((2 pi / 256)^2 / 8 = 7.5e-5 rad inside the ring).
  const double ring = f.horizon + 0.1 * std::numbers::pi / 180.0;
  glProgramUniform3f(ground.program.id(), ground.groundCap, static_cast<float>(std::sin(ring)),
                     static_cast<float>(std::cos(ring)), static_cast<float>(kSegments));
  glDepthMask(GL_TRUE);
  glDrawArrays(GL_TRIANGLES, 0, 3 * kSegments);
  // With the night's layer: the sky near the horizon with its transmittance per pixel, on the
  // cap below a ring kNightLayerBandDeg up (its chords' great circles bulge upwards, so it holds
  // every direction below the ring), then the rest reading the layer dimmed at its texels.
  if (band) {
    v.part = Part::horizonBand;
    const Program& nearHorizon = program(v);
    prepare(nearHorizon, f);
    const double e0 = kNightLayerBandDeg * std::numbers::pi / 180.0;
    glProgramUniform3f(nearHorizon.program.id(), nearHorizon.groundCap, static_cast<float>(std::sin(e0)),
                       static_cast<float>(std::cos(e0)), static_cast<float>(kSegments));
    glDrawArrays(GL_TRIANGLES, 0, 3 * kSegments);
    glBindTextureUnit(SKYIG_UNIT_NIGHT_LAYER, night.transmitted);
  }
  v.part = Part::sky;
  v.nightLayerTransmitted = band;
  prepare(program(v), f);
  glDepthMask(GL_FALSE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (band) glBindTextureUnit(SKYIG_UNIT_NIGHT_LAYER, night.texture);
  v.nightLayerTransmitted = false;
  drawDisc(f, v);  // where the sky is: no depth written; the night's light per pixel
  glDisable(GL_DEPTH_TEST);
  drawHorizonEdge(f, base);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
}

bool PhysicalSkyPass::draw(const glm::dvec3& camera, const glm::dvec3& sunDirection, const glm::dvec3& moonDirection,
                           const glm::dvec3& moonlightScale, const glm::dvec4& sunRefraction,
                           const FoldedTone& tone, const NightLayer& night, bool sunlit) {
  // The frame's variant: the sun's light left out only inside the atmosphere (the space
  // program keeps it), the night's layer, the tone folded in; and the same with the veil per
  // pixel for the boxes of the exact glare veil (render/passes/tone/folded_tone.h).
  SkyVariant base;
  base.moonlit = moonlightScale != glm::dvec3(0.0);
  base.sunless = !sunlit;
  // The weather's layers only when one is on: clear air pays nothing for them.
  base.fog = std::any_of(fog_.begin(), fog_.end(), [](const weather::FogLayer& l) { return l.extinction > 0.0; });
  base.cloudCover = base.fog ? brokenDecks() : 0;

  base.nightLayer = night.texture != 0;
  base.nightLayerCellPx = base.nightLayer ? night.cellPx : 0;
  base.tone = tone.defines;
  const bool exactBoxes = !tone.defines.empty() && !tone.exactBoxes.empty();
  const auto exactVariant = [&] {  // built only when there are boxes: no string copied per frame otherwise
    SkyVariant v = base;
    v.tone = tone.exactDefines;
    return v;
  };
  stepUpload();
  if (!current_.model) throw std::logic_error("PhysicalSkyPass::draw before use()");
  cloudLightLowestZ_ = std::min(sunlit ? sunDirection.z : 1.0, base.moonlit ? moonDirection.z : 1.0);
  base.cloudLight = base.fog ? litDecks(glm::length(camera) - current_.model->parameters(0).bottom_radius).count : 0;
  bindTables(night);
  cloudField_ = {};
  if (glm::length(camera) > current_.model->parameters(0).top_radius) {
    drawFromSpace(camera, sunDirection, moonDirection, moonlightScale, sunRefraction);
    return !base.extended();
  }
  // The camera inside the atmosphere (every IG frame): what every pixel shares, in double, once.
  const Frame f = frameInside(camera, sunDirection, moonDirection, moonlightScale, sunRefraction, night, sunlit);
  if (base.fog) {
    const double h = glm::length(camera) - current_.model->parameters(0).bottom_radius;
    fogTable_->use(fog_, h, SKYIG_UNIT_FOG_TABLE, h == fogPrecomputedHeightM_ ? fogPrecomputed_ : nullptr);
    if (base.cloudCover > 0) {
      fogClearTable_->use(fogClear_, h, SKYIG_UNIT_FOG_CLEAR_TABLE,
                          h == fogPrecomputedHeightM_ ? fogClearPrecomputed_ : nullptr);
      cloudField_ = {cover_, fog_, h, current_.model->parameters(0).bottom_radius, fogTable_->id(), fogClearTable_->id()};
    }
    if (base.cloudLight > 0) updateCloudLightTable(litDecks(h), h);
  }
  const GLint target = drawSlices(f);
  if (reference_) {  // the frozen reference: everything in one program, the moon a uniform branch
    prepare(*reference_, f);
    glProgramUniform1i(reference_->program.id(), reference_->moonOn, f.moon ? 1 : 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return !base.extended();
  }
  // The sky and ground, with the moon's light only when it lights the sky: into a target with
  // depth, the ground's rays first on the cap below the horizon, then the sky's where the
  // ground wrote no depth (early depth testing skips the ground's pixels); else both at once.
  GLint depthType = GL_NONE;
  if (target != 0)
    glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(target), GL_DEPTH_ATTACHMENT,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &depthType);
  if (depthType == GL_NONE) {
    drawWithoutDepth(f, base);
    if (exactBoxes) {  // drawn over
      const SkyVariant exact = exactVariant();
      glEnable(GL_SCISSOR_TEST);
      for (const glm::ivec4& b : tone.exactBoxes) {
        glScissor(b.x, b.y, b.z, b.w);
        drawWithoutDepth(f, exact);
      }
      glDisable(GL_SCISSOR_TEST);
    }
    return true;
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  if (!exactBoxes) {
    drawParts(f, base);
  } else {
    // Everywhere but the boxes (held at depth 0, where no part passes), then each box on its own.
    glEnable(GL_SCISSOR_TEST);
    glClearDepth(0.0);
    for (const glm::ivec4& b : tone.exactBoxes) {
      glScissor(b.x, b.y, b.z, b.w);
      glClear(GL_DEPTH_BUFFER_BIT);
    }
    glClearDepth(1.0);
    glDisable(GL_SCISSOR_TEST);
    drawParts(f, base);
    const SkyVariant exact = exactVariant();
    glEnable(GL_SCISSOR_TEST);
    for (const glm::ivec4& b : tone.exactBoxes) {
      glScissor(b.x, b.y, b.z, b.w);
      glClear(GL_DEPTH_BUFFER_BIT);
      drawParts(f, exact);
    }
    glDisable(GL_SCISSOR_TEST);
  }
  glDisable(GL_DEPTH_TEST);
  return true;
}

}  // namespace skyig::render
