#pragma once
// What `serve` renders into: one headless context for every channel, or one window per
// channel (fullscreen on its configured monitor, else side by side on the desktop). No
// sockets, no host state: it draws a SkyState seen with an attitude through the node's
// channels.
//
// Every window shows the same frame at the display's full rate: all channels are drawn, the
// frame waits until every window's pixels exist (a fence per window), then every window
// swaps; only the last swap waits for the vertical blank (swap interval 1), the others have
// interval 0 and return at once. N windows each waiting for their own vertical blank would
// take N refreshes per frame on most drivers (docs/performance.md, "Presentation"). Where
// the driver offers GLX_NV_swap_group the windows also join swap group 1 / barrier 1.
#include "calibration/projector.h"
#include "render/gl/gl_context.h"
#include "render/gl/glfw_window.h"
#include "render/sky_renderer.h"
#include "sky/camera.h"
#include "sky/channel.h"
#include "sky/sky_state.h"

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace skyig::services {

class DisplayOutputs {
 public:
  using Projector = std::shared_ptr<const calibration::ProjectorCalibration>;
  // `nodeName` titles the windows ("skyig <node> / <channel>"). `projectors`, empty or one per
  // channel (null: a plain channel): a channel with a projector is drawn warped and blended for
  // it (SkyRenderer::drawProjector) and its window is the projector's size.
  DisplayOutputs(bool headless, const std::string& nodeName, const std::vector<sky::ChannelConfig>& channels,
                 std::vector<Projector> projectors = {});

  const render::GlInfo& info() const;
  bool closeRequested() const;

  // The channel's renderer right after its frame, and its projector (null for a plain channel).
  using DrawnCallback =
      std::function<void(const render::SkyRenderer&, const sky::ChannelConfig&, const calibration::ProjectorCalibration*)>;
  // Draws every channel; `drawn` sees each channel's renderer right after its frame (to save it).
  // `channels` are the constructor's, each seen for this frame (same order; a channel may be
  // drawn smaller than its window, which then shows it stretched).
  void draw(const sky::SkyState& state, const sky::Attitude& attitude, const std::vector<sky::ChannelConfig>& channels,
            const DrawnCallback& drawn = {});

  // Draws every channel once without showing it (no swap, no file): the programs a frame of
  // `state` needs are compiled now rather than in the frame that first needs them (the node
  // warms up with a foggy copy of its first state, so the first weather costs no frame).
  void warmUp(const sky::SkyState& state, const sky::Attitude& attitude, const std::vector<sky::ChannelConfig>& channels);

  // The windows' titles, in channel order (none when headless).
  std::vector<std::string> windowTitles() const;
  // Seconds the last frame spent presenting after its draws were submitted: the fence wait and
  // every window's swap, the one vsync'd swap included (0 headless).
  double lastPresentSeconds() const { return lastPresentS_; }
  // How many windows joined swap group 1 (0 without GLX_NV_swap_group).
  std::size_t swapGroupMembers() const { return swapGroupMembers_; }
  // Each channel's GPU time in the last frame, seconds, in channel order: GL timestamp queries
  // before and after its draw (a frame saved to files is not counted), read once the frame's
  // pixels exist, so reading them never waits.
  const std::vector<double>& lastChannelGpuSeconds() const { return channelGpuS_; }

 private:
  void drawChannel(render::SkyRenderer& renderer, const sky::SkyState& state, const sky::Attitude& attitude,
                   const sky::ChannelConfig& channel, std::size_t index);
  // The channel's query pair in the current context (made on first use), and its time once done.
  std::array<unsigned, 2>& queries(std::size_t index);
  void readChannelTime(std::size_t index);

  bool headless_;
  std::unique_ptr<render::GlContext> context_;
  std::vector<std::unique_ptr<render::GlfwWindowContext>> windows_;
  std::vector<std::string> titles_;
  std::vector<std::array<int, 2>> windowSizes_;  // each window's width and height
  std::vector<std::unique_ptr<render::SkyRenderer>> renderers_;
  std::vector<Projector> projectors_;  // one per channel (null: plain)
  std::size_t swapGroupMembers_ = 0;
  double lastPresentS_ = 0.0;
  std::vector<std::array<unsigned, 2>> queries_;  // per channel, in the context it is drawn in
  std::vector<double> channelGpuS_;
};

}  // namespace skyig::services
