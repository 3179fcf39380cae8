#pragma once
// Scripted weather for the host emulator (`skyig host --weather FILE`): what the host sends from
// each time on, held until the next line. CSV, one change a line:
//   time_s, visibility_m, humidity_pct, fog_visibility_m, fog_top_m
//   [, precipitation, severity, precipitation_visibility_m, precipitation_top_m [, cloud]]
// with '#' comments and an optional header line; a fog visibility of 0 switches the ground fog
// (CIGI Weather Control layer 0) off; precipitation is none, rain, snow, sleet, hail, sand or
// dust (layers 4-9; the others off), its visibility 0 the severity's (0-5); cloud is cloud
// layer 1 as TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]] (physics/weather/cloud_layer.h) or
// none (sent switched off). A script without the cloud column leaves layer 1 to --cloud.
#include <optional>
#include <string>
#include <vector>

#include "physics/common/cloud_layer.h"
#include "physics/weather/precipitation.h"

namespace skyig::services {

struct WeatherStep {
  double timeS = 0.0;
  double visibilityM = 40000.0;
  double humidityPct = 0.0;
  double fogVisibilityM = 0.0;
  double fogTopM = 0.0;
  std::optional<weather::Precipitation> precipitation;  // none: every layer 4-9 off
  int precipitationSeverity = 2;
  double precipitationVisibilityM = 0.0;  // 0: the severity's
  double precipitationTopM = 1500.0;
  std::optional<sky::CloudLayer> cloud;  // cloud layer 1 to send (enabled or not); none: not sent
};

class HostWeather {
 public:
  // Throws ConfigError naming the file and line of a bad step.
  static HostWeather load(const std::string& path);
  static HostWeather parse(const std::string& text, const std::string& sourceName);
  // One step from the command line's values (no script).
  static HostWeather constant(const WeatherStep& step);

  const WeatherStep& at(double timeS) const;  // the last step at or before timeS (the first before it)

 private:
  std::vector<WeatherStep> steps_;
};

}  // namespace skyig::services
