#pragma once
// The JSON `skyig probe` prints (docs/atmosphere.md, docs/night-sky.md): the probe's plain
// values (physics/atmosphere/probe.h, sky/night_probe.h) under their documented snake_case keys.
// Formatting only: every number is the library's.
#include <nlohmann/json.hpp>

#include "physics/atmosphere/probe.h"
#include "sky/night_probe.h"
#include "skyig/sky.h"

namespace skyig::services {

// {"luminance_cd_m2": Y, "rgb_cd_m2": [r, g, b]}.
nlohmann::json probeLightJson(const atmosphere::ProbeLight& light);

// The day probe: model, altitude_m, sun, views (each with sky, sun, ground, transmittance) and,
// when computed, irradiance.
nlohmann::json probeJson(const atmosphere::ProbeResult& result);

// The day probe's JSON with each view's night lights (under their names) and "total", the
// irradiance's moon_lux and moonlit_sky_lux, and utc, latitude_deg and longitude_deg.
nlohmann::json nightProbeJson(const sky::NightProbeResult& result);

// `probe --light`: what the library gives a host (skyig::Sky::light, docs/library.md): sun and
// moon (direction_enu, normal_lux, horizontal_lux, colour_rec709), ambient_horizontal_lux,
// ambient_horizontal_rec709_lux, sky_sh_rec709_cd_m2 (nine RGB triples), adaptation_cd_m2 and
// adaptation_gain.
nlohmann::json libraryLightJson(const skyig::Light& light);

}  // namespace skyig::services
