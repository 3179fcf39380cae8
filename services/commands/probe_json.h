#pragma once
// The JSON `skyig probe` prints (docs/atmosphere.md, docs/night-sky.md): the probe's plain
// values (sky/atmosphere/probe.h, sky/night_probe.h) under their documented snake_case keys.
// Formatting only: every number is the library's.
#include <nlohmann/json.hpp>

#include "sky/atmosphere/probe.h"
#include "sky/night_probe.h"

namespace skyig::services {

// {"luminance_cd_m2": Y, "rgb_cd_m2": [r, g, b]}.
nlohmann::json probeLightJson(const atmosphere::ProbeLight& light);

// The day probe: model, altitude_m, sun, views (each with sky, sun, ground, transmittance) and,
// when computed, irradiance.
nlohmann::json probeJson(const atmosphere::ProbeResult& result);

// The day probe's JSON with each view's night lights (under their names) and "total", the
// irradiance's moon_lux and moonlit_sky_lux, and utc, latitude_deg and longitude_deg.
nlohmann::json nightProbeJson(const sky::NightProbeResult& result);

}  // namespace skyig::services
