#pragma once
// HostState: what the host last told this IG, as one immutable snapshot handed from the
// receiver thread to the worker and render threads (latest value wins).
#include "ephemeris/refraction.h"
#include "ephemeris/time.h"
#include "physics/common/sky_conditions.h"
#include "physics/weather/precipitation.h"
#include "sky/observer.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>

namespace skyig::services {

using Clock = std::chrono::steady_clock;

// CIGI Rate Control of the ownship: linear rates (m/s) and angular rates (deg/s).
struct OwnshipRates {
  bool valid = false;
  bool bodyAxes = false;  // false: x north, y east, z down; true: body x forward, y right, z down
  double x = 0.0, y = 0.0, z = 0.0;
  double rollRate = 0.0, pitchRate = 0.0, yawRate = 0.0;
};

// A moment on the host's own clock (its IG Control timestamps): seconds, and how fast that
// clock runs, in host seconds per local second.
struct HostTime {
  double seconds = 0.0;
  double rate = 1.0;
};

// A channel's eyepoint rotation, frustum and goggle as the host set them (CIGI View Control,
// View Definition and Sensor Control); view ID n is the node's n-th channel. Unset parts keep
// the configuration's.
struct ViewOverride {
  std::uint16_t viewId = 0;
  std::optional<double> yawDeg, pitchDeg, rollDeg;
  std::optional<double> leftDeg, rightDeg, upDeg, downDeg;  // skyig's half-angles
  std::optional<bool> sensorOn;       // the channel's night-vision goggle switched on or off
  std::optional<bool> automaticGain;  // the goggle's automatic brightness control
  std::optional<double> gain;         // the goggle's gain without it, a fraction in (0, 1]
};

// The most view ids a node keeps (host.max_views is at most this). The table is a fixed array
// indexed by id, so applying a View Control is O(1) and a snapshot copies a few kilobytes
// whatever the host sends; ids at or above the configured maximum are counted and dropped.
inline constexpr std::size_t kViewTableCapacity = 64;
inline constexpr std::size_t kDefaultMaxViews = 32;  // host.max_views

class ViewTable {
 public:
  // The entry of `id`, created on first use; null when id >= limit.
  ViewOverride* entry(std::uint16_t id, std::size_t limit) {
    if (id >= limit || id >= kViewTableCapacity) return nullptr;
    if (!(used_ & (1ull << id))) {
      entries_[id] = ViewOverride{};
      entries_[id].viewId = id;
      used_ |= 1ull << id;
    }
    return &entries_[id];
  }
  // The entry of `id` if the host set one.
  const ViewOverride* find(std::size_t id) const {
    return id < kViewTableCapacity && (used_ & (1ull << id)) ? &entries_[id] : nullptr;
  }
  std::size_t size() const { return static_cast<std::size_t>(__builtin_popcountll(used_)); }

 private:
  std::array<ViewOverride, kViewTableCapacity> entries_{};
  std::uint64_t used_ = 0;  // bit id: entries_[id] was set by the host
  static_assert(kViewTableCapacity <= 64, "one bit per id in used_");
};

struct HostState {
  std::uint64_t updates = 0;          // host messages applied so far (0: nothing yet)
  std::uint32_t hostFrame = 0;        // IG Control host frame number of the last message
  std::uint8_t cigiMajorVersion = 3;  // CIGI version of the last IG Control (3 or 4): SOF's version
  bool ownshipValid = false;
  sky::Ownship ownship;
  Clock::time_point ownshipTime{};    // arrival of the message that last set the ownship
  OwnshipRates rates;
  bool timeValid = false;             // a date and time has been received
  ephemeris::UtcTime utc;             // the host's time, refined below the minute (see SimClock)
  Clock::time_point utcTime{};        // the local instant utc refers to
  double visibilityM = 50000.0;
  double humidityPct = 0.0;
  // CIGI Weather Control, layer 0 (ground fog), global: unset until the host sends one; a layer
  // the host disabled has a visibility of 0.
  std::optional<sky::FogSpec> groundFog;
  // CIGI Weather Control, layers 4-9 (weather::Precipitation), global: unset until the host sends
  // one; a layer the host disabled has a visibility of 0.
  std::array<std::optional<sky::FogSpec>, weather::kPrecipitationKinds> precipitation;
  // CIGI Weather Control, layers 1-3, global: unset until the host sends one (a layer the host
  // disabled is not enabled()); a layer with a bad value is refused and the last good one kept.
  std::array<std::optional<sky::CloudLayer>, sky::kCloudLayers> clouds;
  double temperatureC = ephemeris::kStandardTemperatureC;  // CIGI Atmosphere Control: refraction
  double pressureHpa = ephemeris::kStandardPressureHpa;
  // CIGI Celestial Sphere Control: star field intensity / 100, 0 while the field is disabled.
  double starFieldIntensity = 1.0;
  Clock::time_point received{};       // arrival of the last applied message
  ViewTable views;
};

}  // namespace skyig::services
