#pragma once
// Applies decoded CIGI host messages to the HostState (pure: no sockets, no threads).
#include "protocol/cigi/decoder.h"
#include "services/host_state.h"
#include "services/sim_clock.h"

#include <algorithm>

namespace skyig::services {

// The host's clock as the receiver last knew it: the minutes the host stated (SimClock) and the
// map from a local instant to the host's continuous time (its IG Control timestamps, or the
// arrival times when it sends none). A small value, so every snapshot carries its own copy and
// the worker and render threads evaluate the host's time at any instant without the tracker.
struct HostClock {
  SimClock clock;
  bool haveTimestamp = false;
  double timestampBaseS = 0.0;              // unwrapped timestamp seconds at timestampArrival
  Clock::time_point timestampArrival{};

  // The host's continuous time at a local instant, seconds.
  double continuousAt(Clock::time_point t) const;
  // UTC at a local instant, refined below the minute; nullopt before the host gave a time.
  std::optional<ephemeris::UtcTime> utcAt(Clock::time_point t) const { return clock.at(continuousAt(t)); }
};

class CigiStateTracker {
 public:
  // Applies every well-formed packet of a message received at `arrival`. Invalid values
  // (NaN, out-of-range angles, impossible dates) are skipped and counted; the rest of the
  // state is kept. Returns the number of rejected values.
  int apply(const protocol::cigi::DecodedMessage& message, Clock::time_point arrival);
  // Messages dropped because their host frame number was older than one already applied
  // (reordered datagrams must not move the ownship back in time).
  std::uint64_t staleMessages() const { return stale_; }
  // View Control and View Definition packets for a view id at or above the maximum
  // (host.max_views, at most kViewTableCapacity): counted and dropped.
  void setMaxViews(std::size_t n) { maxViews_ = std::min(n, kViewTableCapacity); }
  std::uint64_t droppedViews() const { return droppedViews_; }

  const HostState& state() const { return state_; }
  const HostClock& clock() const { return clock_; }

 private:
  HostState state_;
  HostClock clock_;
  std::uint64_t stale_ = 0;
  std::size_t maxViews_ = kDefaultMaxViews;
  std::uint64_t droppedViews_ = 0;
  bool haveHostFrame_ = false;
  std::uint32_t lastTimestamp_ = 0;   // IG Control timestamp, 10 us ticks
};

}  // namespace skyig::services
