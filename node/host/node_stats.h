#pragma once
// Counters of a running node (datagrams, packets by type, errors by kind, frames) and latency
// samples, written as JSON by `skyig serve --stats-json`. Counters are atomics bumped by the
// thread that owns the event; latencies go to small per-kind rings read at report time.
#include "protocol/canaerospace/state_decoder.h"
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/packets.h"
#include "node/host/host_session.h"

#include <nlohmann/json.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace skyig::services {

// p in [0, 1] of `sorted` (ascending; nearest rank: the sample at floor(p n)); 0 for none.
double percentileOfSorted(std::span<const double> sorted, double p);

// Keeps the last N samples (microseconds) and reports percentiles.
class LatencyRing {
 public:
  explicit LatencyRing(std::size_t capacity = 8192) : samples_(capacity) {}
  void add(double us);
  nlohmann::json summary() const;  // count, p50, p90, p99, max (microseconds)

 private:
  mutable std::mutex mutex_;  // held for a store or a copy only, never while computing
  std::vector<double> samples_;
  std::size_t next_ = 0;
  std::uint64_t count_ = 0;
};

// One LatencyRing per channel, named when the node knows its channels (the render thread adds,
// the worker's statistics file reads).
class ChannelTimes {
 public:
  void setChannels(const std::vector<std::string>& names);
  void add(std::size_t channel, double us);
  nlohmann::json summary() const;  // {name: LatencyRing::summary()}

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> names_;
  std::vector<std::unique_ptr<LatencyRing>> rings_;
};

struct NodeStats {
  std::atomic<std::uint64_t> datagrams{0};
  std::atomic<std::uint64_t> bytes{0};
  std::atomic<std::uint64_t> malformedDatagrams{0};
  std::atomic<std::uint64_t> skippedPackets{0};
  std::atomic<std::uint64_t> rejectedValues{0};
  std::atomic<std::uint64_t> staleMessages{0};  // reordered: older than a host frame applied
  // Host sessions (node/host/host_session.h): sessions started, by reason; datagrams from
  // senders outside host.allowed, from another address while the host is alive, and messages
  // that are no host's (an IG's Start of Frame); all dropped.
  std::array<std::atomic<std::uint64_t>, kSessionReasonCount> sessions{};
  std::atomic<std::uint64_t> notAllowedDatagrams{0};
  std::atomic<std::uint64_t> otherHostDatagrams{0};
  std::atomic<std::uint64_t> notHostMessages{0};
  std::atomic<std::uint64_t> timestampJumps{0};  // IG Control timestamps that did not continue the host's clock
  std::atomic<std::uint64_t> droppedViews{0};   // View Control/Definition for ids >= host.max_views
  std::atomic<std::uint64_t> recorded{0};       // datagrams written by serve --record
  std::atomic<std::uint64_t> recordErrors{0};
  std::array<std::atomic<std::uint64_t>, protocol::cigi::kPacketTypeCount> packets{};
  std::array<std::atomic<std::uint64_t>, protocol::cigi::kErrorKindCount> errors{};
  std::atomic<std::uint64_t> canFrames{0};
  std::array<std::atomic<std::uint64_t>, protocol::canaerospace::kFeedStatusCount> canStatus{};
  std::atomic<std::uint64_t> frames{0};
  std::atomic<std::uint64_t> syncTimeouts{0};
  std::atomic<std::uint64_t> startOfFrameSent{0};
  std::atomic<std::uint64_t> skyStates{0};
  LatencyRing arrivalToVisible;   // datagram arrival -> state published to the render thread
  LatencyRing arrivalToFrameEnd;  // datagram arrival -> end of the first frame that shows it
  LatencyRing frameTime;          // render of all channels, per frame
  // The frame's timing (node/frame/frame_timing.h): the period it is held to, the frames that
  // took longer, start-to-start intervals, each channel's GPU time, and the age of the host
  // state each frame shows at its end.
  std::atomic<double> targetPeriodUs{0.0};
  std::atomic<std::uint64_t> framesOverPeriod{0};
  LatencyRing frameInterval;
  LatencyRing shownHostAge;
  // The degradation policy (node/frame/degradation.h): the scale the channels are drawn at now
  // (1: full resolution) and the level changes down and up so far.
  std::atomic<double> resolutionScale{1.0};
  std::atomic<std::uint64_t> resolutionDrops{0};
  std::atomic<std::uint64_t> resolutionRestores{0};
  ChannelTimes channelGpuTime;

  nlohmann::json toJson() const;
};

}  // namespace skyig::services
