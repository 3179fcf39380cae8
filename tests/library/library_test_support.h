#pragma once
// What the library's tests share: the sky they use (the physical sky's small tables, through
// the test cache every test of the build shares) and the observer of each scene.
#include <skyig/sky.h>

#include <cstdlib>
#include <string>

namespace skyig::testing {

inline Settings smallPhysicalSky(bool temporalAdaptation = false) {
  const std::string cache = std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache";
  ::setenv("XDG_CACHE_HOME", cache.c_str(), 1);
  Settings s;
  s.model = "physical";
  s.tables = "small";
  s.temporalAdaptation = temporalAdaptation;
  return s;
}

// Innsbruck airport on midsummer's day at hour:minute UTC, heightM above the ellipsoid.
inline Observer innsbruckAt(int hour, int minute, double heightM = 0.0) {
  Observer o;
  o.latitudeDeg = 47.2603;
  o.longitudeDeg = 11.3439;
  o.heightM = heightM;
  o.utc = {2026, 6, 21, hour * 3600.0 + minute * 60.0};
  return o;
}

}  // namespace skyig::testing
