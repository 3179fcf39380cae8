#pragma once
// `skyig ephemeris`: apparent topocentric positions of the sun, moon, planets (and optionally the
// brightest stars) for a place and a UTC instant, as JSON. Degrees at the interface; every field
// is documented in docs/ephemeris.md.
#include "ephemeris/refraction.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "ephemeris/ephemeris.h"

namespace skyig::services {

struct EphemerisRequest {
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0;
  double altitudeM = 0.0;
  std::string utc;  // ISO 8601, e.g. 2024-06-21T12:00:00Z
  double pressureHpa = ephemeris::kStandardPressureHpa;
  double temperatureC = ephemeris::kStandardTemperatureC;
  std::optional<double> ttMinusUtcS;
  std::optional<double> dut1S;
  std::size_t stars = 0;        // the N brightest stars
  std::string cataloguePath;    // Bright Star Catalogue CSV (for stars > 0); "" = the bundled one
};

// The JSON document of a request. Throws std::invalid_argument (bad value, named) or
// std::runtime_error (unreadable or corrupt catalogue, naming file and line).
nlohmann::json ephemerisToJson(const EphemerisRequest& request);

// The JSON of a computed sky; stars (may be empty) are reported in the order given.
nlohmann::json ephemerisToJson(const ephemeris::SkyEphemeris& sky, const std::vector<ephemeris::Star>& stars);

// Adds the `ephemeris` subcommand. Its callback prints the JSON to out (exitCode 0) or a message
// naming the bad value to err (exitCode 2).
void registerEphemerisCommand(CLI::App& app, int& exitCode, std::ostream& out, std::ostream& err);
void registerEphemerisCommand(CLI::App& app, int& exitCode);  // std::cout / std::cerr

}  // namespace skyig::services
