#include "node/host/host_snapshot.h"

#include <algorithm>

namespace skyig::services {

std::optional<ephemeris::UtcTime> HostSnapshot::utcAt(Clock::time_point t) const {
  if (cigiClock) return cigiClock->utcAt(t);
  if (!state.timeValid) return std::nullopt;
  ephemeris::UtcTime u = state.utc;
  // Within a day of the last statement; a day rollover is left to the host's next message.
  u.secondsOfDay = std::clamp(u.secondsOfDay + std::chrono::duration<double>(t - state.utcTime).count(), 0.0, 86399.999);
  return u;
}

void HostPublisher::publish(HostSnapshot next) {
  if (history_ == 0) return out_.publish(std::move(next));
  next.earlier.assign(recent_.begin(), recent_.end());
  HostSnapshot bare = next;
  bare.earlier.clear();
  out_.publish(std::move(next));
  recent_.push_back(std::make_shared<const HostSnapshot>(std::move(bare)));
  if (recent_.size() > history_) recent_.pop_front();
}

}  // namespace skyig::services
