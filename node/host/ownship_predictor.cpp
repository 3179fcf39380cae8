#include "node/host/ownship_predictor.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skyig::services {

namespace {

using skyig::kDeg;
constexpr double kA = 6378137.0;              // WGS84 semi-major axis, m
constexpr double kE2 = 6.69437999014e-3;      // WGS84 first eccentricity squared

// The WGS84 meridian and prime-vertical radii of curvature (m) at a latitude and height.
void radii(double latitudeDeg, double heightM, double& meridian, double& primeVertical) {
  const double s = std::sin(latitudeDeg * kDeg);
  const double w = std::sqrt(1.0 - kE2 * s * s);
  meridian = kA * (1.0 - kE2) / (w * w * w) + heightM;
  primeVertical = kA / w + heightM;
}

// Advances a geodetic position by a north-east-down displacement (m), with the radii of
// curvature at the start point (exact to first order, i.e. well under a millimetre for a
// frame's motion).
void moveNed(sky::Ownship& o, double north, double east, double down) {
  double meridian = 0.0, primeVertical = 0.0;
  radii(o.latitudeDeg, o.heightM, meridian, primeVertical);
  o.latitudeDeg += north / meridian / kDeg;
  o.longitudeDeg += east / (primeVertical * std::max(std::cos(o.latitudeDeg * kDeg), 1e-6)) / kDeg;
  o.heightM -= down;
}

// Back into the ranges of a pose. Past a pole the path goes on down the far meridian, heading
// the other way; past vertical the nose comes over the top (pitch 95 is pitch 85 facing back,
// upside down).
void normalise(sky::Ownship& o) {
  if (o.latitudeDeg > 90.0 || o.latitudeDeg < -90.0) {
    o.latitudeDeg = std::copysign(180.0, o.latitudeDeg) - o.latitudeDeg;
    o.longitudeDeg += 180.0;
    o.attitude.yawDeg += 180.0;
  }
  o.latitudeDeg = std::clamp(o.latitudeDeg, -90.0, 90.0);  // a step of more than 180 degrees cannot happen
  o.attitude.pitchDeg = wrap180(o.attitude.pitchDeg);
  if (o.attitude.pitchDeg > 90.0 || o.attitude.pitchDeg < -90.0) {
    o.attitude.pitchDeg = std::copysign(180.0, o.attitude.pitchDeg) - o.attitude.pitchDeg;
    o.attitude.yawDeg += 180.0;
    o.attitude.rollDeg += 180.0;
  }
  o.longitudeDeg = wrap180(o.longitudeDeg);
  o.attitude.yawDeg = std::fmod(o.attitude.yawDeg, 360.0);
  if (o.attitude.yawDeg < 0.0) o.attitude.yawDeg += 360.0;
  if (o.attitude.yawDeg >= 360.0) o.attitude.yawDeg = 0.0;  // fmod(-1e-17) + 360
  o.attitude.rollDeg = wrap180(o.attitude.rollDeg);
}

double bounded(double v, double limit) { return std::clamp(v, -limit, limit); }

}  // namespace

double wrap180(double deg) {
  deg = std::fmod(deg, 360.0);
  if (deg > 180.0) deg -= 360.0;
  if (deg <= -180.0) deg += 360.0;
  return deg;
}

void OwnshipPredictor::addSample(const sky::Ownship& ownship, Clock::time_point arrival, const OwnshipRates& rates,
                                 std::optional<HostTime> hostTime) {
  const Sample& last = samples_[static_cast<std::size_t>(newest_)];
  if (count_ > 0 && (arrival < last.arrival || (arrival == last.arrival && !hostTime))) return;
  if (count_ > 0 && hostTime && last.hostTime && hostTime->seconds <= last.hostTime->seconds) return;
  newest_ = (newest_ + 1) % kHistory;
  samples_[static_cast<std::size_t>(newest_)] = {ownship, arrival, hostTime};
  count_ = std::min(count_ + 1, kHistory);
  moving_ = false;
  if (rates.valid) {
    // Rate Control: the host's own velocities, body axes turned into north-east-down by the
    // attitude when it sends them so.
    const sky::Attitude& a = ownship.attitude;
    double n = rates.x, e = rates.y, d = rates.z;
    if (rates.bodyAxes) {
      const double cy = std::cos(a.yawDeg * kDeg), sy = std::sin(a.yawDeg * kDeg);
      const double cp = std::cos(a.pitchDeg * kDeg), sp = std::sin(a.pitchDeg * kDeg);
      const double cr = std::cos(a.rollDeg * kDeg), sr = std::sin(a.rollDeg * kDeg);
      n = cy * cp * rates.x + (cy * sp * sr - sy * cr) * rates.y + (cy * sp * cr + sy * sr) * rates.z;
      e = sy * cp * rates.x + (sy * sp * sr + cy * cr) * rates.y + (sy * sp * cr - cy * sr) * rates.z;
      d = -sp * rates.x + cp * sr * rates.y + cp * cr * rates.z;
    }
    motion_ = {n, e, d, rates.yawRate, rates.pitchRate, rates.rollRate};
    moving_ = true;
  } else {
    estimate();
  }
  if (!moving_) return;
  const double ground = std::hypot(motion_.north, motion_.east);
  if (ground > kMaxGroundSpeedMps) {
    motion_.north *= kMaxGroundSpeedMps / ground;
    motion_.east *= kMaxGroundSpeedMps / ground;
  }
  motion_.down = bounded(motion_.down, kMaxVerticalSpeedMps);
  motion_.yaw = bounded(motion_.yaw, kMaxYawRateDegps);
  motion_.pitch = bounded(motion_.pitch, kMaxPitchRateDegps);
  motion_.roll = bounded(motion_.roll, kMaxRollRateDegps);
}

// The velocity between the newest sample and the newest earlier one far enough back in time:
// on the host's clock when both carry it, else on the arrival clock.
void OwnshipPredictor::estimate() {
  const Sample& b = samples_[static_cast<std::size_t>(newest_)];
  for (int back = 1; back < count_; ++back) {
    const Sample& a = samples_[static_cast<std::size_t>((newest_ - back + kHistory) % kHistory)];
    // On the host's clock, in local seconds (the newest rate: one rate for both ends).
    const bool hostClock = a.hostTime && b.hostTime;
    const double span = hostClock ? (b.hostTime->seconds - a.hostTime->seconds) / b.hostTime->rate
                                  : std::chrono::duration<double>(b.arrival - a.arrival).count();
    if (span > kMaxSpanS) return;  // further back is older still
    if (span < (hostClock ? kMinHostSpanS : kMinArrivalSpanS)) continue;
    double meridian = 0.0, primeVertical = 0.0;
    radii(a.ownship.latitudeDeg, a.ownship.heightM, meridian, primeVertical);
    const sky::Ownship& p = a.ownship;
    const sky::Ownship& q = b.ownship;
    motion_.north = (q.latitudeDeg - p.latitudeDeg) * kDeg * meridian / span;
    motion_.east =
        wrap180(q.longitudeDeg - p.longitudeDeg) * kDeg * primeVertical * std::cos(p.latitudeDeg * kDeg) / span;
    motion_.down = -(q.heightM - p.heightM) / span;
    motion_.yaw = wrap180(q.attitude.yawDeg - p.attitude.yawDeg) / span;
    motion_.pitch = (q.attitude.pitchDeg - p.attitude.pitchDeg) / span;
    motion_.roll = wrap180(q.attitude.rollDeg - p.attitude.rollDeg) / span;
    moving_ = true;
    return;
  }
}

sky::Ownship OwnshipPredictor::at(Clock::time_point t) const {
  if (count_ == 0) return {};
  const Sample& last = samples_[static_cast<std::size_t>(newest_)];
  sky::Ownship o = last.ownship;
  const double dt = std::clamp(std::chrono::duration<double>(t - last.arrival).count(), 0.0, maxAheadS_);
  if (moving_ && dt > 0.0) {
    moveNed(o, motion_.north * dt, motion_.east * dt, motion_.down * dt);
    o.attitude.yawDeg += motion_.yaw * dt;
    o.attitude.pitchDeg += motion_.pitch * dt;
    o.attitude.rollDeg += motion_.roll * dt;
  }
  normalise(o);
  return o;
}

}  // namespace skyig::services
