#pragma once
// Applies decoded CIGI host messages to the HostState (pure: no sockets, no threads).
#include "protocol/cigi/decoder.h"
#include "services/host_state.h"
#include "services/sim_clock.h"

namespace skyig::services {

class CigiStateTracker {
 public:
  // Applies every well-formed packet of a message received at `arrival`. Invalid values
  // (NaN, out-of-range angles, impossible dates) are skipped and counted; the rest of the
  // state is kept. Returns the number of rejected values.
  int apply(const protocol::cigi::DecodedMessage& message, Clock::time_point arrival);
  // Messages dropped because their host frame number was older than one already applied
  // (reordered datagrams must not move the ownship back in time).
  std::uint64_t staleMessages() const { return stale_; }

  const HostState& state() const { return state_; }
  // The host's UTC at a local instant, refined below the minute (SimClock).
  std::optional<ephemeris::UtcTime> utcAt(Clock::time_point t) const;

 private:
  double continuousTime(Clock::time_point arrival) const;

  HostState state_;
  SimClock clock_;
  std::uint64_t stale_ = 0;
  bool haveHostFrame_ = false;
  bool haveTimestamp_ = false;
  std::uint32_t lastTimestamp_ = 0;   // IG Control timestamp, 10 us ticks
  Clock::time_point lastTimestampArrival_{};
  double timestampBaseS_ = 0.0;       // unwrapped timestamp seconds of lastTimestamp_
};

}  // namespace skyig::services
