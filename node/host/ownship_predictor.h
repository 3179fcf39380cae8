#pragma once
// Between host updates the render thread shows the ownship where it is at the frame's time,
// not where it was at the last message: a 30 Hz host on a 60 Hz IG must not judder. With the
// host's Rate Control the last sample is advanced by those rates (dead reckoning, as CIGI
// intends); without, by the velocity between two samples, timed by the host's own clock (IG
// Control timestamps, at the rate that clock runs: a time-lapse host stamps its sim clock) when
// it sends one, else by their arrival times, never closer together than kMinArrivalSpanS (two
// datagrams that arrive back to back say nothing about speed).
// Velocities are bounded by what an aircraft can do (kMax*), prediction is capped at maxAhead
// so a silent host freezes the view instead of flying it away, and every prediction is a valid
// pose: latitude in [-90, 90] (over a pole the path continues on the far meridian), longitude
// in (-180, 180], yaw in [0, 360), pitch in [-90, 90], roll in (-180, 180].
#include "node/host/host_state.h"

#include <array>
#include <optional>

namespace skyig::services {

// Bounds on the ownship's motion, beyond any crewed aircraft a simulator flies (documented in
// docs/protocol.md, "Ownship prediction"): a larger estimate is noise and is saturated.
inline constexpr double kMaxGroundSpeedMps = 1000.0;   // SR-71: about 980 m/s
inline constexpr double kMaxVerticalSpeedMps = 300.0;  // zoom climbs and dives of fighters: < 250 m/s
inline constexpr double kMaxYawRateDegps = 360.0;      // helicopter pedal turns ~100 deg/s, spins ~300 deg/s
inline constexpr double kMaxPitchRateDegps = 360.0;    // aerobatic pitch, tumbling manoeuvres
inline constexpr double kMaxRollRateDegps = 720.0;     // aerobatic aircraft roll at ~400 deg/s
// Arrival times closer than this are not used for a velocity (a host sends at most ~120 Hz).
inline constexpr double kMinArrivalSpanS = 0.02;
// Host timestamps are exact, but a span shorter than this amplifies the float resolution of
// the attitude (CIGI sends float degrees) into rates of degrees per second.
inline constexpr double kMinHostSpanS = 0.002;
// Samples further apart than this say nothing about the present motion.
inline constexpr double kMaxSpanS = 1.0;

class OwnshipPredictor {
 public:
  explicit OwnshipPredictor(double maxAheadS = 0.25) : maxAheadS_(maxAheadS) {}

  // A new host sample received at `arrival`, stamped `hostTime` by the host's clock when its
  // message carried a timestamp (ignored when it is not newer than the last sample).
  void addSample(const sky::Ownship& ownship, Clock::time_point arrival, const OwnshipRates& rates,
                 std::optional<HostTime> hostTime = std::nullopt);
  bool valid() const { return count_ > 0; }
  sky::Ownship at(Clock::time_point t) const;

 private:
  struct Sample {
    sky::Ownship ownship;
    Clock::time_point arrival{};
    std::optional<HostTime> hostTime;
  };
  // North, east, down (m/s) and yaw, pitch, roll rates (deg/s), bounded.
  struct Motion {
    double north = 0.0, east = 0.0, down = 0.0, yaw = 0.0, pitch = 0.0, roll = 0.0;
  };
  void estimate();

  double maxAheadS_;
  static constexpr int kHistory = 4;
  std::array<Sample, kHistory> samples_{};  // ring, newest at samples_[newest_]
  int newest_ = 0;
  int count_ = 0;
  bool moving_ = false;  // motion_ holds a velocity (from the rates or two samples)
  Motion motion_;
};

// Wraps an angle in degrees to (-180, 180].
double wrap180(double deg);

}  // namespace skyig::services
