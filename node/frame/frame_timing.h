#pragma once
// What the operator reads of a node's timing (`skyig serve`): every few seconds an info line of the
// frame rate, the frame time's p50/p99/max, the frames over the target period, each channel's GPU
// time and the age of the host frame shown, over the seconds since the last line; at exit one line
// for the whole run. The same figures go to --stats-json (NodeStats, "timing").
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace skyig::services {

class FrameTimingWindow {
 public:
  // `channels` name the node's channels in draw order; a frame longer than targetPeriodS is over.
  FrameTimingWindow(std::vector<std::string> channels, double targetPeriodS);

  // One frame: its time (start to end), the time since the previous frame's start (none for the
  // first), each channel's GPU time (seconds; empty if not measured) and the age of the host state
  // it shows at its end (none without a host).
  void add(double frameS, std::optional<double> intervalS, std::span<const double> channelS,
           std::optional<double> hostAgeS);
  std::size_t frames() const { return frameS_.size(); }
  std::size_t overPeriod() const { return over_; }
  // "frames: 59.9 fps, frame p50 4.1 ms p99 6.0 ms max 9.2 ms, 0 of 300 over 16.7 ms; GPU
  // front 3.1 ms ...; host frame shown at most 35 ms old"; then starts a new window.
  std::string takeLogLine();

 private:
  std::vector<std::string> channels_;
  double periodS_;
  std::vector<double> frameS_, intervalS_, hostAgeS_;
  std::vector<std::vector<double>> channelS_;
  std::size_t over_ = 0;
};

}  // namespace skyig::services
