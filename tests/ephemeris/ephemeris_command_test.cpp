// `skyig ephemeris` through CLI11, without the executable: JSON fields, values, bad flags.
#include "commands/ephemeris_command.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

using namespace skyig;
using namespace skyig::ephemeris;

namespace {
struct CommandRun {
  int exitCode = -1;
  std::string out, err;
};

CommandRun run(std::vector<std::string> args) {
  CLI::App app("skyig");
  CommandRun r;
  std::ostringstream out, err;
  services::registerEphemerisCommand(app, r.exitCode, out, err);
  args.insert(args.begin(), "ephemeris");
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 wants them reversed
  app.parse(reversed);
  r.out = out.str();
  r.err = err.str();
  return r;
}
}  // namespace

TEST(EphemerisCommand, PrintsTheDocumentedFields) {
  const CommandRun r = run({"--lat", "47.3769", "--lon", "8.5417", "--alt", "408", "--utc", "2024-08-12T21:30:00Z",
                     "--stars", "5"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* body : {"sun", "moon"})
    for (const char* key : {"azimuth_deg", "altitude_deg", "altitude_refracted_deg", "distance_km"})
      EXPECT_TRUE(j[body].contains(key)) << body << "." << key;
  for (const char* key : {"phase_angle_deg", "illuminated_fraction", "bright_limb_angle_deg", "angular_radius_deg"})
    EXPECT_TRUE(j["moon"].contains(key)) << key;
  ASSERT_EQ(j["planets"].size(), 5u);
  EXPECT_EQ(j["planets"][1]["name"], "Venus");
  for (const char* key : {"name", "azimuth_deg", "altitude_deg", "magnitude"}) EXPECT_TRUE(j["planets"][0].contains(key));
  EXPECT_DOUBLE_EQ(j["tt_minus_utc_s"].get<double>(), 69.184);
  ASSERT_EQ(j["stars"].size(), 5u);
  EXPECT_EQ(j["stars"][0]["hr"], 2491);  // Sirius, below the horizon in a Zurich August night
  EXPECT_LT(j["stars"][0]["altitude_deg"].get<double>(), 0.0);
  EXPECT_NEAR(j["stars"][0]["colour_temperature_k"].get<double>(), 7000.0 / (0.0 + 0.56), 7000.0 / 0.56 * 0.05);
  // The values are those of computeEphemeris, in degrees and hours.
  Observer o;
  o.latitudeRad = 47.3769 * kDegToRad;
  o.longitudeRad = 8.5417 * kDegToRad;
  o.heightM = 408.0;
  const SkyEphemeris s = computeEphemeris(UtcTime{2024, 8, 12, 21.5 * 3600.0}, o);
  EXPECT_NEAR(j["moon"]["azimuth_deg"].get<double>(), s.moon.azimuthRad / kDegToRad, 1e-9);
  EXPECT_NEAR(j["gast_hours"].get<double>(), s.gastRad / kTwoPi * 24.0, 1e-12);
}

TEST(EphemerisCommand, TimeOverridesReachTheComputation) {
  const CommandRun r = run({"--lat", "0", "--lon", "0", "--utc", "2000-01-01T12:00:00Z", "--tt-minus-utc", "64.184",
                     "--dut1", "0.355"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["tt_minus_utc_s"].get<double>(), 64.184);
  EXPECT_DOUBLE_EQ(j["ut1_minus_utc_s"].get<double>(), 0.355);
}

TEST(EphemerisCommand, BadValuesGiveAMessageAndExitCode2) {
  CommandRun r = run({"--lat", "91", "--lon", "0", "--utc", "2024-01-01T00:00:00Z"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("latitude 91"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = run({"--lat", "10", "--lon", "0", "--utc", "2024-13-01T00:00:00Z"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("2024-13-01T00:00:00Z"), std::string::npos) << r.err;
  r = run({"--lat", "10", "--lon", "0", "--utc", "2150-01-01T00:00:00Z"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("2150"), std::string::npos) << r.err;
  r = run({"--lat", "10", "--lon", "0", "--utc", "2024-01-01T00:00:00Z", "--stars", "3", "--catalogue", "/no/such.csv"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/no/such.csv"), std::string::npos) << r.err;
  // The former spelling of the flag, as scripts written for it pass it.
  r = run({"--lat", "10", "--lon", "0", "--utc", "2024-01-01T00:00:00Z", "--stars", "3", "--catalog", "/no/such.csv"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/no/such.csv"), std::string::npos) << r.err;
}

TEST(EphemerisCommand, MalformedFlagsAreParseErrors) {
  // CLI11 rejects these before the callback; skyig's main maps CLI::ParseError to exit code 2.
  EXPECT_THROW(run({"--lat", "north", "--lon", "0", "--utc", "2024-01-01T00:00:00Z"}), CLI::ParseError);
  EXPECT_THROW(run({"--lon", "0", "--utc", "2024-01-01T00:00:00Z"}), CLI::RequiredError);
  EXPECT_THROW(run({"--lat", "1", "--lon", "0", "--utc", "2024-01-01T00:00:00Z", "--bogus"}), CLI::ParseError);
}
