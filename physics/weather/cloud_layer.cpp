#include "physics/weather/cloud_layer.h"

#include "physics/common/parse_number.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace skyig::weather {

namespace {
using sky::CloudType;
constexpr std::array<std::string_view, 10> kNames = {"altocumulus", "altostratus",   "cirrocumulus", "cirrostratus",
                                                     "cirrus",      "cumulonimbus",  "cumulus",      "nimbostratus",
                                                     "stratocumulus", "stratus"};

void require(bool ok, const char* what, double value) {
  if (ok) return;
  char text[96];
  std::snprintf(text, sizeof text, "cloud layer: %s %g is out of range", what, value);
  throw std::invalid_argument(text);
}
}  // namespace

CloudFamily familyOf(CloudType type) {
  switch (type) {
    case CloudType::Cumulus:
    case CloudType::Cumulonimbus: return CloudFamily::Cumuliform;
    case CloudType::Cirrus:
    case CloudType::Cirrostratus:
    case CloudType::Cirrocumulus: return CloudFamily::Cirriform;
    default: return CloudFamily::Stratiform;
  }
}

std::string_view toString(CloudType type) { return kNames[static_cast<std::size_t>(type) - 1]; }

std::optional<CloudType> parseCloudType(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<CloudType>(i + 1);
  return std::nullopt;
}

std::optional<CloudType> cloudTypeOfCigi(int value) {
  if (value < 1 || value > 10) return std::nullopt;
  return static_cast<CloudType>(value);
}

void validate(const sky::CloudLayer& l) {
  if (!l.enabled) return;
  require(std::isfinite(l.baseM), "base", l.baseM);
  require(std::isfinite(l.thicknessM) && l.thicknessM > 0.0, "thickness", l.thicknessM);
  require(l.coveragePct >= 0.0 && l.coveragePct <= 100.0, "coverage", l.coveragePct);
  require(l.transitionM >= 0.0 && std::isfinite(l.transitionM), "transition band", l.transitionM);
  require(l.topTransitionM >= 0.0 && std::isfinite(l.topTransitionM), "top transition band", l.topTransitionM);
  require(l.severity >= 0 && l.severity <= 5, "severity", l.severity);
  require(l.visibilityM >= 0.0 && std::isfinite(l.visibilityM), "visibility", l.visibilityM);
  require(l.scudFrequencyPct >= 0.0 && l.scudFrequencyPct <= 100.0, "scud frequency", l.scudFrequencyPct);
  require(l.topScudFrequencyPct >= 0.0 && l.topScudFrequencyPct <= 100.0, "top scud frequency", l.topScudFrequencyPct);
  require(l.windSpeedMps >= 0.0 && l.windSpeedMps <= 150.0, "wind speed", l.windSpeedMps);
  require(std::isfinite(l.windFromDeg), "wind direction", l.windFromDeg);
  require(static_cast<int>(l.type) >= 1 && static_cast<int>(l.type) <= 10, "type", static_cast<int>(l.type));
}

sky::CloudLayer parseCloudSpec(std::string_view spec) {
  std::vector<std::string> parts(1);
  for (char c : spec) {
    if (c == ':') parts.emplace_back();
    else parts.back() += c;
  }
  const std::string quoted = "\"" + std::string(spec) + "\"";
  if (parts.size() < 3 || parts.size() == 5 || parts.size() > 6)
    throw std::invalid_argument(quoted + " is not TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]], e.g. stratus:300:400:100 or "
                                "cumulus:1200:800:50:10:270");
  sky::CloudLayer l;
  l.enabled = true;
  const std::optional<CloudType> type = parseCloudType(parts[0]);
  if (!type) throw std::invalid_argument(quoted + ": \"" + parts[0] + "\" is not a cloud type (stratus, cumulus, cirrus, ...)");
  l.type = *type;
  auto number = [&](const std::string& text, const char* what) {
    const std::optional<double> v = parseWholeNumber(text);
    if (!v) throw std::invalid_argument(quoted + ": " + what + " \"" + text + "\" is not a number");
    return *v;
  };
  l.baseM = number(parts[1], "the base");
  l.thicknessM = number(parts[2], "the thickness");
  l.coveragePct = parts.size() >= 4 ? number(parts[3], "the coverage") : 100.0;
  if (parts.size() == 6) {
    l.windSpeedMps = number(parts[4], "the wind speed");
    l.windFromDeg = number(parts[5], "the wind's direction");
  }
  validate(l);
  return l;
}

std::string describe(const sky::CloudLayer& l) {
  if (!l.enabled) return "off";
  char text[112];
  std::snprintf(text, sizeof text, " base %.0f m, %.0f m thick, %.0f %% cover, severity %d", l.baseM, l.thicknessM,
                l.coveragePct, l.severity);
  return std::string(toString(l.type)) + text;
}

}  // namespace skyig::weather
