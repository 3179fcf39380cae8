#include "node/host/host_weather.h"

#include "node/common/config_error.h"
#include "node/host/host_script.h"
#include "physics/weather/cloud_layer.h"

#include <algorithm>
#include <cmath>

namespace skyig::services {

HostWeather HostWeather::parse(const std::string& text, const std::string& sourceName) {
  HostWeather w;
  forEachScriptLine(text, [&](std::istringstream& fields, int lineNumber) {
    WeatherStep s;
    std::string extra;
    auto fail = [&](const std::string& why) { throw ConfigError(sourceName + ":" + std::to_string(lineNumber) + ": " + why); };
    if (!(fields >> s.timeS >> s.visibilityM >> s.humidityPct >> s.fogVisibilityM >> s.fogTopM))
      fail("expected 5 numbers: time_s, visibility_m, humidity_pct, fog_visibility_m, fog_top_m");
    std::string kind;
    if (fields >> kind) {
      if (kind != "none") {
        s.precipitation = weather::parsePrecipitation(kind);
        if (!s.precipitation) fail("precipitation \"" + kind + "\": expected none, rain, snow, sleet, hail, sand or dust");
      }
      if (!(fields >> s.precipitationSeverity >> s.precipitationVisibilityM >> s.precipitationTopM))
        fail("after the precipitation, expected its severity, precipitation_visibility_m and precipitation_top_m");
      if (s.precipitationSeverity < 0 || s.precipitationSeverity > 5)
        fail("severity " + std::to_string(s.precipitationSeverity) + " must be in [0, 5]");
      if (!(s.precipitationVisibilityM >= 0.0) || !(s.precipitationTopM > 0.0))
        fail("precipitation_visibility_m must be 0 (the severity's) or more and precipitation_top_m above 0");
      std::string cloud;
      if (fields >> cloud) {
        s.cloud = sky::CloudLayer{};  // "none": layer 1 sent switched off
        if (cloud != "none") {
          try {
            s.cloud = weather::parseCloudSpec(cloud);
          } catch (const std::invalid_argument& e) {
            fail(std::string("cloud: ") + e.what());
          }
        }
      }
    }
    if (fields >> extra) fail("unexpected \"" + extra + "\" after the last field");
    for (double v : {s.timeS, s.visibilityM, s.humidityPct, s.fogVisibilityM, s.fogTopM, s.precipitationVisibilityM,
                     s.precipitationTopM})
      if (!std::isfinite(v)) fail("a value is not a finite number");
    if (!(s.visibilityM > 0.0)) fail("visibility_m " + std::to_string(s.visibilityM) + " must be above 0");
    if (s.humidityPct < 0.0 || s.humidityPct > 100.0) fail("humidity_pct " + std::to_string(s.humidityPct) + " must be in [0, 100]");
    if (s.fogVisibilityM < 0.0 || (s.fogVisibilityM > 0.0 && !(s.fogTopM > 0.0)))
      fail("a fog needs a visibility above 0 and a top above the ground (fog_visibility_m 0: none)");
    if (!w.steps_.empty() && s.timeS <= w.steps_.back().timeS) fail("times must increase");
    w.steps_.push_back(s);
  });
  if (w.steps_.empty()) throw ConfigError(sourceName + ": a weather script needs at least one line");
  return w;
}

HostWeather HostWeather::load(const std::string& file) { return parse(readHostScript(file, "weather script"), file); }

HostWeather HostWeather::constant(const WeatherStep& step) {
  HostWeather w;
  w.steps_.push_back(step);
  return w;
}

const WeatherStep& HostWeather::at(double t) const {
  auto next = std::upper_bound(steps_.begin(), steps_.end(), t, [](double v, const WeatherStep& s) { return v < s.timeS; });
  return next == steps_.begin() ? steps_.front() : *(next - 1);
}

}  // namespace skyig::services
