#include "services/node_stats.h"

#include <algorithm>

namespace skyig::services {

void LatencyRing::add(double us) {
  std::lock_guard lock(mutex_);
  samples_[next_] = us;
  next_ = (next_ + 1) % samples_.size();
  ++count_;
}

nlohmann::json LatencyRing::summary() const {
  std::vector<double> v;
  std::uint64_t count = 0;
  {
    std::lock_guard lock(mutex_);
    count = count_;
    v.assign(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(std::min<std::uint64_t>(count_, samples_.size())));
  }
  if (v.empty()) return {{"count", 0}};
  std::sort(v.begin(), v.end());
  auto pct = [&](double p) { return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))]; };
  return {{"count", count}, {"p50_us", pct(0.5)}, {"p90_us", pct(0.9)}, {"p99_us", pct(0.99)}, {"max_us", v.back()}};
}

nlohmann::json NodeStats::toJson() const {
  nlohmann::json packetsByType = nlohmann::json::object();
  for (std::size_t i = 0; i < packets.size(); ++i)
    packetsByType[protocol::cigi::packetName(i)] = packets[i].load();
  nlohmann::json errorsByKind = nlohmann::json::object();
  for (std::size_t i = 0; i < errors.size(); ++i)
    errorsByKind[protocol::cigi::toString(static_cast<protocol::cigi::ErrorKind>(i))] = errors[i].load();
  nlohmann::json can = nlohmann::json::object();
  for (std::size_t i = 0; i < canStatus.size(); ++i)
    can[protocol::canaerospace::toString(static_cast<protocol::canaerospace::FeedStatus>(i))] = canStatus[i].load();
  return {
      {"datagrams", datagrams.load()},
      {"bytes", bytes.load()},
      {"malformed_datagrams", malformedDatagrams.load()},
      {"skipped_packets", skippedPackets.load()},
      {"rejected_values", rejectedValues.load()},
      {"stale_messages", staleMessages.load()},
      {"dropped_views", droppedViews.load()},
      {"recorded", recorded.load()},
      {"record_errors", recordErrors.load()},
      {"packets", packetsByType},
      {"errors", errorsByKind},
      {"can_frames", canFrames.load()},
      {"can", can},
      {"frames", frames.load()},
      {"sky_states", skyStates.load()},
      {"sync_timeouts", syncTimeouts.load()},
      {"start_of_frame_sent", startOfFrameSent.load()},
      {"latency", {{"arrival_to_visible", arrivalToVisible.summary()},
                   {"arrival_to_frame_end", arrivalToFrameEnd.summary()},
                   {"frame_render", frameTime.summary()}}},
  };
}

}  // namespace skyig::services
