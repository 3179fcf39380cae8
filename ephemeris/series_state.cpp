#include "ephemeris/series_state.h"

#include "ephemeris/elp82b.h"

namespace skyig::ephemeris {

SeriesState evaluateSeries(double jdTt) {
  SeriesState s;
  s.jdTt = jdTt;
  s.earth = vsop87Heliocentric(VsopBody::Earth, jdTt);
  constexpr VsopBody kBodies[5] = {VsopBody::Mercury, VsopBody::Venus, VsopBody::Mars, VsopBody::Jupiter,
                                   VsopBody::Saturn};
  for (std::size_t i = 0; i < 5; ++i) s.planets[i] = vsop87Heliocentric(kBodies[i], jdTt);
  s.moonGeocentricKm = elp82bGeocentric(jdTt - kMoonLightTimeDays);
  s.nutation = nutation2000B(jdTt);
  return s;
}

}  // namespace skyig::ephemeris
