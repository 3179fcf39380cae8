#pragma once
// What the receiver hands the worker and render threads: the host state plus what it takes
// to evaluate it at any instant (ownship prediction, the refined sim clock): values only.
#include "node/host/cigi_state.h"
#include "node/common/latest.h"
#include "node/host/host_state.h"
#include "node/host/ownship_predictor.h"

#include "node/host/sender.h"

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace skyig::services {

struct HostSnapshot {
  HostState state;
  OwnshipPredictor predictor;
  std::optional<HostClock> cigiClock;    // the CIGI clock, when the host speaks CIGI
  std::optional<Sender> sender;          // where the last host message came from (UDP)
  Clock::time_point published{};
  // The snapshots published before this one, oldest first, each without its own `earlier`: the
  // worker reads only the latest snapshot, so on a busy machine it may skip host messages; with
  // these it still steps the eye at every host instant (node/frame/sky_worker.h), as a node that
  // skipped none does.
  std::vector<std::shared_ptr<const HostSnapshot>> earlier;

  // UTC at a local instant: CIGI's refined clock, else the last full time plus elapsed time.
  std::optional<ephemeris::UtcTime> utcAt(Clock::time_point t) const;
};

// How a receiver publishes: each snapshot goes out with the last `history` before it. CIGI's
// are host frames (kHistory); a CANaerospace host sends each value in a CAN frame of its own,
// dozens per host frame, so its snapshots go out without history (0): the eye steps at the
// snapshots the worker reads, as many per second as the worker builds.
class HostPublisher {
 public:
  static constexpr std::size_t kHistory = 64;  // two seconds of a 30 Hz host
  explicit HostPublisher(Latest<HostSnapshot>& out, std::size_t history = kHistory) : out_(out), history_(history) {}
  void publish(HostSnapshot next);

 private:
  Latest<HostSnapshot>& out_;
  std::size_t history_;
  std::deque<std::shared_ptr<const HostSnapshot>> recent_;  // bare: `earlier` empty
};

}  // namespace skyig::services
