#pragma once
// The observer: where the ownship is, how it is oriented, when, and the air it looks through.
// One type for the host's ownship (node/host/host_state.h) and the sky's observer, with one
// default place.
#include "ephemeris/refraction.h"
#include "ephemeris/time.h"
#include "sky/camera.h"

namespace skyig::sky {

// WGS84 geodetic position, height above the ellipsoid, CIGI attitude (docs/design.md, "Frames,
// units, time").
struct Ownship {
  double latitudeDeg = 47.2603;   // Innsbruck airport (LOWI), a valley the sky is framed by
  double longitudeDeg = 11.3439;
  double heightM = 581.0;
  Attitude attitude{180.0, 5.0, 0.0};  // looking south, slightly up
};

// What a sky state is computed for: the ownship at an instant, with the air's pressure and
// temperature at the observer, which scale the refraction of the sun, moon and stars
// (ephemeris/refraction.h).
struct ObserverState : Ownship {
  ephemeris::UtcTime utc{2026, 6, 21, 17 * 3600.0};  // 19:00 CEST on midsummer's day
  double pressureHpa = ephemeris::kStandardPressureHpa;
  double temperatureC = ephemeris::kStandardTemperatureC;
};

}  // namespace skyig::sky
