#include "node/frame/display_outputs.h"

#include "render/gl/swap_group.h"

#include <glad/gl.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

namespace skyig::services {

DisplayOutputs::DisplayOutputs(bool headless, const std::string& nodeName,
                               const std::vector<sky::ChannelConfig>& channels, std::vector<Projector> projectors)
    : headless_(headless), projectors_(std::move(projectors)) {
  projectors_.resize(channels.size());
  if (headless_) {
    context_ = render::createHeadlessContext();
    renderers_.push_back(std::make_unique<render::SkyRenderer>());
    return;
  }
  int x = 0;  // windowed channels side by side, left to right in configuration order
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const auto& c = channels[i];
    render::WindowOptions w;
    w.title = "skyig " + nodeName + " / " + c.name;
    // A projector's window is what the projector is sent: its own resolution.
    w.width = projectors_[i] ? projectors_[i]->width : c.width;
    w.height = projectors_[i] ? projectors_[i]->height : c.height;
    w.vsync = i + 1 == channels.size();  // one swap per frame waits for the vertical blank
    w.shareWith = windows_.empty() ? nullptr : windows_.front().get();
    if (!c.monitor.empty()) {
      w.fullscreenMonitor = c.monitor;
    } else {
      w.position = std::pair{x, 0};
      x += w.width;
    }
    windows_.push_back(std::make_unique<render::GlfwWindowContext>(w));
    windowSizes_.push_back({w.width, w.height});
    titles_.push_back(w.title);
    renderers_.push_back(std::make_unique<render::SkyRenderer>());  // VAOs and FBOs are per context
  }
  const render::SwapGroupSupport swapGroups = render::querySwapGroupSupport();
  if (!swapGroups.available) {
    spdlog::info("{} window(s), only the last waits for the vertical blank; no swap group: {}", windows_.size(),
                 swapGroups.reason);
    return;
  }
  for (const auto& w : windows_) {
    w->makeCurrent();
    if (const std::string error = render::joinSwapGroup(w->handle()); !error.empty())
      spdlog::warn("window \"{}\" swaps on its own: {}", titles_[static_cast<std::size_t>(&w - windows_.data())], error);
    else
      ++swapGroupMembers_;
  }
  spdlog::info("{} of {} window(s) joined swap group 1 / barrier 1", swapGroupMembers_, windows_.size());
}

const render::GlInfo& DisplayOutputs::info() const {
  return headless_ ? context_->info() : windows_.front()->info();
}

bool DisplayOutputs::closeRequested() const {
  for (const auto& w : windows_)
    if (w->closeRequested()) return true;
  return false;
}

std::vector<std::string> DisplayOutputs::windowTitles() const { return titles_; }

std::array<unsigned, 2>& DisplayOutputs::queries(std::size_t index) {
  if (queries_.size() <= index) queries_.resize(index + 1, {0u, 0u});
  if (queries_[index][0] == 0) glGenQueries(2, queries_[index].data());
  return queries_[index];
}

void DisplayOutputs::drawChannel(render::SkyRenderer& renderer, const sky::SkyState& state, const sky::Attitude& attitude,
                                 const sky::ChannelConfig& channel, std::size_t index) {
  const std::array<unsigned, 2>& q = queries(index);
  glQueryCounter(q[0], GL_TIMESTAMP);
  if (index < projectors_.size() && projectors_[index]) renderer.drawProjector(state, attitude, channel, projectors_[index]);
  else renderer.draw(state, attitude, channel);
  glQueryCounter(q[1], GL_TIMESTAMP);
}

void DisplayOutputs::readChannelTime(std::size_t index) {
  if (channelGpuS_.size() <= index) channelGpuS_.resize(index + 1, 0.0);
  GLuint64 begin = 0, end = 0;
  glGetQueryObjectui64v(queries_[index][0], GL_QUERY_RESULT, &begin);
  glGetQueryObjectui64v(queries_[index][1], GL_QUERY_RESULT, &end);
  channelGpuS_[index] = end > begin ? static_cast<double>(end - begin) * 1e-9 : 0.0;
}

void DisplayOutputs::warmUp(const sky::SkyState& state, const sky::Attitude& attitude,
                            const std::vector<sky::ChannelConfig>& channels) {
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (!headless_) windows_.at(i)->makeCurrent();
    drawChannel(headless_ ? *renderers_.front() : *renderers_[i], state, attitude, channels[i], i);
  }
  glFinish();
}

void DisplayOutputs::draw(const sky::SkyState& state, const sky::Attitude& attitude,
                          const std::vector<sky::ChannelConfig>& channels, const DrawnCallback& drawn) {
  if (headless_) {
    for (std::size_t i = 0; i < channels.size(); ++i) {
      drawChannel(*renderers_.front(), state, attitude, channels[i], i);
      if (drawn) drawn(*renderers_.front(), channels[i], i < projectors_.size() ? projectors_[i].get() : nullptr);
    }
    glFinish();  // the frame ends when its pixels exist
    for (std::size_t i = 0; i < channels.size(); ++i) readChannelTime(i);
    return;
  }
  if (channels.size() != windows_.size())
    throw std::logic_error("DisplayOutputs::draw: " + std::to_string(channels.size()) + " channels for " +
                           std::to_string(windows_.size()) + " windows");
  // Every window's frame is drawn and submitted first (a fence each; sync objects are shared
  // between the shared contexts), so that no swap waits for another window's rendering.
  std::vector<GLsync> ready(windows_.size());
  for (std::size_t i = 0; i < windows_.size(); ++i) {
    windows_[i]->makeCurrent();
    drawChannel(*renderers_[i], state, attitude, channels[i], i);
    if (drawn) drawn(*renderers_[i], channels[i], projectors_[i].get());
    // The window's own size: a channel drawn smaller (node/frame/degradation.h) is stretched to it.
    renderers_[i]->presentToDefaultFramebuffer(windowSizes_[i][0], windowSizes_[i][1]);
    ready[i] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();
  }
  const auto submitted = std::chrono::steady_clock::now();
  for (GLsync f : ready) {
    glClientWaitSync(f, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);  // 1 s: a hung GPU does not hang the node
    glDeleteSync(f);
  }
  // Then the swaps, back to back: interval 0 on all but the last, which alone waits for the
  // vertical blank, so the frame costs one refresh whatever the number of windows.
  for (std::size_t i = 0; i < windows_.size(); ++i) {
    windows_[i]->makeCurrent();
    readChannelTime(i);  // done: its fence was passed
    windows_[i]->swapBuffers();
  }
  lastPresentS_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - submitted).count();
  render::pollWindowEvents();
}

}  // namespace skyig::services
