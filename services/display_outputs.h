#pragma once
// What `serve` renders into: one headless context for every channel, or one window per
// channel (fullscreen on its configured monitor). No sockets, no host state: it draws a
// SkyState seen with an attitude through the node's channels.
#include "render/gl/gl_context.h"
#include "render/gl/glfw_window.h"
#include "render/sky_renderer.h"
#include "sky/camera.h"
#include "sky/channel.h"
#include "sky/sky_state.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace skyig::services {

class DisplayOutputs {
 public:
  // `nodeName` titles the windows ("skyig <node> / <channel>").
  DisplayOutputs(bool headless, const std::string& nodeName, const std::vector<sky::ChannelConfig>& channels);

  const render::GlInfo& info() const;
  bool closeRequested() const;

  using DrawnCallback = std::function<void(const render::SkyRenderer&, const sky::ChannelConfig&)>;
  // Draws every channel; `drawn` sees each channel's renderer right after its frame (to save it).
  void draw(const sky::SkyState& state, const sky::Attitude& attitude, const std::vector<sky::ChannelConfig>& channels,
            const DrawnCallback& drawn = {});

 private:
  bool headless_;
  std::unique_ptr<render::GlContext> context_;
  std::vector<std::unique_ptr<render::GlfwWindowContext>> windows_;
  std::vector<std::unique_ptr<render::SkyRenderer>> renderers_;
};

}  // namespace skyig::services
