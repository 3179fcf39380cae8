#include "ephemeris/ephemeris_cache.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::ephemeris {

namespace {
Vec3 mix(const double w[4], Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return w[0] * a + w[1] * b + w[2] * c + w[3] * d;
}
StateVector mix(const double w[4], const StateVector& a, const StateVector& b, const StateVector& c,
                const StateVector& d) {
  return {mix(w, a.position, b.position, c.position, d.position), mix(w, a.velocity, b.velocity, c.velocity, d.velocity)};
}
}  // namespace

EphemerisCache::EphemerisCache(double nodeSpacingDays) : spacing_(nodeSpacingDays) {
  if (!(nodeSpacingDays > 0.0 && nodeSpacingDays <= 0.25))
    throw std::invalid_argument("ephemeris cache node spacing " + std::to_string(nodeSpacingDays) +
                                " days is outside (0, 0.25]");
}

const SeriesState& EphemerisCache::node(std::int64_t index) {
  Slot& slot = slots_[static_cast<std::size_t>(index & 7)];
  if (slot.index != index) {
    slot.state = evaluateSeries(2451545.0 + static_cast<double>(index) * spacing_);
    slot.index = index;
    ++evaluations_;
  }
  return slot.state;
}

SeriesState EphemerisCache::interpolate(double jdTt) {
  const double u = (jdTt - 2451545.0) / spacing_;
  const double k = std::floor(u);
  const double x = u - k;
  const auto i = static_cast<std::int64_t>(k);
  // Cubic Lagrange weights for nodes -1, 0, 1, 2 at fraction x of the central interval.
  const double w[4] = {-x * (x - 1.0) * (x - 2.0) / 6.0, (x + 1.0) * (x - 1.0) * (x - 2.0) / 2.0,
                       -(x + 1.0) * x * (x - 2.0) / 2.0, (x + 1.0) * x * (x - 1.0) / 6.0};
  const SeriesState& a = node(i - 1);
  const SeriesState& b = node(i);
  const SeriesState& c = node(i + 1);
  const SeriesState& d = node(i + 2);
  SeriesState s;
  s.jdTt = jdTt;
  s.earth = mix(w, a.earth, b.earth, c.earth, d.earth);
  for (std::size_t p = 0; p < s.planets.size(); ++p) s.planets[p] = mix(w, a.planets[p], b.planets[p], c.planets[p], d.planets[p]);
  s.moonGeocentricKm = mix(w, a.moonGeocentricKm, b.moonGeocentricKm, c.moonGeocentricKm, d.moonGeocentricKm);
  s.nutation.dpsi = w[0] * a.nutation.dpsi + w[1] * b.nutation.dpsi + w[2] * c.nutation.dpsi + w[3] * d.nutation.dpsi;
  s.nutation.deps = w[0] * a.nutation.deps + w[1] * b.nutation.deps + w[2] * c.nutation.deps + w[3] * d.nutation.deps;
  return s;
}

SkyEphemeris EphemerisCache::compute(const UtcTime& utc, const Observer& observer, const EphemerisOptions& options) {
  checkObserver(observer);
  const TimeScales ts = timeScales(utc, options.ttMinusUtcS, options.dut1S);
  return assembleEphemeris(ts, observer, interpolate(ts.jdTt));
}

}  // namespace skyig::ephemeris
