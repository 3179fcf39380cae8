#include "render/sky_renderer.h"

#include "render/texture_readback.h"
#include "render/glsl/band_uniforms.h"
#include "sky/nvis_weights.h"
#include "physics/physics.h"

#include "render/glsl/bindings.h"
#include "render/glsl/uniforms.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::render {

namespace {

glm::vec4 v4(const glm::dvec3& v, double w = 0.0) { return glm::vec4(glm::dvec4(v, w)); }

AnalyticSkyBlock toBlock(const skyig::sky::AnalyticSkyParams& p) {
  AnalyticSkyBlock b{};
  b.perezA = v4(p.a);
  b.perezB = v4(p.b);
  b.perezC = v4(p.c);
  b.perezD = v4(p.d);
  b.perezE = v4(p.e);
  b.perezK = v4(p.k);
  b.zenith = v4(p.zenith);
  b.skySunDirection = v4(p.skySunDirection, p.luminanceScale);
  b.sunDirection = v4(p.sunDirection, p.cosSunRadius);
  b.sunRadiance = v4(p.sunRadiance);
  b.groundRadiance = v4(p.groundRadiance);
  return b;
}

FrameBlock toBlock(const skyig::sky::Attitude& attitude, const skyig::sky::ChannelConfig& channel) {
  FrameBlock b{};
  const glm::dmat3 m = skyig::sky::ndcToWorld(skyig::sky::eyeToEnu(attitude, channel.offset), channel.frustum);
  b.ndcToWorld = glm::mat4(glm::mat3(m));
  b.viewport = glm::vec4(static_cast<float>(channel.width), static_cast<float>(channel.height),
                         1.0f / static_cast<float>(channel.width), 1.0f / static_cast<float>(channel.height));
  return b;
}

// The state's glare sources that give light, in its order: the tone block holds them first and
// the tone pass's variant evaluates only those.
std::vector<skyig::sky::eye::GlareSource> litGlareSources(const skyig::sky::SkyState& state) {
  std::vector<skyig::sky::eye::GlareSource> lit;
  for (const skyig::sky::eye::GlareSource& g : state.glare)
    if (g.rec709Lux != glm::dvec3(0.0)) lit.push_back(g);
  return lit;
}

ToneBlock toToneBlock(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel) {
  ToneBlock b{};
  const skyig::sky::DisplayParams& d = channel.display;
  b.display = glm::vec4(glm::dvec4(d.maxLuminance, d.ambientLuminance, d.gamma, d.viewerAdaptationLuminance));
  const bool histogram = d.toneOperator == skyig::sky::ToneOperator::Histogram;
  b.adaptation = glm::vec4(static_cast<float>(state.worldAdaptationLuminance), 1.0f, histogram ? 0.0f : 1.0f, 0.0f);
  const std::vector<skyig::sky::eye::GlareSource> lit = litGlareSources(state);
  for (std::size_t i = 0; i < lit.size(); ++i) {
    b.glareDirection[i] = glm::vec4(glm::vec3(lit[i].direction), static_cast<float>(lit[i].angularRadiusRad * 180.0 / 3.14159265358979));
    b.glareLux[i] = glm::vec4(glm::vec3(lit[i].rec709Lux), 0.0f);
  }
  b.glareCoefficients = glm::vec4(skyig::shader::veilCoefficients(skyig::sky::eye::kGlareObserverAgeYears,
                                                                  skyig::sky::eye::kGlareOcularPigmentation));
  if (histogram) {
    const skyig::sky::eye::ToneCurve curve = skyig::sky::toneCurveFor(state, d);
    b.curveRange = glm::vec4(static_cast<float>(curve.minLog10), static_cast<float>(curve.maxLog10), 0.0f, 0.0f);
    for (int i = 0; i < skyig::sky::eye::ToneCurve::kPoints; ++i)
      b.curve[i / 4][i % 4] = curve.displayLog10[static_cast<std::size_t>(i)];
  }
  return b;
}

// The channel's band for its passes (sky/nvis_weights.h), its weights taken along the
// channel's centre.
BandBlock toBandBlock(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                      const skyig::sky::ChannelConfig& channel) {
  BandBlock b{};
  if (!skyig::sky::isGoggle(channel)) return b;
  const glm::dvec3 centre = skyig::sky::ndcToWorld(skyig::sky::eyeToEnu(attitude, channel.offset), channel.frustum) *
                            glm::dvec3(0.0, 0.0, 1.0);
  const skyig::sky::NvisWeights w = skyig::sky::nvisWeights(channel.band, state, centre);
  b.band = glm::vec4(1.0f, static_cast<float>(w.sunDisc / w.sunlitSky), static_cast<float>(w.moonlitSky / w.sunlitSky), 0.0f);
  b.lightWeights = glm::vec4(glm::dvec4(w.sunlitSky, w.moon, w.airglow, w.zodiacal));
  b.nightWeights = glm::vec4(static_cast<float>(w.milkyWay), static_cast<float>(w.nightGround), 0.0f, 0.0f);
  return b;
}

// The seed of a goggle frame's noise: the state's instant and the channel's name (FNV-1a), so
// a replay draws the same noise and two goggles of one node do not.
std::uint32_t goggleSeed(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      h ^= static_cast<const unsigned char*>(data)[i];
      h *= 1099511628211ull;
    }
  };
  const skyig::ephemeris::UtcTime& t = state.observer.utc;
  const std::int64_t ymd[3] = {t.year, t.month, t.day};
  mix(ymd, sizeof(ymd));
  mix(&t.secondsOfDay, sizeof(t.secondsOfDay));
  mix(channel.name.data(), channel.name.size());
  return static_cast<std::uint32_t>(h ^ (h >> 32));
}

}  // namespace

SkyRenderer::SkyRenderer()
    : skyProgram_("render/glsl/fullscreen.vert", "render/passes/sky/analytic_sky.frag"),
      frameBlock_(SKYIG_BINDING_FRAME, sizeof(FrameBlock)),
      skyBlock_(SKYIG_BINDING_SKY, sizeof(AnalyticSkyBlock)),
      toneBlock_(SKYIG_BINDING_TONE, sizeof(ToneBlock)),
      bandBlock_(SKYIG_BINDING_BAND, sizeof(BandBlock)) {
  glCreateVertexArrays(1, &emptyVao_);  // the full-screen triangle needs no vertex data
  bandBlock_.upload(BandBlock{});  // the eye's band until a channel says otherwise
  bandBlock_.bind();
}

SkyRenderer::~SkyRenderer() { glDeleteVertexArrays(1, &emptyVao_); }

void SkyRenderer::ensureTargets(int width, int height) {
  if (hdr_ && hdr_->width() == width && hdr_->height() == height) return;
  foldedDisplay_.reset();  // before the targets they draw into
  foldedValues_.reset();
  hdr_ = std::make_unique<RenderTarget>(width, height, GL_RGBA32F, true);
  display_ = std::make_unique<RenderTarget>(width, height, GL_RGBA8);
  pointSources_ = std::make_unique<RenderTarget>(width, height, GL_RGBA16F);
  displayValues_ = std::make_unique<RenderTarget>(width, height, GL_RGBA16F);
  pointSourcesDrawn_ = true;  // a new target's texels are undefined: cleared before first use
  foldedDisplay_ = std::make_unique<TwoTargetFramebuffer>(*hdr_, *display_);
  foldedValues_ = std::make_unique<TwoTargetFramebuffer>(*hdr_, *displayValues_);
}

void SkyRenderer::advance(const skyig::sky::SkyState& state) {
  if (state.conditions.model == skyig::sky::SkyModel::Physical) physicalPassFor(state).stepUpload();
}

PhysicalSkyPass& SkyRenderer::physicalPassFor(const skyig::sky::SkyState& state) {
  if (!state.conditions.atmosphere) throw std::invalid_argument("physical sky without an atmosphere model");
  if (!physical_) physical_ = std::make_unique<PhysicalSkyPass>();
  physical_->use(state.conditions.atmosphere);
  return *physical_;
}

void SkyRenderer::bindChannelBlocks(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                                    const skyig::sky::ChannelConfig& channel) {
  frameBlock_.upload(toBlock(attitude, channel));
  skyBlock_.upload(toBlock(state.sky.params));
  bandBlock_.upload(toBandBlock(state, attitude, channel));
  frameBlock_.bind();
  skyBlock_.bind();
  bandBlock_.bind();
}

bool SkyRenderer::drawSky(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel,
                          const FoldedTone& tone, const NightLayer& night) {
  glBindVertexArray(emptyVao_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  if (state.conditions.model == skyig::sky::SkyModel::Physical) {
    physicalPassFor(state);
    // The tables on screen may still be the previous model's while a new one uploads; both
    // share the planet, so the camera is the same. The moonlit sky, and the sun's own sky at
    // night, only where they change what the displays show (sky/shown_layers.h), and always in
    // a goggle, which sees far fainter light than the eye.
    const weather::FogLayers drawn = skyig::sky::isGoggle(channel)
                                         ? skyig::sky::goggleFogLayers(state, skyig::sky::nvisClassOf(channel.band))
                                         : sky::drawnFogLayers(state.fog);
    // A broken deck: drawn where its field has cloud (the layers with its gaps filled, mixed per
    // pixel with those without it).
    physical_->setFog(sky::clouded(state.fog, drawn), skyig::sky::fogTableFor(state.fog, channel.band),
                      state.fog.tables.heightM);
    physical_->setCloudCover(state.fog.cover, sky::withoutBrokenDecks(state.fog, drawn),
                             skyig::sky::clearFogTableFor(state.fog, channel.band));
    physical_->setPixelAngle(skyig::sky::largestPixelAngleRad(channel.frustum, channel.width, channel.height));
    physical_->setSunThroughFog(
        state.fog.any() ? sky::fogTransmittanceToSpaceAlong(state.fog, *state.conditions.atmosphere, state.observer.heightM,
                                                            sky::enuDirection(state.sunAzimuth, state.sunApparentAltitude))
                        : 1.0);
    return physical_->draw(atmosphere::physicalCamera(*state.conditions.atmosphere, state.observer.heightM),
                           skyig::sky::enuDirection(state.sunAzimuth, state.sunAltitude), state.moonDirection,
                           state.shown.moonlitSky || skyig::sky::isGoggle(channel) ? state.moonlightScale
                                                                                    : glm::dvec3(0.0),
                           state.sunRefraction, tone, night,
                           state.shown.sunlitSky || skyig::sky::isGoggle(channel));
  }
  skyProgram_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  return tone.defines.empty() && night.texture == 0;
}

void SkyRenderer::drawSkyPass(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                              const skyig::sky::ChannelConfig& channel) {
  ensureTargets(channel.width, channel.height);
  bindChannelBlocks(state, attitude, channel);
  hdr_->bindForDrawing();
  drawSky(state, channel, {}, {});
}

void SkyRenderer::drawMappedSkyPass(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                                    const skyig::sky::ChannelConfig& channel) {
  if (skyig::sky::isGoggle(channel)) throw std::invalid_argument("drawMappedSkyPass: a goggle channel has no eye's tone");
  ensureTargets(channel.width, channel.height);
  drawMappedSky(state, attitude, channel, *display_, 1.0f);
}

void SkyRenderer::draw(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                       const skyig::sky::ChannelConfig& channel) {
  ensureTargets(channel.width, channel.height);
  drawChannel(state, attitude, channel, *display_, 1.0f);
  lastWasProjector_ = false;
}

skyig::sky::ChannelConfig SkyRenderer::projectorChannel(const skyig::sky::ChannelConfig& channel,
                                                        const skyig::calibration::ProjectorCalibration& projector) {
  skyig::sky::ChannelConfig c = channel;
  if (projector.cameraGiven) {  // else (MPCDI 2d, a Bourke mesh) the channel's own camera
    c.offset = projector.camera.offset;
    c.frustum = projector.camera.frustum;
  }
  return c;
}

const ProjectorMaps& SkyRenderer::mapsFor(
    const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector) {
  for (const auto& [calibration, maps] : projectorMaps_)
    if (calibration == projector) return *maps;
  // Calibrations only this renderer still holds can never be drawn again (a reloaded one is a
  // new object): their textures go.
  std::erase_if(projectorMaps_, [](const auto& entry) { return entry.first.use_count() == 1; });
  projectorMaps_.emplace_back(projector, std::make_unique<ProjectorMaps>(*projector));
  return *projectorMaps_.back().second;
}

void SkyRenderer::drawProjector(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                                const skyig::sky::ChannelConfig& channel,
                                const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector) {
  if (!projector) throw std::invalid_argument("drawProjector without a calibration");
  const ProjectorMaps& maps = mapsFor(projector);
  const skyig::sky::ChannelConfig c = projectorChannel(channel, *projector);
  ensureTargets(c.width, c.height);
  // Undithered into a float target: the warp resamples it and dithers what the projector gets.
  drawChannel(state, attitude, c, *displayValues_, 0.0f);
  if (!warpBlend_) warpBlend_ = std::make_unique<WarpBlendPass>();
  warpBlend_->draw(maps, displayValues_->texture(), hdr_->texture(), c.display.gamma, 1.0);
  lastWasProjector_ = true;
  lastProjectorGamma_ = c.display.gamma;
}

void SkyRenderer::drawWarpBlendPass(const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector) {
  if (!warpBlend_) throw std::logic_error("drawWarpBlendPass before any drawProjector");
  warpBlend_->draw(mapsFor(projector), displayValues_->texture(), hdr_->texture(), lastProjectorGamma_, 1.0);
}

void SkyRenderer::drawChannel(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                              const skyig::sky::ChannelConfig& channel, const RenderTarget& toneTarget,
                              float ditherLsb) {
  if (skyig::sky::isGoggle(channel)) {
    drawGoggleChannel(state, attitude, channel, toneTarget, ditherLsb);
    return;
  }
  const MappedSky sky = drawMappedSky(state, attitude, channel, toneTarget, ditherLsb);
  const glm::dmat3& ndcToWorld = sky.ndcToWorld;
  hdr_->bindForDrawing();
  glm::ivec4 moonPixels(0);
  if (state.ephemeris) moonPixels = (moon_ ? *moon_ : *(moon_ = std::make_unique<MoonPass>())).draw(state, attitude, channel);
  if (sky.nightLight && !(sky.nightLayer && sky.drewAll))
    (nightDiffuse_ ? *nightDiffuse_ : *(nightDiffuse_ = std::make_unique<NightDiffusePass>())).draw(state, cloudFieldShown(state));
  if (!stars_) stars_ = std::make_unique<StarPass>();
  glBindVertexArray(emptyVao_);
  // Stars and planets as displayed, against the sky without them; the tone pass adds them to
  // the mapped sky, so it never maps a star as if it were sky (docs/night-sky-stars.md). Not
  // where none can pass the eye's threshold against the darkest of the view (sky/shown_layers.h):
  // the target is then left clear; else only the sources above that threshold.
  if (state.shown.pointSources || pointSourcesDrawn_) {
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(pointSources_->framebuffer(), GL_COLOR, 0, none);
    pointSourcesDrawn_ = false;
  }
  if (state.shown.pointSources) {
    pointSources_->bindForDrawing();
    stars_->drawDisplayed(state.starField, ndcToWorld, hdr_->texture(), state.shown.pointSourceFloorLux);
    pointSourcesDrawn_ = true;
  }
  glBindTextureUnit(SKYIG_UNIT_HDR_IMAGE, hdr_->texture());
  glBindTextureUnit(SKYIG_UNIT_POINT_SOURCES, pointSources_->texture());
  if (sky.folded)
    tone_->drawOver(toneTarget, std::span(&moonPixels, 1), [&](const GlProgram& quads) {
      if (state.shown.pointSources)
        stars_->drawFootprints(state.starField, ndcToWorld, hdr_->texture(), quads, state.shown.pointSourceFloorLux);
    });
  else
    tone_->draw(toneTarget);
  // Then into the HDR image in absolute units, every value kept for the EXR.
  hdr_->bindForDrawing();
  stars_->draw(state.starField, ndcToWorld);
}

CloudFieldView SkyRenderer::cloudFieldShown(const skyig::sky::SkyState& state) const {
  if (state.conditions.model != skyig::sky::SkyModel::Physical || !physical_) return {};
  return physical_->cloudField();
}

SkyRenderer::MappedSky SkyRenderer::drawMappedSky(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                                                  const skyig::sky::ChannelConfig& channel,
                                                  const RenderTarget& toneTarget, float ditherLsb) {
  const glm::dmat3 ndcToWorld = skyig::sky::ndcToWorld(skyig::sky::eyeToEnu(attitude, channel.offset), channel.frustum);
  bindChannelBlocks(state, attitude, channel);
  ToneBlock tone = toToneBlock(state, channel);
  tone.adaptation.y = ditherLsb;
  toneBlock_.upload(tone);
  toneBlock_.bind();
  // The tone's variant: the display's operator, with rod vision only where some of the view is
  // dim enough (sky/shown_layers.h) and the glare veil of the sources that give light.
  std::vector<glm::dvec3> glareSources;
  for (const skyig::sky::eye::GlareSource& g : litGlareSources(state)) glareSources.push_back(g.direction);
  // The night's own light only where it changes what the displays show (sky/shown_layers.h).
  const bool nightLight = state.ephemeris && state.shown.nightLight;
  // The physical sky pass draws the night's own light too, from a layer at about the Milky Way
  // map's resolution (NightDiffusePass::drawLayer), and maps its own pixels to the display as it
  // computes them: one pass over every pixel, where the night pass and the tone pass each read
  // every pixel back (docs/performance.md). The tone pass then runs only where later passes
  // drew. Where the sky pass cannot (the analytic skies, the physical one from space), the
  // night's pass and the tone pass cover every pixel after it. With one glare source (the moon)
  // the layer holds its veil too, which the sky pass then reads with the night's light instead
  // of from a grid of its own (render/passes/tone/tone_pass.h).
  const bool physical = state.conditions.model == skyig::sky::SkyModel::Physical;
  NightLayer night;
  if (nightLight && physical) {
    if (!nightDiffuse_) nightDiffuse_ = std::make_unique<NightDiffusePass>();
    const double pixelRad = skyig::sky::largestPixelAngleRad(channel.frustum, channel.width, channel.height);
    glBindVertexArray(emptyVao_);
    night = nightDiffuse_->drawLayer(state, channel.width, channel.height, nightDiffuse_->layerScale(pixelRad),
                                     veilInNightLayer_ && glareSources.size() == 1);
  }
  if (!tone_) tone_ = std::make_unique<TonePass>();
  tone_->prepare({channel.display.toneOperator != skyig::sky::ToneOperator::Histogram, !state.shown.mesopic}, ndcToWorld,
                 channel.width, channel.height, glareSources, night);
  const bool fold = foldTone_ && physical;
  if (fold)
    (toneTarget.texture() == display_->texture() ? *foldedDisplay_ : *foldedValues_).bindForDrawing();
  else
    hdr_->bindForDrawing();
  const bool drewAll = drawSky(state, channel, fold ? tone_->folded() : FoldedTone{}, night);
  return {ndcToWorld, nightLight, night.texture != 0, drewAll, fold && drewAll};
}

void SkyRenderer::drawGoggleChannel(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                                    const skyig::sky::ChannelConfig& channel, const RenderTarget& toneTarget,
                                    float ditherLsb) {
  skyig::sky::ChannelConfig c = channel;
  c.frustum = skyig::sky::goggleFrustum(channel);
  // Every layer of the night: the goggle sees light far below the eye's threshold, so what the
  // eye's visibility leaves out (sky/shown_layers.h) is drawn here, but for the diffuse night
  // light with the sun up: the sunlit sky outshines it by a million in any band.
  drawSkyPass(state, attitude, c);
  if (state.ephemeris) {
    (moon_ ? *moon_ : *(moon_ = std::make_unique<MoonPass>())).draw(state, attitude, c);
    if (state.sunAltitude < 0.0)
      (nightDiffuse_ ? *nightDiffuse_ : *(nightDiffuse_ = std::make_unique<NightDiffusePass>())).draw(state, cloudFieldShown(state));
  }
  if (!stars_) stars_ = std::make_unique<StarPass>();
  hdr_->bindForDrawing();
  stars_->draw(state.starField, skyig::sky::ndcToWorld(skyig::sky::eyeToEnu(attitude, c.offset), c.frustum), c.band);
  ToneBlock tone = toToneBlock(state, c);
  tone.adaptation.y = ditherLsb;
  toneBlock_.upload(tone);
  toneBlock_.bind();
  if (!goggle_) goggle_ = std::make_unique<GogglePass>();
  goggle_->draw(hdr_->texture(), c,
                skyig::sky::nvisPerLuxOfBlackbody(kIlluminantAKelvin, skyig::sky::nvisClassOf(c.band)),
                goggleSeed(state, c), toneTarget);
}

void SkyRenderer::presentToDefaultFramebuffer(int windowWidth, int windowHeight) const {
  if (lastWasProjector_) {  // the image the projector is sent (its colour attachment 0)
    glBlitNamedFramebuffer(warpBlend_->framebuffer(), 0, 0, 0, warpBlend_->width(), warpBlend_->height(), 0, 0,
                           windowWidth, windowHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return;
  }
  // A channel drawn at its window's size is copied; one drawn smaller (a node that degrades) is
  // stretched with bilinear filtering, not blocks.
  const bool sameSize = display_->width() == windowWidth && display_->height() == windowHeight;
  glBlitNamedFramebuffer(display_->framebuffer(), 0, 0, 0, display_->width(), display_->height(), 0, 0,
                         windowWidth, windowHeight, GL_COLOR_BUFFER_BIT, sameSize ? GL_NEAREST : GL_LINEAR);
}

HdrImage SkyRenderer::readHdr() const { return readFloatTexture(hdr_->texture(), hdr_->width(), hdr_->height()); }

HdrImage SkyRenderer::readPointSources() const {
  return readFloatTexture(pointSources_->texture(), pointSources_->width(), pointSources_->height());
}

DisplayImage SkyRenderer::readDisplay() const {
  return readDisplayTexture(display_->texture(), display_->width(), display_->height());
}

DisplayImage SkyRenderer::readProjectorDisplay() const {
  if (!warpBlend_) throw std::logic_error("readProjectorDisplay before any drawProjector");
  return readDisplayTexture(warpBlend_->displayTexture(), warpBlend_->width(), warpBlend_->height());
}

HdrImage SkyRenderer::readProjectorHdr() const {
  if (!warpBlend_) throw std::logic_error("readProjectorHdr before any drawProjector");
  return readFloatTexture(warpBlend_->lightTexture(), warpBlend_->width(), warpBlend_->height());
}

}  // namespace skyig::render
