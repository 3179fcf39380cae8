#include "node/frame/frame_timing.h"

#include "node/host/node_stats.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace skyig::services {

FrameTimingWindow::FrameTimingWindow(std::vector<std::string> channels, double targetPeriodS)
    : channels_(std::move(channels)), periodS_(targetPeriodS), channelS_(channels_.size()) {}

void FrameTimingWindow::add(double frameS, std::optional<double> intervalS, std::span<const double> channelS,
                            std::optional<double> hostAgeS) {
  frameS_.push_back(frameS);
  if (frameS > periodS_) ++over_;
  if (intervalS) intervalS_.push_back(*intervalS);
  for (std::size_t i = 0; i < std::min(channelS.size(), channelS_.size()); ++i) channelS_[i].push_back(channelS[i]);
  if (hostAgeS) hostAgeS_.push_back(*hostAgeS);
}

std::string FrameTimingWindow::takeLogLine() {
  auto ms = [](double s) { return 1000.0 * s; };
  std::sort(frameS_.begin(), frameS_.end());
  // The rate from the starts' spacing: frames over the time they spanned.
  const double spanS = std::accumulate(intervalS_.begin(), intervalS_.end(), 0.0);
  const double fps = spanS > 0.0 ? static_cast<double>(intervalS_.size()) / spanS : 0.0;
  std::string line = fmt::format("frames: {:.1f} fps, frame p50 {:.1f} ms p99 {:.1f} ms max {:.1f} ms, {} of {} over {:.1f} ms",
                                 fps, ms(percentileOfSorted(frameS_, 0.5)), ms(percentileOfSorted(frameS_, 0.99)),
                                 ms(frameS_.empty() ? 0.0 : frameS_.back()), over_, frameS_.size(), ms(periodS_));
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (channelS_[i].empty()) continue;
    std::sort(channelS_[i].begin(), channelS_[i].end());
    line += fmt::format("{} {} GPU p50 {:.1f} ms p99 {:.1f} ms", i == 0 ? ";" : ",", channels_[i],
                        ms(percentileOfSorted(channelS_[i], 0.5)), ms(percentileOfSorted(channelS_[i], 0.99)));
  }
  if (!hostAgeS_.empty())
    line += fmt::format("; host frame shown at most {:.0f} ms old", ms(*std::max_element(hostAgeS_.begin(), hostAgeS_.end())));
  frameS_.clear();
  intervalS_.clear();
  hostAgeS_.clear();
  for (auto& c : channelS_) c.clear();
  over_ = 0;
  return line;
}

}  // namespace skyig::services
