#include "services/ownship_predictor.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skyig::services {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kA = 6378137.0;              // WGS84 semi-major axis, m
constexpr double kE2 = 6.69437999014e-3;      // WGS84 first eccentricity squared

// Advances a geodetic position by a north-east-down displacement (m), with the WGS84
// meridian and prime-vertical radii of curvature at the start point (exact to first order,
// i.e. well under a millimetre for a frame's motion).
void moveNed(sky::Ownship& o, double north, double east, double down) {
  const double s = std::sin(o.latitudeDeg * kDeg);
  const double w = std::sqrt(1.0 - kE2 * s * s);
  const double meridian = kA * (1.0 - kE2) / (w * w * w) + o.heightM;
  const double primeVertical = kA / w + o.heightM;
  o.latitudeDeg += north / meridian / kDeg;
  o.longitudeDeg += east / (primeVertical * std::max(std::cos(o.latitudeDeg * kDeg), 1e-6)) / kDeg;
  o.heightM -= down;
}

}  // namespace

double wrap180(double deg) {
  deg = std::fmod(deg, 360.0);
  if (deg > 180.0) deg -= 360.0;
  if (deg <= -180.0) deg += 360.0;
  return deg;
}

void OwnshipPredictor::addSample(const sky::Ownship& ownship, Clock::time_point time, const OwnshipRates& rates) {
  if (count_ > 0 && time <= lastTime_) return;
  previous_ = last_;
  previousTime_ = lastTime_;
  last_ = ownship;
  lastTime_ = time;
  rates_ = rates;
  count_ = std::min(count_ + 1, 2);
}

sky::Ownship OwnshipPredictor::at(Clock::time_point t) const {
  if (count_ == 0) return {};
  const double dt = std::clamp(std::chrono::duration<double>(t - lastTime_).count(), 0.0, maxAheadS_);
  sky::Ownship o = last_;
  if (dt == 0.0) return o;
  if (rates_.valid) {
    double n = rates_.x, e = rates_.y, d = rates_.z;
    if (rates_.bodyAxes) {  // body (x forward, y right, z down) to NED by the attitude
      const double cy = std::cos(o.attitude.yawDeg * kDeg), sy = std::sin(o.attitude.yawDeg * kDeg);
      const double cp = std::cos(o.attitude.pitchDeg * kDeg), sp = std::sin(o.attitude.pitchDeg * kDeg);
      const double cr = std::cos(o.attitude.rollDeg * kDeg), sr = std::sin(o.attitude.rollDeg * kDeg);
      n = cy * cp * rates_.x + (cy * sp * sr - sy * cr) * rates_.y + (cy * sp * cr + sy * sr) * rates_.z;
      e = sy * cp * rates_.x + (sy * sp * sr + cy * cr) * rates_.y + (sy * sp * cr - cy * sr) * rates_.z;
      d = -sp * rates_.x + cp * sr * rates_.y + cp * cr * rates_.z;
    }
    moveNed(o, n * dt, e * dt, d * dt);
    o.attitude.yawDeg += rates_.yawRate * dt;
    o.attitude.pitchDeg = std::clamp(o.attitude.pitchDeg + rates_.pitchRate * dt, -90.0, 90.0);
    o.attitude.rollDeg += rates_.rollRate * dt;
  } else if (count_ == 2) {
    const double span = std::chrono::duration<double>(lastTime_ - previousTime_).count();
    if (span <= 0.0 || span > 1.0) return o;  // samples too far apart to say how it moves
    const double k = dt / span;
    o.latitudeDeg += (last_.latitudeDeg - previous_.latitudeDeg) * k;
    o.longitudeDeg += wrap180(last_.longitudeDeg - previous_.longitudeDeg) * k;
    o.heightM += (last_.heightM - previous_.heightM) * k;
    o.attitude.yawDeg += wrap180(last_.attitude.yawDeg - previous_.attitude.yawDeg) * k;
    o.attitude.pitchDeg = std::clamp(o.attitude.pitchDeg + (last_.attitude.pitchDeg - previous_.attitude.pitchDeg) * k, -90.0, 90.0);
    o.attitude.rollDeg += wrap180(last_.attitude.rollDeg - previous_.attitude.rollDeg) * k;
  }
  o.attitude.yawDeg = std::fmod(o.attitude.yawDeg + 360.0, 360.0);
  o.attitude.rollDeg = wrap180(o.attitude.rollDeg);
  return o;
}

}  // namespace skyig::services
