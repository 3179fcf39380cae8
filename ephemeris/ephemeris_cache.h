#pragma once
// Frame-to-frame ephemeris for the worker thread: the series (SeriesState) are evaluated at
// nodes one hour apart and interpolated with a cubic through the four nodes around the instant
// (Lagrange, central interval). The interpolation error is below 1e-4 km for the moon and far
// less for the planets (tests/ephemeris/ephemeris_cache_test.cpp measures it), so a frame costs
// only the cheap assembly; crossing a node costs one series evaluation, a jump in time four.
// Not thread-safe: one cache per worker.
#include <array>
#include <cstdint>

#include "ephemeris/ephemeris.h"
#include "ephemeris/series_state.h"

namespace skyig::ephemeris {

class EphemerisCache {
 public:
  explicit EphemerisCache(double nodeSpacingDays = 1.0 / 24.0);

  // Same contract as computeEphemeris (same exceptions), interpolated series.
  SkyEphemeris compute(const UtcTime& utc, const Observer& observer, const EphemerisOptions& options = {});

  // The interpolated series at TT Julian date jdTt.
  SeriesState interpolate(double jdTt);

  // Series evaluations done so far (to test and benchmark the cache).
  std::uint64_t evaluations() const { return evaluations_; }

 private:
  const SeriesState& node(std::int64_t index);

  struct Slot {
    std::int64_t index = INT64_MIN;
    SeriesState state;
  };
  double spacing_;
  std::array<Slot, 8> slots_{};
  std::uint64_t evaluations_ = 0;
};

}  // namespace skyig::ephemeris
