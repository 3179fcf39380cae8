#include "node/host/host_atmosphere.h"
#include "physics/common/units.h"


#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::services {

HostAtmosphere::HostAtmosphere(const atmosphere::Medium& base, double groundAlbedo, double debounceS)
    : base_(base),
      groundAlbedo_(groundAlbedo),
      debounce_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(debounceS))),
      requested_{HostState{}.visibilityM, HostState{}.humidityPct},
      candidate_(requested_) {}

std::optional<atmosphere::Conditions> HostAtmosphere::observe(double visibilityM, double humidityPct,
                                                              Clock::time_point now) {
  const Values v{visibilityM, humidityPct};
  if (v == requested_ && v == candidate_) return std::nullopt;
  if (rejected_ && *rejected_ == v) return std::nullopt;  // already counted
  atmosphere::Conditions c;
  c.groundAlbedo = groundAlbedo_;
  const double visibilityKm = kmFromMetres(visibilityM);  // the host says metres, the medium km
  try {
    if (!std::isfinite(humidityPct) || humidityPct < 0.0 || humidityPct > 100.0)
      throw std::invalid_argument("host humidity " + std::to_string(humidityPct) + " % must be in [0, 100]");
    if (!std::isfinite(visibilityM))
      throw std::invalid_argument("host visibility " + std::to_string(visibilityM) + " m must be finite");
    // Throws for a visibility the medium cannot have (not positive, or beyond clean air).
    atmosphere::mieExtinctionForVisibility(base_, visibilityKm);
  } catch (const std::invalid_argument&) {
    rejected_ = v;
    throw;
  }
  rejected_.reset();
  if (!(v == candidate_)) {
    candidate_ = v;
    candidateSince_ = now;
    return std::nullopt;
  }
  if (now - candidateSince_ < debounce_ || v == requested_) return std::nullopt;
  requested_ = v;
  c.visibilityKm = visibilityKm;
  // With a visibility the humidity changes nothing (conditions.h); kept within its range.
  c.relativeHumidity = std::min(humidityPct / 100.0, 0.99);
  return c;
}

}  // namespace skyig::services
