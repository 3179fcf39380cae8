#pragma once
// The host's time of day to the millisecond. CIGI's Celestial Sphere Control carries only the
// hour and minute; taken alone the sun would jump once a minute. SimClock runs a continuous
// clock from the IG Control timestamp (10 us ticks; the arrival time when the host sends none)
// plus an offset, and moves the offset only as far as needed to keep the clock inside the
// minute the host last stated. The first minute rollover the host reports pins the offset to
// within one host frame; from then on the clock is smooth and exact.
#include "ephemeris/time.h"

#include <optional>

namespace skyig::services {

class SimClock {
 public:
  // Host's stated date and time of day, the continuous time (s) it was stated at, and how
  // finely the host states it: CIGI 3.3 gives the minute (60 s: the clock may run anywhere
  // inside it), CIGI 4.0 adds a float seconds field (a small window: the clock is pinned to
  // the stated instant and only corrected when it drifts out of the window).
  void observe(const ephemeris::UtcTime& stated, double continuousS, double resolutionS = 60.0);
  // UTC at a continuous time; nullopt before the first observation.
  std::optional<ephemeris::UtcTime> at(double continuousS) const;
  void setSpeed(double simSecondsPerSecond) { speed_ = simSecondsPerSecond; }
  bool valid() const { return valid_; }  // the host has stated a time

 private:
  bool valid_ = false;
  double dayStartJd_ = 0.0;     // Julian date (UTC) of 0h of the stated date
  double offsetS_ = 0.0;        // seconds of day = (continuous - anchor) * speed + offset
  double anchorS_ = 0.0;
  double speed_ = 1.0;
};

}  // namespace skyig::services
