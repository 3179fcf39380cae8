#pragma once
// Between host updates the render thread shows the ownship where it is at the frame's time,
// not where it was at the last message: a 30 Hz host on a 60 Hz IG must not judder. With the
// host's Rate Control the last sample is advanced by those rates (dead reckoning, as CIGI
// intends); without, by the velocity between the last two samples. Prediction is capped at
// maxAhead so a silent host freezes the view instead of flying it away.
#include "services/host_state.h"

namespace skyig::services {

class OwnshipPredictor {
 public:
  explicit OwnshipPredictor(double maxAheadS = 0.25) : maxAheadS_(maxAheadS) {}

  // A new host sample (ignored when it is not newer than the last one).
  void addSample(const sky::Ownship& ownship, Clock::time_point time, const OwnshipRates& rates);
  bool valid() const { return count_ > 0; }
  sky::Ownship at(Clock::time_point t) const;

 private:
  double maxAheadS_;
  int count_ = 0;
  sky::Ownship last_, previous_;
  Clock::time_point lastTime_{}, previousTime_{};
  OwnshipRates rates_;
};

// Wraps an angle in degrees to (-180, 180].
double wrap180(double deg);

}  // namespace skyig::services
