#pragma once
// Scripted weather for the host emulator (`skyig host --weather FILE`): what the host sends from
// each time on, held until the next line. CSV, one change a line:
//   time_s, visibility_m, humidity_pct, fog_visibility_m, fog_top_m
// with '#' comments and an optional header line; a fog visibility of 0 switches the ground fog
// (CIGI Weather Control layer 0) off.
#include <string>
#include <vector>

namespace skyig::services {

struct WeatherStep {
  double timeS = 0.0;
  double visibilityM = 40000.0;
  double humidityPct = 0.0;
  double fogVisibilityM = 0.0;
  double fogTopM = 0.0;
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
