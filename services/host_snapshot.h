#pragma once
// What the receiver hands the worker and render threads: the host state plus what it takes
// to evaluate it at any instant (ownship prediction, the refined sim clock): values only.
#include "services/cigi_state.h"
#include "services/host_state.h"
#include "services/ownship_predictor.h"

#include <netinet/in.h>

#include <optional>

namespace skyig::services {

struct HostSnapshot {
  HostState state;
  OwnshipPredictor predictor;
  std::optional<HostClock> cigiClock;    // the CIGI clock, when the host speaks CIGI
  std::optional<sockaddr_in> sender;     // where the last host message came from (UDP)
  Clock::time_point published{};

  // UTC at a local instant: CIGI's refined clock, else the last full time plus elapsed time.
  std::optional<ephemeris::UtcTime> utcAt(Clock::time_point t) const;
};

}  // namespace skyig::services
