#include "node/host/sim_clock.h"

#include <algorithm>
#include <cmath>

namespace skyig::services {

void SimClock::observe(const ephemeris::UtcTime& stated, double continuousS, double resolutionS) {
  const double statedDay = ephemeris::julianDayAt0h(stated.year, stated.month, stated.day);
  // The start of the window the host's statement allows: the minute for CIGI 3.3, the stated
  // instant itself when the host states seconds.
  const double windowStart = resolutionS >= 60.0 ? std::floor(stated.secondsOfDay / 60.0) * 60.0 : stated.secondsOfDay;
  if (!valid_) {
    // First statement: assume the start of the window; for a minute, the first rollover will
    // correct it.
    valid_ = true;
    dayStartJd_ = statedDay;
    anchorS_ = continuousS;
    offsetS_ = windowStart;
    return;
  }
  // The window the host allows, in seconds since our day start, and what the clock shows.
  const double lo = (statedDay - dayStartJd_) * 86400.0 + windowStart, hi = lo + resolutionS;
  const double shown = (continuousS - anchorS_) * speed_ + offsetS_;
  if (shown < lo - 90.0 || shown > hi + 90.0) {  // a new scenario time: start again from it
    anchorS_ = continuousS;
    offsetS_ = lo;
  } else if (shown < lo) {
    offsetS_ += lo - shown;  // the host's minute began later than we thought
  } else if (shown >= hi) {
    offsetS_ -= shown - (hi - std::min(1e-3, resolutionS / 2));  // we ran ahead of the host's window
  }
}

std::optional<ephemeris::UtcTime> SimClock::at(double continuousS) const {
  if (!valid_) return std::nullopt;
  // Whole days and seconds kept apart: a Julian date in one double would cost ~50 us.
  const double seconds = (continuousS - anchorS_) * speed_ + offsetS_;
  const double days = std::floor(seconds / 86400.0);
  // Back to a calendar date: Meeus ch. 7 inverse, Gregorian calendar (dayStartJd_ is at 0h).
  const double z = dayStartJd_ + 0.5 + days;
  const double alpha = std::floor((z - 1867216.25) / 36524.25);
  const double a = z + 1 + alpha - std::floor(alpha / 4);
  const double b = a + 1524;
  const double c = std::floor((b - 122.1) / 365.25);
  const double d = std::floor(365.25 * c);
  const double e = std::floor((b - d) / 30.6001);
  ephemeris::UtcTime t;
  t.day = static_cast<int>(b - d - std::floor(30.6001 * e));
  t.month = static_cast<int>(e < 14 ? e - 1 : e - 13);
  t.year = static_cast<int>(t.month > 2 ? c - 4716 : c - 4715);
  t.secondsOfDay = seconds - days * 86400.0;
  return t;
}

}  // namespace skyig::services
