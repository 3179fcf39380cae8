#pragma once
// Renders one channel of a skyig::sky::SkyState: the sky pass into a float target (absolute radiance),
// then tone reproduction into an 8-bit target (what the projector shows).
#include "calibration/projector.h"
#include "sky/channel.h"
#include "render/gl/gl_program.h"
#include "render/image.h"
#include "render/passes/night/moon_pass.h"
#include "render/passes/night/night_diffuse_pass.h"
#include "render/passes/sky/physical_sky_pass.h"
#include "render/gl/render_target.h"
#include "sky/sky_state.h"
#include "render/passes/night/star_pass.h"
#include "render/passes/tone/tone_pass.h"
#include "render/passes/goggle/goggle_pass.h"

#include <array>
#include "render/passes/projector/warp_blend_pass.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace skyig::render {

class SkyRenderer {
 public:
  // Needs the GL context current on the calling thread, now and for every call.
  SkyRenderer();
  ~SkyRenderer();

  // Draws every pass of `channel` for the ownship's `attitude` at the frame's instant (the node
  // predicts it per frame; the state was built at the worker's instant and is never patched);
  // the targets stay bound to the renderer until the next call. A goggle channel
  // (sky::isGoggle) is drawn in its band with its own frustum (sky::goggleFrustum) and shown
  // through its image intensifier (render/passes/goggle/goggle_pass.h); its HDR image is then the NVIS
  // radiance, W m^-2 sr^-1 in all three channels.
  void draw(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
            const skyig::sky::ChannelConfig& channel);
  // The same with the state's own observer's attitude (single renders, tests).
  void draw(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel) {
    draw(state, state.observer.attitude, channel);
  }
  // What a draw() would change in the renderer's own state, without drawing anything: the
  // physical sky's pending tables take their next slices. Drawn later, a frame then shows what
  // it would have shown had every frame before it been drawn.
  void advance(const skyig::sky::SkyState& state);
  // Draws `channel` for a projector: the calibration's region camera, where it gives one,
  // replaces the channel's offset and frustum (the channel's size stays the render size), the
  // tone pass writes the
  // undithered display values into a float target, and the warp-and-blend pass makes the
  // projector's image and light (readProjectorDisplay, readProjectorHdr). The calibration's maps
  // are uploaded the first time it is drawn and kept until no one else holds the calibration.
  void drawProjector(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                     const skyig::sky::ChannelConfig& channel,
                     const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector);
  void drawProjector(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel,
                     const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector) {
    drawProjector(state, state.observer.attitude, channel, projector);
  }
  // Only the warp-and-blend pass again, from the last drawProjector's channel images (for
  // benchmarks of the pass itself).
  void drawWarpBlendPass(const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector);
  // The channel as a projector draws it: its offset and frustum the region's, where the
  // calibration gives a camera.
  static skyig::sky::ChannelConfig projectorChannel(const skyig::sky::ChannelConfig& channel,
                                                    const skyig::calibration::ProjectorCalibration& projector);

  // Draws only the sky pass (for benchmarks of the pass itself).
  void drawSkyPass(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                   const skyig::sky::ChannelConfig& channel);
  void drawSkyPass(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel) {
    drawSkyPass(state, state.observer.attitude, channel);
  }

  // Draws what a frame draws up to its sky pass (for benchmarks): its tone prepared (the glare
  // veil's grid), its night layer, and the sky pass mapping its own pixels to the display.
  void drawMappedSkyPass(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                         const skyig::sky::ChannelConfig& channel);
  void drawMappedSkyPass(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel) {
    drawMappedSkyPass(state, state.observer.attitude, channel);
  }

  // Whether the physical sky pass maps its own pixels to the display where no full-screen pass
  // follows it (on by default; drawChannel in sky_renderer.cpp): off, the tone pass maps every
  // pixel after the others, as it always did; for the tests and the benchmark that compare the two.
  void setToneFolding(bool on) { foldTone_ = on; }
  // Whether, on a night with one glare source, the night's layer holds its veil (on by default;
  // drawMappedSky in sky_renderer.cpp): off, the veil comes from its own grid, as by day; for the
  // test that compares the two.
  void setGlareVeilInNightLayer(bool on) { veilInNightLayer_ = on; }

  // Copies the last tone-reproduced frame to the window's back buffer (windowed channels): the
  // projector's image when the last draw was drawProjector.
  void presentToDefaultFramebuffer(int windowWidth, int windowHeight) const;

  // The physical sky pass, once a state needed it (its table upload state, for tests and
  // benchmarks); null before.
  const PhysicalSkyPass* physicalPass() const { return physical_.get(); }
  // The goggle pass, once a goggle channel was drawn (tests); null before.
  const GogglePass* gogglePass() const { return goggle_.get(); }
  // The physical sky pass for `state` (a physical sky's), made the first time and told to use
  // the state's model (uploaded at once the first time, else over the next draws).
  PhysicalSkyPass& physicalPassFor(const skyig::sky::SkyState& state);
  // Draws the physical sky with `pass` from now on (the frozen reference of
  // render/passes/sky/reference_sky_pass.h, for its benchmark and test) instead of its own.
  void usePhysicalSkyPass(std::unique_ptr<PhysicalSkyPass> pass) { physical_ = std::move(pass); }

  // The last draw's channel: its HDR image (the region's camera after drawProjector) and its
  // display frame (draw only).
  HdrImage readHdr() const;
  DisplayImage readDisplay() const;
  // The same two images on the GPU, channel-sized (RGBA32F cd/m^2 and RGBA8 display values),
  // for a pass that composites them into another framebuffer (render/client/client_frame.h); 0 before
  // the first draw.
  GLuint hdrTexture() const { return hdr_ ? hdr_->texture() : 0; }
  GLuint displayTexture() const { return display_ ? display_->texture() : 0; }
  // The last drawProjector's outputs at the projector's resolution: the 8-bit image sent to
  // the projector, and the light it contributes (the channel's cd/m^2 warped, times alpha).
  DisplayImage readProjectorDisplay() const;
  HdrImage readProjectorHdr() const;
  // The displayed stars and planets of the last frame, display cd/m^2 that the tone pass added
  // to the mapped sky (linear Rec.709; zero where there is none).
  HdrImage readPointSources() const;

 private:
  void ensureTargets(int width, int height);
  // The frame, sky and band blocks of a channel, uploaded and bound.
  void bindChannelBlocks(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                         const skyig::sky::ChannelConfig& channel);
  // The sky pass into the bound framebuffer; with a tone (TonePass::folded) the
  // physical pass maps its pixels to the display too, into the framebuffer's second target, and
  // with a night layer adds the night's light: whether it drew all it was asked.
  bool drawSky(const skyig::sky::SkyState& state, const skyig::sky::ChannelConfig& channel,
               const FoldedTone& tone, const NightLayer& night);
  // Every pass of the channel, the tone pass into `toneTarget` with a dither of `ditherLsb`.
  void drawChannel(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                   const skyig::sky::ChannelConfig& channel, const RenderTarget& toneTarget, float ditherLsb);
  // drawChannel's first part: the channel's blocks, the tone prepared, the night's layer and the
  // sky pass, mapping its own pixels into `toneTarget` where it can (`folded`).
  struct MappedSky {
    glm::dmat3 ndcToWorld;
    bool nightLight = false;  // the night's own light is drawn (sky/shown_layers.h)
    bool nightLayer = false;  // the sky pass was given the night's layer
    bool drewAll = false;     // drawSky's answer
    bool folded = false;      // the sky pass mapped every pixel to the display
  };
  // The broken decks the physical sky pass just drew for `state`, for the night's light drawn
  // over it (none for another sky).
  CloudFieldView cloudFieldShown(const skyig::sky::SkyState& state) const;
  MappedSky drawMappedSky(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                          const skyig::sky::ChannelConfig& channel, const RenderTarget& toneTarget, float ditherLsb);
  // The same for a goggle channel: its band, its frustum, its intensifier instead of the eye's tone.
  void drawGoggleChannel(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                         const skyig::sky::ChannelConfig& channel, const RenderTarget& toneTarget, float ditherLsb);
  const ProjectorMaps& mapsFor(const std::shared_ptr<const skyig::calibration::ProjectorCalibration>& projector);

  GlProgram skyProgram_;
  UniformBuffer frameBlock_;
  UniformBuffer skyBlock_;
  UniformBuffer toneBlock_;
  UniformBuffer bandBlock_;
  GLuint emptyVao_ = 0;
  std::unique_ptr<PhysicalSkyPass> physical_;  // compiled the first time a state needs it
  std::unique_ptr<MoonPass> moon_;             // likewise, the first time a state has a moon
  std::unique_ptr<StarPass> stars_;
  std::unique_ptr<NightDiffusePass> nightDiffuse_;  // Milky Way, zodiacal light, airglow
  std::unique_ptr<TonePass> tone_;
  std::unique_ptr<GogglePass> goggle_;  // the first time a goggle channel is drawn
  std::unique_ptr<RenderTarget> hdr_;
  std::unique_ptr<RenderTarget> display_;
  std::unique_ptr<RenderTarget> pointSources_;  // displayed stars, display cd/m^2 (StarPass::drawDisplayed)
  bool pointSourcesDrawn_ = true;  // pointSources_ may hold something: clear it before a frame reads it
  std::unique_ptr<RenderTarget> displayValues_;  // a projector channel's undithered display values (RGBA16F)
  // The HDR image with the display (or the projector's display values) beside it, for a sky
  // pass that maps its own pixels.
  std::unique_ptr<TwoTargetFramebuffer> foldedDisplay_, foldedValues_;
  bool foldTone_ = true;
  bool veilInNightLayer_ = true;
  std::unique_ptr<WarpBlendPass> warpBlend_;     // the first time a projector is drawn
  // The calibrations drawn so far and their maps on the GPU; holding them keeps their
  // addresses from being reused by another calibration.
  std::vector<std::pair<std::shared_ptr<const skyig::calibration::ProjectorCalibration>, std::unique_ptr<ProjectorMaps>>>
      projectorMaps_;
  bool lastWasProjector_ = false;
  double lastProjectorGamma_ = 2.2;
};

}  // namespace skyig::render
