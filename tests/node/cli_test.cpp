// The skyig executable as a user meets it: defaults, outputs, and exit code 2 with a clear
// message for bad flags, bad configuration and unwritable outputs — writing nothing then.
#include "render/image_io.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <variant>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using Result = skyig::services::testing::SkyigResult;
using skyig::services::testing::slurp;

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("skyig_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                                           "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `environment`: env(1) arguments, e.g. "-u SKYIG_DATA_DIR" (the test programs set it,
  // tests/staged_data_dir.cpp, and skyig inherits it).
  Result run(const std::string& args, const std::string& environment = "") const {
    return skyig::services::testing::runSkyig(args, dir_, environment);
  }

  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }

  size_t imageFiles() const {
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().extension() != ".txt" && e.path().extension() != ".toml") ++n;
    return n;
  }

  fs::path dir_;
};

}  // namespace

TEST_F(Cli, RendersAnAnalyticSkyWithOnlyAnOutput) {
  const Result r = run("render --sky-model preetham --size 64x48 --exr " + (dir_ / "sky.exr").string() + " --png " + (dir_ / "sky.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto exr = skyig::render::readExr((dir_ / "sky.exr").string());
  EXPECT_EQ(exr.image.width, 64);
  EXPECT_EQ(exr.whiteLuminance, 1.0f);
  EXPECT_EQ(std::get<std::string>(exr.attributes.at("skyig:utc")), "2026-06-21T17:00:00.000Z");
  EXPECT_EQ(std::get<std::string>(exr.attributes.at("skyig:channel")), "front");
  EXPECT_EQ(std::get<std::string>(exr.attributes.at("skyig:sky_model")), "preetham");
  EXPECT_TRUE(fs::file_size(dir_ / "sky.png") > 100);
}

// `render --cloud` records the cloud layer with the frame (the EXR header names it; the physical
// sky draws it), and a spec that is not one exits 2 naming the flag.
TEST_F(Cli, ACloudLayerFromTheCommandLineIsRecordedWithTheFrame) {
  const Result r = run("render --sky-model preetham --size 32x24 --cloud stratus:300:400 --exr " + (dir_ / "c.exr").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto exr = skyig::render::readExr((dir_ / "c.exr").string());
  EXPECT_EQ(std::get<std::string>(exr.attributes.at("skyig:cloud_layer_1")), "stratus base 300 m, 400 m thick, 100 % cover, severity 2");
  EXPECT_EQ(std::get<std::string>(exr.attributes.at("skyig:cloud_layer_2")), "off");
  const Result bad = run("render --sky-model preetham --size 32x24 --cloud stratus:300:-5 --exr " + (dir_ / "d.exr").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--cloud"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("thickness"), std::string::npos) << bad.err;
}

// Each of the dome's five EXRs, read back with OpenEXR, names its own channel, offset and
// frustum (not the ownship's yaw five times), stores numbers as float/double/int attributes and
// uses OpenEXR's standard latitude, longitude, altitude, capDate, utcOffset and worldToCamera.
TEST_F(Cli, DomeExrsRecordEachChannelsOwnGeometry) {
  const Result r = run("render --config " + std::string(SKYIG_SOURCE_DIR) +
                       "/config/dome5.toml --sky-model preetham --all-channels --size 16x16 --exr " +
                       (dir_ / "dome.exr").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  struct Expected {
    const char* name;
    double yaw, pitch, left, right, down, up;
  };
  // config/dome5.toml
  const Expected channels[] = {{"left", -60, 0, 30, 30, 20, 30},      {"centre", 0, 0, 30, 30, 20, 30},
                               {"right", 60, 0, 30, 30, 20, 30},      {"chin-left", -25, -45, 25, 15, 20, 20},
                               {"chin-right", 25, -45, 15, 25, 20, 20}};
  for (const Expected& e : channels) {
    SCOPED_TRACE(e.name);
    const auto exr = skyig::render::readExr((dir_ / ("dome_" + std::string(e.name) + ".exr")).string());
    const auto& a = exr.attributes;
    EXPECT_EQ(std::get<std::string>(a.at("skyig:channel")), e.name);
    EXPECT_EQ(std::get<double>(a.at("skyig:channel_yaw_deg")), e.yaw);
    EXPECT_EQ(std::get<double>(a.at("skyig:channel_pitch_deg")), e.pitch);
    EXPECT_EQ(std::get<double>(a.at("skyig:channel_roll_deg")), 0.0);
    EXPECT_EQ(std::get<double>(a.at("skyig:frustum_left_deg")), e.left);
    EXPECT_EQ(std::get<double>(a.at("skyig:frustum_right_deg")), e.right);
    EXPECT_EQ(std::get<double>(a.at("skyig:frustum_down_deg")), e.down);
    EXPECT_EQ(std::get<double>(a.at("skyig:frustum_up_deg")), e.up);
    // The ownship (the configuration's default observer: Innsbruck, heading 180, pitch 5).
    EXPECT_EQ(std::get<double>(a.at("skyig:ownship_yaw_deg")), 180.0);
    EXPECT_EQ(std::get<double>(a.at("skyig:ownship_pitch_deg")), 5.0);
    EXPECT_EQ(std::get<double>(a.at("skyig:latitude_deg")), 47.2603);
    EXPECT_EQ(std::get<float>(a.at("latitude")), 47.2603f);
    EXPECT_EQ(std::get<float>(a.at("longitude")), 11.3439f);
    EXPECT_EQ(std::get<float>(a.at("altitude")), 581.0f);
    EXPECT_EQ(std::get<std::string>(a.at("capDate")), "2026:06:21 17:00:00");
    EXPECT_EQ(std::get<float>(a.at("utcOffset")), 0.0f);
    EXPECT_EQ(std::get<int>(a.at("skyig:cie_type")), 12);
    EXPECT_TRUE(std::holds_alternative<double>(a.at("skyig:sun_altitude_deg")));
    // worldToCamera (row vectors, ENU world): the channel's boresight, the direction at yaw and
    // pitch relative to the ownship's nose (roll 0), maps to the camera's +z; zenith is up.
    const auto& m = std::get<skyig::render::Matrix44f>(a.at("worldToCamera")).m;
    auto toCamera = [&](double e0, double n, double u) {
      std::array<double, 3> c{};
      for (std::size_t j = 0; j < 3; ++j) c[j] = e0 * double{m[0][j]} + n * double{m[1][j]} + u * double{m[2][j]};
      return c;
    };
    // Ownship heading 180 pitch 5, then the channel's yaw and pitch in the body frame: with
    // yaw first, the boresight is the nose direction turned by the channel's yaw in the
    // ownship's (pitched) wing plane, then raised by its pitch. Built here from rotations about
    // the body axes in plain trigonometry (no code of the renderer).
    const double d = std::numbers::pi / 180.0;
    const double cy = std::cos(e.yaw * d), sy = std::sin(e.yaw * d), cp = std::cos(e.pitch * d), sp = std::sin(e.pitch * d);
    const double body[3] = {cp * cy, cp * sy, -sp};  // forward, right, down
    // Body axes of the ownship in ENU for heading 180, pitch 5, roll 0.
    const double p5 = 5.0 * d;
    const double fwd[3] = {0.0, -std::cos(p5), std::sin(p5)}, right[3] = {-1.0, 0.0, 0.0},
                 down[3] = {0.0, -std::sin(p5), -std::cos(p5)};
    double enu[3];
    for (int i = 0; i < 3; ++i) enu[i] = body[0] * fwd[i] + body[1] * right[i] + body[2] * down[i];
    const auto boresight = toCamera(enu[0], enu[1], enu[2]);
    EXPECT_NEAR(boresight[0], 0.0, 1e-6);
    EXPECT_NEAR(boresight[1], 0.0, 1e-6);
    EXPECT_NEAR(boresight[2], 1.0, 1e-6);
    EXPECT_GT(toCamera(0, 0, 1)[1], 0.0);  // the zenith is up in every channel's image
    EXPECT_EQ(m[3][0], 0.0f);              // no translation: the sky is at infinity
    EXPECT_EQ(m[3][3], 1.0f);
  }
}

TEST_F(Cli, AllChannelsWritesOneFilePerChannel) {
  const Result r = run("render --config " + std::string(SKYIG_SOURCE_DIR) +
                       "/config/dome5.toml --all-channels --size 32x32 --png " + (dir_ / "dome.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"left", "centre", "right", "chin-left", "chin-right"})
    EXPECT_TRUE(fs::exists(dir_ / ("dome_" + std::string(name) + ".png"))) << name;
}

TEST_F(Cli, BadFlagValueExitsTwo) {
  const Result r = run("render --lat 100 --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--lat"), std::string::npos) << r.err;
  EXPECT_EQ(imageFiles(), 0u);
}

TEST_F(Cli, UnknownFlagAndMissingOutputExitTwo) {
  EXPECT_EQ(run("render --latitude 10 --png x.png").exitCode, 2);
  const Result r = run("render --lat 10");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--exr PATH and/or --png PATH"), std::string::npos) << r.err;
  const Result size = run("render --size 12x-4 --png " + (dir_ / "x.png").string());
  EXPECT_EQ(size.exitCode, 2);
  EXPECT_NE(size.err.find("--size"), std::string::npos) << size.err;
}

TEST_F(Cli, BadConfigNamesFileLineAndKey) {
  const fs::path cfg = write("bad.toml", "[sky]\nturbidity = 2.0\ncie_type = 22\n");
  const Result r = run("render --config " + cfg.string() + " --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(cfg.string() + ":3: sky.cie_type: expected an integer in [1, 15], got 22"), std::string::npos)
      << r.err;
  EXPECT_EQ(imageFiles(), 0u);
}

TEST_F(Cli, UnwritableOutputExitsTwoAndWritesNothing) {
  const std::string good = (dir_ / "good.exr").string();
  const Result r = run("render --sky-model preetham --exr " + good + " --png /nonexistent-dir/sky.png");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent-dir"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(good));  // checked before rendering: not even the good output
  EXPECT_EQ(imageFiles(), 0u);
}

TEST_F(Cli, UnknownChannelListsTheChannels) {
  const Result r = run("render --config " + std::string(SKYIG_SOURCE_DIR) + "/config/dome5.toml --channel nose --png " +
                       (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("left, centre, right, chin-left, chin-right"), std::string::npos) << r.err;
}

TEST_F(Cli, SunOverrideNeedsBothAngles) {
  const Result r = run("render --sun-azimuth 10 --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--sun-elevation"), std::string::npos) << r.err;
}

TEST_F(Cli, VersionAndCaps) {
  const Result r = run("--version --caps");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("skyig 0."), std::string::npos);
  EXPECT_NE(r.out.find("GL renderer:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("SocketCAN:"), std::string::npos) << r.out;
  // Swap-barrier hardware is reported either way: available, or why not (no X display here
  // unless the tests run under an X server; Mesa offers no GLX_NV_swap_group).
  EXPECT_NE(r.out.find("Swap barrier:  "), std::string::npos) << r.out;
  if (!std::getenv("DISPLAY")) {
    EXPECT_NE(r.out.find("Swap barrier:  unavailable: no X display"), std::string::npos) << r.out;
  }
  // The test programs point skyig at the staged data (tests/staged_data_dir.cpp).
  EXPECT_NE(r.out.find("Data files:    " + std::string(SKYIG_BINARY_DIR) + "/share/skyig (SKYIG_DATA_DIR)\n"), std::string::npos) << r.out;
}

// `skyig probe` on the physical atmosphere, with the small tables the atmosphere tests share
// through the build tree's cache: the clear-sky reference values of Bruneton's 2017 defaults,
// his ground albedo 0.1 included (without it the probe takes the node's, 0.2, as `render` does,
// and the zenith measured 1911 cd/m^2, outside the reference's 10%).
TEST_F(Cli, ProbeReportsTheClearAtmosphere) {
  const std::string cache = std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache";
  const Result r = run("probe --sun-zenith 30 --sun-azimuth 180 --view 0,0 --view 95,180 --irradiance --ground-albedo 0.1 --cache " + cache);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& zenith = j["views"][0];
  EXPECT_NEAR(zenith["sky"]["luminance_cd_m2"].get<double>(), 1700.0, 0.1 * 1700.0);
  EXPECT_NEAR(zenith["transmittance"]["550"].get<double>(), 0.8677, 0.005);
  EXPECT_NEAR(zenith["transmittance"]["440"].get<double>(), 0.7624, 0.005);
  EXPECT_TRUE(zenith["ground"].is_null());
  EXPECT_FALSE(j["views"][1]["ground"].is_null());  // 95 deg from the zenith: the ground
  EXPECT_NEAR(j["irradiance"]["direct_sun_lux"].get<double>(), 115000.0 * std::cos(30.0 * 3.14159265 / 180.0), 0.1 * 100000.0);
}

// With a time and place the probe adds the night's lights to each view, under the keys
// docs/night-sky.md names, and their total (sky, sun, ground and every night light).
TEST_F(Cli, ProbeReportsTheNightLightsAndTheirTotal) {
  const std::string cache = std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache";
  const Result r = run("probe --lat 47.26 --lon 11.34 --alt 2000 --utc 2026-01-18T19:00:00Z --view 0,0 --view 100,0 "
                       "--irradiance --cache " + cache);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["utc"], "2026-01-18T19:00:00.000Z");
  EXPECT_EQ(j["latitude_deg"].get<double>(), 47.26);
  EXPECT_EQ(j["longitude_deg"].get<double>(), 11.34);
  EXPECT_EQ(j["model"], "physical");
  EXPECT_EQ(j["altitude_m"].get<double>(), 2000.0);
  EXPECT_GT(j["sun"]["zenith_deg"].get<double>(), 108.0);  // night
  for (const char* key : {"direct_sun_lux", "sky_lux", "moon_lux", "moonlit_sky_lux"})
    EXPECT_TRUE(j["irradiance"][key].is_number()) << key;
  ASSERT_EQ(j["views"].size(), 2u);
  for (const auto& v : j["views"]) {
    for (const char* day : {"zenith_deg", "azimuth_deg", "sky", "sun", "ground", "transmittance"})
      EXPECT_TRUE(v.contains(day)) << day;
    EXPECT_TRUE(v["sky"].contains("spectral_radiance"));
    double sum[3] = {0.0, 0.0, 0.0};
    for (const char* key : {"sky", "sun", "ground", "moonlit_sky", "moon", "stars_planets", "milky_way", "zodiacal_light",
                            "airglow"}) {
      ASSERT_TRUE(v.contains(key)) << key;
      if (v[key].is_null()) continue;
      for (int k = 0; k < 3; ++k) sum[k] += v[key]["rgb_cd_m2"][k].get<double>();
    }
    EXPECT_EQ(v["sunlit_sky"]["rgb_cd_m2"], v["sky"]["rgb_cd_m2"]);  // one sky, counted once
    EXPECT_FALSE(v["sunlit_sky"].contains("spectral_radiance"));
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(v["total"]["rgb_cd_m2"][k].get<double>(), sum[k], 1e-12 + 1e-9 * std::abs(sum[k]));
    const auto& t = v["total"]["rgb_cd_m2"];
    EXPECT_NEAR(v["total"]["luminance_cd_m2"].get<double>(),
                0.2126 * t[0].get<double>() + 0.7152 * t[1].get<double>() + 0.0722 * t[2].get<double>(), 1e-15);
  }
  EXPECT_TRUE(j["views"][0]["ground"].is_null());
  EXPECT_FALSE(j["views"][1]["ground"].is_null());  // 100 deg from the zenith: the ground
}

TEST_F(Cli, ProbeNeedsASun) {
  const Result r = run("probe --view 0,0");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--sun-zenith and --sun-azimuth"), std::string::npos) << r.err;
  EXPECT_EQ(run("probe --sun-zenith 30 --sun-azimuth 0 --view 0").exitCode, 2);
}

TEST_F(Cli, ServeRejectsAnUnwritableDumpBeforeListening) {
  const fs::path analytic = write("analytic.toml", "[sky]\nmodel = \"preetham\"\n");
  const Result r = run("serve --config " + analytic.string() + " --headless --frames 1 --listen 127.0.0.1:0 --dump-state /nonexistent-dir/states.jsonl");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent-dir"), std::string::npos) << r.err;
  const Result bad = run("serve --config " + analytic.string() + " --headless --frames 1 --listen 127.0.0.1:99999");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("port must be 0..65535"), std::string::npos) << bad.err;
}

namespace {

// Pixels of an EXR brighter than `factor` times its median luminance: the point sources.
int pointSources(const skyig::render::HdrImage& image, double factor) {
  std::vector<double> y;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    y.push_back(0.2126 * double(image.rgba[i]) + 0.7152 * double(image.rgba[i + 1]) + 0.0722 * double(image.rgba[i + 2]));
  std::vector<double> sorted = y;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  return static_cast<int>(std::count_if(y.begin(), y.end(), [&](double v) { return v > factor * median; }));
}

}  // namespace

// The render command loads the bundled catalogue: the zenith of a moonless night over the Alps
// shows dozens of stars; with star_catalogue = "none" only what planets are in view.
TEST_F(Cli, RenderDrawsTheBundledStarCatalogue) {
  const std::string night = "render --sky-model preetham --lat 47.26 --lon 11.34 --utc 2026-11-09T22:00:00Z --pitch 90 --size 200x200 --exr ";
  const Result stars = run(night + (dir_ / "stars.exr").string());
  ASSERT_EQ(stars.exitCode, 0) << stars.err;
  const fs::path none = write("none.toml", "[sky]\nstar_catalogue = \"none\"\n");
  const Result planets = run(night + (dir_ / "planets.exr").string() + " --config " + none.string());
  ASSERT_EQ(planets.exitCode, 0) << planets.err;
  const int withStars = pointSources(skyig::render::readExr((dir_ / "stars.exr").string()).image, 3.0);
  const int without = pointSources(skyig::render::readExr((dir_ / "planets.exr").string()).image, 3.0);
  EXPECT_GT(withStars, 30);
  EXPECT_LT(without, 10);
}

TEST_F(Cli, MissingStarCatalogueNamesTheFile) {
  const fs::path cfg = write("stars.toml", "[sky]\nmodel = \"preetham\"\nstar_catalogue = \"/nonexistent/stars.csv\"\n");
  const Result r = run("render --config " + cfg.string() + " --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("sky.star_catalogue"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/stars.csv"), std::string::npos) << r.err;
  EXPECT_EQ(imageFiles(), 0u);
}

// Without SKYIG_DATA_DIR, build/bin/skyig reads the data files staged in build/share/skyig, as an
// installed /usr/bin/skyig reads /usr/share/skyig: no path of the source tree is compiled in.
TEST_F(Cli, FindsItsDataBesideTheExecutable) {
  const std::string args = "ephemeris --lat 47.26 --lon 11.34 --utc 2026-11-09T22:00:00Z --stars 3";
  const Result r = run(args, "-u SKYIG_DATA_DIR");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["stars"].size(), 3u) << r.out;
  EXPECT_EQ(run("render --sky-model preetham --utc 2026-11-09T22:00:00Z --size 32x32 --png " +
                    (dir_ / "x.png").string(), "-u SKYIG_DATA_DIR").exitCode, 0);
}

// A data file that is not there stops the command with exit code 2, naming the path it tried and
// the variable that chose it.
TEST_F(Cli, AMissingDataFileNamesThePathAndTheVariable) {
  const Result r = run("render --sky-model preetham --png " + (dir_ / "x.png").string(),
                       "SKYIG_DATA_DIR=/nonexistent-skyig-data");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent-skyig-data/bsc5.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("SKYIG_DATA_DIR"), std::string::npos) << r.err;
  EXPECT_EQ(imageFiles(), 0u);
  const Result e = run("ephemeris --lat 0 --lon 0 --utc 2026-11-09T22:00:00Z --stars 3",
                       "SKYIG_DATA_DIR=/nonexistent-skyig-data");
  EXPECT_EQ(e.exitCode, 2);
  EXPECT_NE(e.err.find("/nonexistent-skyig-data/bsc5.csv"), std::string::npos) << e.err;
}

// The probe computes for the configuration's [atmosphere]: five times Bruneton's aerosols
// (mie_extinction 2.22e-5 m^-1 with his 1.2 km scale height) add 4 x 4.44e-6 x 1200 = 0.0213 to
// the vertical optical depth, so the zenith transmittance at 550 nm falls from 0.8677 to
// 0.8677 exp(-0.0213) = 0.8494.
TEST_F(Cli, ProbeUsesTheConfiguredMedium) {
  const std::string cache = std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache";
  const fs::path hazy = write("hazy.toml", "[atmosphere]\nmie_extinction = 2.22e-5\n");
  const Result r = run("probe --config " + hazy.string() + " --tables small --sun-zenith 30 --sun-azimuth 0 --view 0,0 --cache " + cache);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["views"][0]["transmittance"]["550"].get<double>(), 0.8494, 0.002);
  const fs::path bad = write("bad.toml", "[atmosphere]\nmie_phase_g = 2\n");
  const Result refused = run("probe --config " + bad.string() + " --sun-zenith 30 --sun-azimuth 0");
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("atmosphere.mie_phase_g"), std::string::npos) << refused.err;
}

// `render --visibility` hazes the physical sky without editing a configuration: 5 degrees from
// the sun the aerosols' forward scattering (Cornette-Shanks) makes the aureole of a 5 km haze
// far brighter than the clear medium's; a bad value is a usage error.
TEST_F(Cli, RenderVisibilityHazesThePhysicalSky) {
  const fs::path config = write("small.toml", "[sky]\natmosphere_tables = \"small\"\n[[channel]]\nname = \"front\"\n"
                                              "width = 32\nheight = 24\nup = 2\ndown = 2\nleft = 2\nright = 2\n");
  const std::string common = "render --config " + config.string() + " --sun-azimuth 90 --sun-elevation 30 --yaw 90 --pitch 25 --exr ";
  ASSERT_EQ(run(common + (dir_ / "clear.exr").string()).exitCode, 0);
  ASSERT_EQ(run(common + (dir_ / "hazy.exr").string() + " --visibility 5").exitCode, 0);
  auto green = [&](const char* name) {
    return static_cast<double>(skyig::render::readExr((dir_ / name).string()).image.pixel(16, 12)[1]);
  };
  EXPECT_GT(green("hazy.exr"), 1.5 * green("clear.exr"));
  EXPECT_EQ(run(common + (dir_ / "bad.exr").string() + " --visibility 0").exitCode, 2);
}

// Outputs never replace what they name: two outputs naming one file are refused (exit 2,
// nothing written); "-" is standard output; /dev/null is written and stays a device.
TEST_F(Cli, TwoOutputsNamingOneFileExitTwoAndWriteNothing) {
  const std::string x = (dir_ / "x.png").string();
  const Result r = run("render --sky-model preetham --size 32x24 --png " + x + " --exr " + x);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--exr and --png name the same file, " + x), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(x));
}

TEST_F(Cli, RenderWritesAPngToStandardOutputAndItsReportToStderr) {
  const Result r = run("render --sky-model preetham --size 32x24 --png -");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  ASSERT_GE(r.out.size(), 8u);
  EXPECT_EQ(r.out.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_NE(r.err.find("channel front: 32x24"), std::string::npos) << r.err;
}

TEST_F(Cli, RenderToDevNullLeavesTheDevice) {
  const Result r = run("render --sky-model preetham --size 32x24 --exr /dev/null --png /dev/null");
  EXPECT_EQ(r.exitCode, 2) << r.err;  // one file for two outputs
  const Result one = run("render --sky-model preetham --size 32x24 --exr /dev/null");
  EXPECT_EQ(one.exitCode, 0) << one.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// Exit codes of the network commands: a bad output path or configuration is a usage error (2)
// naming the file and line; names resolve.
TEST_F(Cli, RecordToAMissingDirectoryExitsTwo) {
  const Result r = run("record --listen 127.0.0.1:0 --out /nonexistent-dir/r.pcap --duration 1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent-dir"), std::string::npos) << r.err;
}

TEST_F(Cli, BadHostAddressesInTheConfigurationExitTwoWithFileAndLine) {
  const fs::path group = write("group.toml", "[sky]\nmodel = \"preetham\"\n[host]\nmulticast_group = \"10.0.0.1\"\n");
  const Result g = run("serve --config " + group.string() + " --headless --frames 1 --listen 127.0.0.1:0");
  EXPECT_EQ(g.exitCode, 2);
  EXPECT_NE(g.err.find(group.string() + ":4: host.multicast_group: expected an IPv4 multicast address"),
            std::string::npos)
      << g.err;
  const fs::path interface = write("interface.toml", "[sky]\nmodel = \"preetham\"\n[host]\nmulticast_group = \"239.1.2.3\"\n"
                                                    "multicast_interface = \"lo\"\n");
  const Result i = run("serve --config " + interface.string() + " --headless --frames 1 --listen 127.0.0.1:0");
  EXPECT_EQ(i.exitCode, 2);
  EXPECT_NE(i.err.find(interface.string() + ":5: host.multicast_interface: expected the IPv4 address of an interface"),
            std::string::npos)
      << i.err;
  const Result f = run("serve --multicast-interface 127.0.0.1 --headless --frames 1 --listen 127.0.0.1:0");
  EXPECT_EQ(f.exitCode, 2);
  EXPECT_NE(f.err.find("--multicast-interface: expected the IPv4 address of an interface, with host.multicast_group set"),
            std::string::npos)
      << f.err;
  // The host emulator's multicast options need a multicast destination.
  const fs::path path = write("path.csv", "0, 47.26, 11.34, 900, 90, 0, 0\n1, 47.26, 11.34, 900, 90, 0, 0\n");
  const Result h = run("host --path " + path.string() + " --to 127.0.0.1:9 --multicast-interface 127.0.0.1");
  EXPECT_EQ(h.exitCode, 2);
  EXPECT_NE(h.err.find("--multicast-interface: --to 127.0.0.1:9 is not a multicast group"), std::string::npos) << h.err;
  const fs::path port = write("port.toml", "[sky]\nmodel = \"preetham\"\n[host]\nlisten = \"127.0.0.1:99999\"\n");
  for (const std::string& command :
       {"render --size 32x24 --png " + (dir_ / "p.png").string(), std::string("serve --headless --frames 1")}) {
    const Result p = run(command + " --config " + port.string());
    EXPECT_EQ(p.exitCode, 2) << command;
    EXPECT_NE(p.err.find(port.string() + ":4: host.listen: \"127.0.0.1:99999\": port must be 0..65535"),
              std::string::npos)
        << command << ": " << p.err;
  }
}

TEST_F(Cli, ListenAcceptsAHostNameAndNamesOneThatDoesNotResolve) {
  const fs::path analytic =
      write("analytic.toml", "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 32\nheight = 24\n");
  const Result ok = run("serve --config " + analytic.string() + " --headless --frames 1 --listen localhost:0");
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
  EXPECT_NE((ok.out + ok.err).find("listening for CIGI on 127.0.0.1:"), std::string::npos) << ok.out << ok.err;
  const Result bad =
      run("serve --config " + analytic.string() + " --headless --frames 1 --listen no-such-host.invalid:8004");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("cannot resolve \"no-such-host.invalid\""), std::string::npos) << bad.err;
}

// --log-level after the subcommand as well as before; serve says how it started at info.
TEST_F(Cli, LogLevelIsAcceptedAfterTheSubcommand) {
  const fs::path analytic =
      write("analytic.toml", "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 32\nheight = 24\n");
  const Result quiet =
      run("serve --config " + analytic.string() + " --headless --frames 1 --listen 127.0.0.1:0 --log-level warn");
  EXPECT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ((quiet.out + quiet.err).find("listening for CIGI"), std::string::npos) << quiet.out;
  const Result chatty = run("serve --config " + analytic.string() + " --headless --frames 1 --listen 127.0.0.1:0");
  EXPECT_EQ(chatty.exitCode, 0) << chatty.err;
  for (const char* line : {"configuration: ", "listening for CIGI on 127.0.0.1:", "channel front: 32x24", "llvmpipe"})
    EXPECT_NE((chatty.out + chatty.err).find(line), std::string::npos) << line << " in " << chatty.out;
}

// One configuration's tables are one cache file whichever command asks: a render after a probe
// of the same configuration loads the probe's tables instead of precomputing them again.
TEST_F(Cli, RenderAfterProbeOfTheSameConfigurationDoesNotPrecomputeAgain) {
  const fs::path cache = dir_ / "cache";
  const fs::path cfg = write("small.toml", "[sky]\natmosphere_tables = \"small\"\natmosphere_cache = \"" +
                                               cache.string() + "\"\n[atmosphere]\nvisibility_km = 30.0\n");
  const Result probe = run("probe --config " + cfg.string() + " --sun-zenith 30 --sun-azimuth 0 --view 0,0");
  ASSERT_EQ(probe.exitCode, 0) << probe.err;
  EXPECT_NE(probe.err.find("physical sky: precomputing"), std::string::npos) << probe.err;  // a fresh cache
  const Result render = run("render --config " + cfg.string() + " --size 32x24 --png " + (dir_ / "x.png").string());
  ASSERT_EQ(render.exitCode, 0) << render.err;
  EXPECT_EQ(render.err.find("physical sky: precomputing"), std::string::npos) << render.err;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(cache)) files += entry.path().extension() == ".skyatm";
  EXPECT_EQ(files, 1);
}

// `skyig precompute` leaves the configuration's tables and its visibility steps in the cache, so a
// node's first start has them: the steps it lacks are built (small tables on llvmpipe: seconds),
// those it has are kept, and a second run builds nothing.
TEST_F(Cli, PrecomputeBuildsTheMissingVisibilitySteps) {
  const fs::path shared = fs::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache" / "visibility-blend-node";
  const fs::path cache = dir_ / "cache";
  fs::create_directories(cache / "visibility-steps");
  // Seeded with the configuration's tables the node test (host_atmosphere_test.cpp) left in the
  // shared cache, if it ran; the steps are this test's own.
  if (fs::is_directory(shared))
    for (const auto& entry : fs::directory_iterator(shared))
      if (entry.path().extension() == ".skyatm") fs::copy_file(entry.path(), cache / entry.path().filename());
  const fs::path cfg = write("node.toml", "[sky]\natmosphere_tables = \"small\"\natmosphere_cache = \"" + cache.string() +
                                              "\"\natmosphere_visibility_steps = [20, 50]\n");
  const Result first = run("precompute --config " + cfg.string());
  ASSERT_EQ(first.exitCode, 0) << first.err;
  EXPECT_NE(first.out.find(" failed"), std::string::npos) << first.out;
  int steps = 0;
  for (const auto& entry : fs::directory_iterator(cache / "visibility-steps")) steps += entry.path().extension() == ".skyatm";
  EXPECT_EQ(steps, 2);
  for (const auto& entry : fs::directory_iterator(cache / "visibility-steps"))
    if (entry.path().extension() == ".skyatm") {  // one step's tables (not a lock file)
      fs::remove(entry.path());
      break;
    }
  const Result second = run("precompute --config " + cfg.string());
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_NE(second.out.find("1 steps built, 0 failed"), std::string::npos) << second.out;
  const Result third = run("precompute --config " + cfg.string());
  EXPECT_NE(third.out.find("0 steps built, 0 failed"), std::string::npos) << third.out;
  const Result bad = run("precompute --config " + write("bad.toml", "[sky]\natmosphere_visibility_steps = [5, 5000]\n").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("atmosphere_visibility_steps"), std::string::npos) << bad.err;
}

// A table cache that cannot be written, a full disk (a 16 KiB tmpfs) or a read-only one,
// mounted in a private mount namespace of the command alone (so nothing outside the test
// sees it): `serve` and `render` run on the tables they computed and say so once, no
// temporary file is left behind, and `precompute`, whose output is the cache, exits 3.
TEST_F(Cli, AFullOrReadOnlyCacheIsRunOnNotFatal) {
  if (::geteuid() != 0 || std::system("unshare --mount true 2>/dev/null") != 0)
    GTEST_SKIP() << "a private mount namespace needs root (CI runs as root)";
  for (const std::string options : {"size=16k", "ro"}) {
    const fs::path cache = dir_ / ("cache-" + options.substr(0, 4));
    fs::create_directories(cache);
    const fs::path cfg = write("node.toml", "[sky]\natmosphere_tables = \"small\"\natmosphere_cache = \"" +
                                                cache.string() + "\"\natmosphere_visibility_steps = []\n");
    // The command in the namespace, then what the cache holds, before the namespace goes.
    auto inNamespace = [&](const std::string& args) {
      const fs::path script = write("run.sh", "mount -t tmpfs -o " + options + " skyig-test " + cache.string() + "\n" +
                                                  SKYIG_EXECUTABLE + " " + args + " >" + (dir_ / "out.txt").string() +
                                                  " 2>" + (dir_ / "err.txt").string() + "\necho $? >" +
                                                  (dir_ / "rc.txt").string() + "\nls -a " + cache.string() + " >" +
                                                  (dir_ / "ls.txt").string() + "\n");
      EXPECT_EQ(std::system(("unshare --mount --propagation private sh " + script.string()).c_str()), 0);
      return std::make_pair(std::stoi(slurp(dir_ / "rc.txt")), slurp(dir_ / "err.txt"));
    };
    const auto [serveRc, serveErr] =
        inNamespace("serve --config " + cfg.string() + " --headless --frames 3 --listen 127.0.0.1:0");
    EXPECT_EQ(serveRc, 0) << options << ": " << serveErr;
    EXPECT_NE(serveErr.find("not cached, running on them"), std::string::npos) << serveErr;
    EXPECT_EQ(serveErr.find("precomputed the small tables", serveErr.find("precomputed the small tables") + 1),
              std::string::npos)
        << "computed twice: " << serveErr;
    EXPECT_EQ(slurp(dir_ / "ls.txt").find(".tmp"), std::string::npos) << slurp(dir_ / "ls.txt");
    const auto [precomputeRc, precomputeErr] = inNamespace("precompute --config " + cfg.string());
    EXPECT_EQ(precomputeRc, 3) << options << ": " << precomputeErr;
    EXPECT_NE(precomputeErr.find("could not be written"), std::string::npos) << precomputeErr;
    EXPECT_EQ(slurp(dir_ / "ls.txt").find(".tmp"), std::string::npos) << slurp(dir_ / "ls.txt");
  }
}

// A configuration is read with a bound: /dev/zero (which never ends) is refused at once.
TEST_F(Cli, EndlessConfigurationIsRefusedWithABound) {
  const auto start = std::chrono::steady_clock::now();
  const Result r = run("render --sky-model preetham --config /dev/zero --size 16x16 --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/dev/zero: the configuration file is larger than 1 MiB"), std::string::npos) << r.err;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// A size the renderer cannot allocate is refused when it is given, not when the target fails.
TEST_F(Cli, OversizedChannelIsRefusedAtValidation) {
  const Result r = run("render --sky-model preetham --size 16384x16384 --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("each in 16..8192"), std::string::npos) << r.err;
  const fs::path config = write("big.toml", "[[channel]]\nwidth = 16384\n");
  const Result c = run("render --sky-model preetham --config " + config.string() + " --png " + (dir_ / "x.png").string());
  EXPECT_EQ(c.exitCode, 2);
  EXPECT_NE(c.err.find("channel[0].width: expected an integer in [16, 8192]"), std::string::npos) << c.err;
}

// A year the ephemeris cannot serve is the observer's time at fault, and says its range.
TEST_F(Cli, YearOutsideTheEphemerisNamesTheTimeNotTheCatalogue) {
  for (const char* year : {"1000", "3000"}) {
    const Result r = run("render --sky-model preetham --utc " + std::string(year) + "-06-21T12:00:00Z --size 16x16 --png " +
                         (dir_ / "x.png").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("observer's time"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("1900-2100 range of the ephemeris"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("star_catalogue"), std::string::npos) << r.err;
  }
}

// `probe` and `render` of one configuration read one table file and one ground albedo: after
// `render` has precomputed the tables into a fresh cache, `probe --config` loads them (no second
// precompute), and the ground it reports 30 degrees below the horizon, sky in-scatter plus the
// reflected ground, is the rendered pixel's luminance. The configuration's albedo 0.3 (not the
// medium's default 0.1 nor the sky's 0.2) makes the ground half as bright again as 0.2 would, so
// a probe with another albedo misses the 5% it is held to by far.
TEST_F(Cli, ProbeAndRenderShareTheTablesAndTheGroundAlbedo) {
  const fs::path cache = dir_ / "cache";
  const fs::path config = write("small.toml", "[sky]\natmosphere_tables = \"small\"\nground_albedo = 0.3\n"
                                              "atmosphere_cache = \"" + cache.string() + "\"\n[[channel]]\nname = \"front\"\n"
                                              "width = 33\nheight = 25\nup = 2\ndown = 2\nleft = 2\nright = 2\n");
  const Result rendered = run("render --config " + config.string() + " --alt 500 --sun-azimuth 180 --sun-elevation 30 "
                              "--yaw 0 --pitch -30 --exr " + (dir_ / "ground.exr").string());
  ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
  ASSERT_NE(rendered.err.find("precomputed"), std::string::npos) << "a fresh cache: the render precomputes";
  const Result probed = run("probe --config " + config.string() + " --alt 500 --sun-zenith 60 --sun-azimuth 180 --view 120,0");
  ASSERT_EQ(probed.exitCode, 0) << probed.err;
  EXPECT_EQ(probed.err.find("precomputed"), std::string::npos) << probed.err;
  const auto j = nlohmann::json::parse(probed.out);
  const auto& view = j["views"][0];
  ASSERT_FALSE(view["ground"].is_null());
  const double probe = view["sky"]["luminance_cd_m2"].get<double>() + view["ground"]["luminance_cd_m2"].get<double>();
  const auto image = skyig::render::readExr((dir_ / "ground.exr").string()).image;
  const auto rgb = image.pixel(16, 12);
  const double render = 0.2126 * double{rgb[0]} + 0.7152 * double{rgb[1]} + 0.0722 * double{rgb[2]};
  std::printf("ground 30 deg down: render %.1f cd/m^2, probe %.1f cd/m^2\n", render, probe);
  EXPECT_NEAR(render, probe, 0.05 * probe);
}

// Below the tables' 10 km the node draws the rest of the haze as a layer over them; the probe's
// through_layers is that composition on the CPU (sky/client_light.h), the frame's on the GPU from
// the sky pass's table: at a visibility of 2 km, 500 m up, the ground 30 degrees down and the sky
// 5 degrees up agree within 5%, where the tables' own figures miss the layer by far.
TEST_F(Cli, ProbeBelowTenKilometresComposesTheHazeAsTheFrameDoes) {
  const fs::path cache = dir_ / "cache";
  const fs::path config = write("haze.toml", "[sky]\natmosphere_tables = \"small\"\nground_albedo = 0.3\n"
                                             "atmosphere_cache = \"" + cache.string() + "\"\n[[channel]]\nname = \"front\"\n"
                                             "width = 33\nheight = 25\nup = 2\ndown = 2\nleft = 2\nright = 2\n");
  struct View {
    double pitchDeg;
    const char* probeView;
  };
  for (const View& v : {View{-30.0, "120,0"}, View{5.0, "85,0"}}) {
    SCOPED_TRACE(v.probeView);
    const Result rendered = run("render --config " + config.string() + " --visibility 2 --alt 500 --sun-azimuth 180 "
                                "--sun-elevation 30 --yaw 0 --pitch " + std::to_string(v.pitchDeg) + " --exr " +
                                (dir_ / "haze.exr").string());
    ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
    const Result probed = run("probe --config " + config.string() + " --visibility 2 --alt 500 --sun-zenith 60 "
                              "--sun-azimuth 180 --view " + v.probeView);
    ASSERT_EQ(probed.exitCode, 0) << probed.err;
    EXPECT_NE(probed.err.find("through_layers adds the haze layer"), std::string::npos) << probed.err;
    const auto view = nlohmann::json::parse(probed.out)["views"][0];
    ASSERT_TRUE(view.contains("through_layers")) << probed.out;
    const double layered = view["through_layers"]["luminance_cd_m2"].get<double>();
    const double tables = view["sky"]["luminance_cd_m2"].get<double>() +
                          (view["ground"].is_null() ? 0.0 : view["ground"]["luminance_cd_m2"].get<double>());
    const auto image = skyig::render::readExr((dir_ / "haze.exr").string()).image;
    const auto rgb = image.pixel(16, 12);
    const double render = 0.2126 * double{rgb[0]} + 0.7152 * double{rgb[1]} + 0.0722 * double{rgb[2]};
    std::printf("2 km haze, pitch %+.0f deg: render %.1f, probe through the layers %.1f, the tables alone %.1f cd/m^2\n",
                v.pitchDeg, render, layered, tables);
    EXPECT_NEAR(render, layered, 0.05 * layered);
    EXPECT_GT(std::abs(tables - render), 0.1 * render);  // the layer matters: the tables alone would not do
  }
}

// A channel with a [channel.projector]: `render --projector` writes the image sent to the
// projector and the light it adds, at the projector's resolution (the channel's size defaults
// to it), the EXR naming the calibration.
TEST_F(Cli, RenderProjectorWritesWhatTheProjectorIsSent) {
  const fs::path cfg = write("dome.toml", "[[channel]]\nname = \"p1\"\n[channel.projector]\nmpcdi = \"" +
                                              std::string(SKYIG_SOURCE_DIR) +
                                              "/tests/data/calibration/warp_absolute.mpcdi\"\nregion = \"p1\"\n");
  const Result r = run("render --config " + cfg.string() + " --sky-model preetham --projector --exr " +
                       (dir_ / "p.exr").string() + " --png " + (dir_ / "p.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("projector p1: 64x40"), std::string::npos) << r.out;
  const auto exr = skyig::render::readExr((dir_ / "p.exr").string());
  EXPECT_EQ(exr.image.width, 64);
  EXPECT_EQ(exr.image.height, 40);
  EXPECT_NE(std::get<std::string>(exr.attributes.at("skyig:projector")).find("warp_absolute.mpcdi"), std::string::npos);
  EXPECT_EQ(std::get<int>(exr.attributes.at("skyig:projector_width")), 64);
  EXPECT_TRUE(fs::file_size(dir_ / "p.png") > 100);
  // Without --projector: the channel's own (unwarped) frame, at the projector's size.
  const Result plain = run("render --config " + cfg.string() + " --sky-model preetham --exr " + (dir_ / "c.exr").string());
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(skyig::render::readExr((dir_ / "c.exr").string()).image.width, 64);
  EXPECT_EQ(skyig::render::readExr((dir_ / "c.exr").string()).attributes.count("skyig:projector"), 0u);
  // --size with --projector: the outputs stay the projector's, and the command says so.
  const Result sized = run("render --config " + cfg.string() + " --sky-model preetham --projector --size 32x20 --exr " +
                           (dir_ / "s.exr").string());
  ASSERT_EQ(sized.exitCode, 0) << sized.err;
  EXPECT_EQ(skyig::render::readExr((dir_ / "s.exr").string()).image.width, 64);
  EXPECT_NE(sized.err.find("--size 32x20 sets the channel image each projector's warp reads"), std::string::npos)
      << sized.err;
}

// Every MPCDI profile as VESA's reference library writes it renders for its projector, and the
// EXR's camera is the one the file gives: the region's frustum for 3d and sl (the second of
// three sl regions too), the channel's own for 2d, and for an a3 region without a frustum the
// camera made to cover its points.
TEST_F(Cli, EveryReferenceLibraryProfileRendersThroughItsRegionsCamera) {
  struct Case {
    const char* file;
    const char* region;
    double yawDeg, leftDeg;  // the EXR's channel yaw and left half-angle
  };
  for (const Case& k : {Case{"sdk_2d.mpcdi", "r1", 0.0, 30.0}, Case{"sdk_3d.mpcdi", "r1", 10.0, 30.0},
                        Case{"sdk_sl.mpcdi", "r1", 10.0, 30.0}, Case{"sdk_sl_three.mpcdi", "r2", 10.0, 30.0},
                        Case{"sdk_a3.mpcdi", "r1", 8.0, 26.7}}) {
    SCOPED_TRACE(k.file);
    const fs::path cfg = write("sdk.toml", std::string("[[channel]]\nname = \"p\"\n[channel.projector]\nmpcdi = \"") +
                                               SKYIG_SOURCE_DIR + "/tests/data/calibration/" + k.file +
                                               "\"\nregion = \"" + k.region + "\"\nwarp_values = \"absolute\"\n");
    const Result r = run("render --config " + cfg.string() + " --sky-model preetham --projector --exr " +
                         (dir_ / "p.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto exr = skyig::render::readExr((dir_ / "p.exr").string());
    EXPECT_EQ(exr.image.width, 64);
    EXPECT_NEAR(std::get<double>(exr.attributes.at("skyig:channel_yaw_deg")), k.yawDeg, 0.01);
    EXPECT_NEAR(std::get<double>(exr.attributes.at("skyig:frustum_left_deg")), k.leftDeg, 0.01);
  }
}

// The example configuration of a projector dome works as its comment says: `skyig dome` writes
// the calibration beside it, and every one of its five channels renders for its projector.
TEST_F(Cli, TheProjectorDomeExampleRendersWithAGeneratedDome) {
  fs::copy_file(std::string(SKYIG_SOURCE_DIR) + "/config/dome5-projectors.toml", dir_ / "dome5-projectors.toml");
  const Result dome = run("dome --out " + (dir_ / "dome5.mpcdi").string() + " --resolution 64x40 --warp-step 8");
  ASSERT_EQ(dome.exitCode, 0) << dome.err;
  const Result r = run("render --config " + (dir_ / "dome5-projectors.toml").string() +
                       " --sky-model preetham --all-channels --projector --png " + (dir_ / "p.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"left", "centre", "right", "chin-left", "chin-right"}) {
    EXPECT_NE(r.out.find(std::string("projector ") + name + ": 64x40"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir_ / (std::string("p_") + name + ".png"))) << name;
  }
}

// A bad calibration stops the command with exit 2 before anything renders: the message names
// the file and what is wrong in it, and no image is written.
TEST_F(Cli, BadCalibrationExitsTwoNamingTheFileBeforeRendering) {
  const std::string mpcdi = std::string(SKYIG_SOURCE_DIR) + "/tests/data/calibration/warp_absolute.mpcdi";
  const fs::path region = write("region.toml", "[[channel]]\nname = \"p1\"\n[channel.projector]\nmpcdi = \"" + mpcdi +
                                                   "\"\nregion = \"p9\"\n");
  const Result r = run("render --config " + region.string() + " --sky-model preetham --projector --png " +
                       (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(mpcdi), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\"p9\""), std::string::npos) << r.err;
  const fs::path mesh = write("short.mesh", "2\n3 2\n-1 -1 0 0 1\n0 -1 0.5 0 1\n");
  const fs::path truncated = write("mesh.toml", "[[channel]]\nname = \"m\"\nwidth = 32\nheight = 32\n"
                                                "[channel.projector]\nbourke_mesh = \"short.mesh\"\n");
  const Result m = run("render --config " + truncated.string() + " --sky-model preetham --projector --png " +
                       (dir_ / "y.png").string());
  EXPECT_EQ(m.exitCode, 2);
  EXPECT_NE(m.err.find(mesh.string()), std::string::npos) << m.err;
  // Missing file.
  const fs::path missing = write("missing.toml", "[[channel]]\nname = \"m\"\n[channel.projector]\nmpcdi = \"nowhere.mpcdi\"\n"
                                                 "region = \"p1\"\n");
  const Result n = run("render --config " + missing.string() + " --sky-model preetham --png " + (dir_ / "z.png").string());
  EXPECT_EQ(n.exitCode, 2);
  EXPECT_NE(n.err.find((dir_ / "nowhere.mpcdi").string()), std::string::npos) << n.err;
  // The node reads its projectors before it draws a frame: the same file stops `serve` with 2.
  const fs::path node = write("node.toml", "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"p1\"\n[channel.projector]\nmpcdi = \"" +
                                              mpcdi + "\"\nregion = \"p9\"\n");
  const Result served = run("serve --config " + node.string() + " --headless --listen 127.0.0.1:0 --frames 1");
  EXPECT_EQ(served.exitCode, 2) << served.err;
  EXPECT_NE(served.err.find("\"p9\""), std::string::npos) << served.err;
  EXPECT_EQ(imageFiles(), 1u);  // the mesh file only: no image
}

TEST_F(Cli, ProjectorFlagNeedsAProjectorChannel) {
  const Result r = run("render --sky-model preetham --projector --png " + (dir_ / "x.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("front have no [channel.projector]"), std::string::npos) << r.err;
  EXPECT_EQ(imageFiles(), 0u);
}
