#include "services/display_outputs.h"

#include <glad/gl.h>

namespace skyig::services {

DisplayOutputs::DisplayOutputs(bool headless, const std::string& nodeName,
                               const std::vector<sky::ChannelConfig>& channels)
    : headless_(headless) {
  if (headless_) {
    context_ = render::createHeadlessContext();
    renderers_.push_back(std::make_unique<render::SkyRenderer>());
    return;
  }
  for (const auto& c : channels) {
    render::WindowOptions w;
    w.title = "skyig " + nodeName + " / " + c.name;
    w.width = c.width;
    w.height = c.height;
    w.shareWith = windows_.empty() ? nullptr : windows_.front().get();
    if (!c.monitor.empty()) w.fullscreenMonitor = c.monitor;
    windows_.push_back(std::make_unique<render::GlfwWindowContext>(w));
    renderers_.push_back(std::make_unique<render::SkyRenderer>());  // VAOs and FBOs are per context
  }
}

const render::GlInfo& DisplayOutputs::info() const {
  return headless_ ? context_->info() : windows_.front()->info();
}

bool DisplayOutputs::closeRequested() const {
  for (const auto& w : windows_)
    if (w->closeRequested()) return true;
  return false;
}

void DisplayOutputs::draw(const sky::SkyState& state, const sky::Attitude& attitude,
                          const std::vector<sky::ChannelConfig>& channels, const DrawnCallback& drawn) {
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (headless_) {
      renderers_.front()->draw(state, attitude, channels[i]);
      if (drawn) drawn(*renderers_.front(), channels[i]);
      continue;
    }
    windows_[i]->makeCurrent();
    renderers_[i]->draw(state, attitude, channels[i]);
    if (drawn) drawn(*renderers_[i], channels[i]);
    renderers_[i]->presentToDefaultFramebuffer(channels[i].width, channels[i].height);
    windows_[i]->swapBuffers();
  }
  if (headless_) glFinish();  // the frame ends when its pixels exist
  else render::pollWindowEvents();
}

}  // namespace skyig::services
