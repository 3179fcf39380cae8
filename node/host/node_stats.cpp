#include "node/host/node_stats.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>
#include <string_view>

namespace skyig::services {

void LatencyRing::add(double us) {
  std::lock_guard lock(mutex_);
  samples_[next_] = us;
  next_ = (next_ + 1) % samples_.size();
  ++count_;
}

double percentileOfSorted(std::span<const double> sorted, double p) {
  if (sorted.empty()) return 0.0;
  const auto rank = static_cast<std::size_t>(p * static_cast<double>(sorted.size()));
  return sorted[std::min(sorted.size() - 1, rank)];
}

void ChannelTimes::setChannels(const std::vector<std::string>& names) {
  std::lock_guard lock(mutex_);
  names_ = names;
  rings_.clear();
  for (std::size_t i = 0; i < names.size(); ++i) rings_.push_back(std::make_unique<LatencyRing>());
}

void ChannelTimes::add(std::size_t channel, double us) {
  std::lock_guard lock(mutex_);
  if (channel < rings_.size()) rings_[channel]->add(us);
}

nlohmann::json ChannelTimes::summary() const {
  std::lock_guard lock(mutex_);
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < names_.size(); ++i) out[names_[i]] = rings_[i]->summary();
  return out;
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
  auto pct = [&](double p) { return percentileOfSorted(v, p); };
  return {{"count", count}, {"p50_us", pct(0.5)}, {"p90_us", pct(0.9)}, {"p99_us", pct(0.99)}, {"max_us", v.back()}};
}

namespace {

// A packet's display name as a JSON key: "Start of Frame" -> "start_of_frame".
std::string snakeCase(std::string_view phrase) {
  std::string key;
  for (char c : phrase) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!key.empty() && key.back() != '_')
      key += '_';
  }
  while (!key.empty() && key.back() == '_') key.pop_back();
  return key;
}

// Keys of the CIGI error kinds and CANaerospace feed statuses, in enum order (their display
// phrases are sentences, too long for keys).
constexpr const char* kErrorKeys[] = {"empty_message",      "truncated_header",  "missing_first_packet",
                                      "unsupported_version", "bad_byte_swap_magic", "packet_size_too_small",
                                      "packet_past_end",     "wrong_packet_size"};
static_assert(std::size(kErrorKeys) == protocol::cigi::kErrorKindCount);
constexpr const char* kCanKeys[] = {"applied",   "pending_double_half", "identifier_not_mapped", "malformed_frame",
                                    "wrong_data_type", "bad_value", "unpaired_double_half"};
static_assert(std::size(kCanKeys) == protocol::canaerospace::kFeedStatusCount);

}  // namespace

nlohmann::json NodeStats::toJson() const {
  nlohmann::json packetsByType = nlohmann::json::object();
  for (std::size_t i = 0; i < packets.size(); ++i) packetsByType[snakeCase(protocol::cigi::packetName(i))] = packets[i].load();
  nlohmann::json errorsByKind = nlohmann::json::object();
  for (std::size_t i = 0; i < errors.size(); ++i) errorsByKind[kErrorKeys[i]] = errors[i].load();
  nlohmann::json can = nlohmann::json::object();
  for (std::size_t i = 0; i < canStatus.size(); ++i) can[kCanKeys[i]] = canStatus[i].load();
  nlohmann::json sessionsByReason = nlohmann::json::object();
  for (std::size_t i = 0; i < sessions.size(); ++i)
    sessionsByReason[toString(static_cast<SessionReason>(i))] = sessions[i].load();
  return {
      {"datagrams", datagrams.load()},
      {"bytes", bytes.load()},
      {"malformed_datagrams", malformedDatagrams.load()},
      {"skipped_packets", skippedPackets.load()},
      {"rejected_values", rejectedValues.load()},
      {"stale_messages", staleMessages.load()},
      {"sessions", sessionsByReason},
      {"not_allowed_datagrams", notAllowedDatagrams.load()},
      {"other_host_datagrams", otherHostDatagrams.load()},
      {"not_host_messages", notHostMessages.load()},
      {"timestamp_jumps", timestampJumps.load()},
      {"dropped_views", droppedViews.load()},
      {"recorded_datagrams", recorded.load()},
      {"record_errors", recordErrors.load()},
      {"packets", packetsByType},
      {"errors", errorsByKind},
      {"can_frames", canFrames.load()},
      {"can", can},
      {"frames", frames.load()},
      {"sky_states", skyStates.load()},
      {"sync_timeouts", syncTimeouts.load()},
      {"start_of_frame_sent", startOfFrameSent.load()},
      // Latencies: count and percentiles in microseconds (p50_us, p90_us, p99_us, max_us).
      {"latency", {{"arrival_to_visible", arrivalToVisible.summary()},
                   {"arrival_to_frame_end", arrivalToFrameEnd.summary()},
                   {"frame_render", frameTime.summary()}}},
      // The frame's timing: target period (1 / the frame rate) and the frames over it; the
      // start-to-start interval (its p50 gives the rate); each channel's GPU time (timestamp
      // queries around its draw); the age of the host state a frame shows at its end.
      {"timing", {{"target_period_us", targetPeriodUs.load()},
                  {"frames_over_period", framesOverPeriod.load()},
                  {"frame_interval", frameInterval.summary()},
                  {"channel_gpu", channelGpuTime.summary()},
                  {"shown_host_age", shownHostAge.summary()},
                  {"resolution_scale", resolutionScale.load()},
                  {"resolution_drops", resolutionDrops.load()},
                  {"resolution_restores", resolutionRestores.load()}}},
  };
}

}  // namespace skyig::services
