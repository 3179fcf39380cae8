#pragma once
// A scripted flight for the host emulator: waypoints with times, interpolated linearly
// (headings the short way round). CSV, one waypoint a line:
//   time_s, latitude_deg, longitude_deg, altitude_m, yaw_deg, pitch_deg, roll_deg
// with '#' comments and an optional header line.
#include "node/host/host_state.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::services {

struct Waypoint {
  double timeS = 0.0;
  sky::Ownship pose;
};

class HostPath {
 public:
  // Throws ConfigError naming the file and line of a bad waypoint.
  static HostPath load(const std::string& path);
  static HostPath parse(const std::string& text, const std::string& sourceName);

  double durationS() const { return waypoints_.back().timeS; }
  sky::Ownship at(double timeS) const;          // clamped to the path's ends
  OwnshipRates ratesAt(double timeS) const;  // NED m/s and deg/s of the segment at timeS

 private:
  std::vector<Waypoint> waypoints_;
};

}  // namespace skyig::services
