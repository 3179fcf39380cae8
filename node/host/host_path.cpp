#include "node/host/host_path.h"

#include "node/common/config_error.h"
#include "node/host/host_script.h"
#include "node/host/ownship_predictor.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace skyig::services {

namespace {
using skyig::kDeg;
constexpr double kEarthRadius = 6371008.8;  // mean radius: rates are for dead reckoning only
}  // namespace

HostPath HostPath::parse(const std::string& text, const std::string& sourceName) {
  HostPath path;
  forEachScriptLine(text, [&](std::istringstream& fields, int lineNumber) {
    Waypoint w;
    sky::Ownship& p = w.pose;
    std::string extra;
    auto fail = [&](const std::string& why) {
      throw ConfigError(sourceName + ":" + std::to_string(lineNumber) + ": " + why);
    };
    if (!(fields >> w.timeS >> p.latitudeDeg >> p.longitudeDeg >> p.heightM >> p.attitude.yawDeg >> p.attitude.pitchDeg >> p.attitude.rollDeg) ||
        (fields >> extra))
      fail("expected 7 numbers: time_s, latitude, longitude, altitude_m, yaw, pitch, roll");
    const double all[7] = {w.timeS, p.latitudeDeg, p.longitudeDeg, p.heightM, p.attitude.yawDeg, p.attitude.pitchDeg, p.attitude.rollDeg};
    for (double v : all)
      if (!std::isfinite(v)) fail("a value is not a finite number");
    if (std::abs(p.latitudeDeg) > 90.0 || std::abs(p.attitude.pitchDeg) > 90.0) fail("latitude or pitch outside [-90, 90]");
    if (!path.waypoints_.empty() && w.timeS <= path.waypoints_.back().timeS) fail("times must increase");
    path.waypoints_.push_back(w);
  });
  if (path.waypoints_.size() < 2) throw ConfigError(sourceName + ": a path needs at least two waypoints");
  return path;
}

HostPath HostPath::load(const std::string& file) { return parse(readHostScript(file, "path file"), file); }

sky::Ownship HostPath::at(double t) const {
  t = std::clamp(t, waypoints_.front().timeS, waypoints_.back().timeS);
  auto next = std::upper_bound(waypoints_.begin(), waypoints_.end(), t, [](double v, const Waypoint& w) { return v < w.timeS; });
  if (next == waypoints_.end()) return waypoints_.back().pose;
  const Waypoint& b = *next;
  const Waypoint& a = *(next - 1);
  const double k = (t - a.timeS) / (b.timeS - a.timeS);
  auto lerp = [k](double x, double y) { return x + (y - x) * k; };
  sky::Ownship o;
  o.latitudeDeg = lerp(a.pose.latitudeDeg, b.pose.latitudeDeg);
  o.longitudeDeg = a.pose.longitudeDeg + wrap180(b.pose.longitudeDeg - a.pose.longitudeDeg) * k;
  o.heightM = lerp(a.pose.heightM, b.pose.heightM);
  o.attitude.yawDeg = std::fmod(a.pose.attitude.yawDeg + wrap180(b.pose.attitude.yawDeg - a.pose.attitude.yawDeg) * k + 360.0, 360.0);
  o.attitude.pitchDeg = lerp(a.pose.attitude.pitchDeg, b.pose.attitude.pitchDeg);
  o.attitude.rollDeg = wrap180(a.pose.attitude.rollDeg + wrap180(b.pose.attitude.rollDeg - a.pose.attitude.rollDeg) * k);
  return o;
}

OwnshipRates HostPath::ratesAt(double t) const {
  const double dt = 0.01;
  const double t0 = std::clamp(t, waypoints_.front().timeS, waypoints_.back().timeS - dt);
  const sky::Ownship a = at(t0), b = at(t0 + dt);
  OwnshipRates r;
  r.valid = true;
  r.x = (b.latitudeDeg - a.latitudeDeg) * kDeg * kEarthRadius / dt;
  r.y = wrap180(b.longitudeDeg - a.longitudeDeg) * kDeg * kEarthRadius * std::cos(a.latitudeDeg * kDeg) / dt;
  r.z = -(b.heightM - a.heightM) / dt;
  r.yawRate = wrap180(b.attitude.yawDeg - a.attitude.yawDeg) / dt;
  r.pitchRate = (b.attitude.pitchDeg - a.attitude.pitchDeg) / dt;
  r.rollRate = wrap180(b.attitude.rollDeg - a.attitude.rollDeg) / dt;
  return r;
}

}  // namespace skyig::services
