// Golden images of the look: the scenes a change of the sky, the eye or the display mapping
// touches (noon, sunset, the sun 4, 9 and 15 deg down, a full moon rising, a moonless winter
// night, 12 km looking 2 deg down, haze and fog, cloud decks, and three of them through
// night-vision goggles),
// rendered by `skyig render` at 96x60 and compared with the
// PNGs in tests/data/golden/ so that a reviewer sees a change of look as a failing test and a
// changed PNG.
//
// Tolerances: llvmpipe on another CPU or Mesa build may round differently, and the dither is a
// hash of the pixel, so exact bytes are not expected. A scene matches when its values differ by
// at most 1.5 codes on average and 99% of them by at most 6 codes (a star moved by a pixel
// changes a few values by many codes; a change of look moves most of them).
//
// To accept a new look: SKYIG_UPDATE_GOLDEN=1 ctest -R GoldenLook, then look at the PNGs
// (docs/images/look/ has the same scenes larger, docs/look.md says how they were made) before
// committing them.
#include <gtest/gtest.h>
#include <png.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct Scene {
  const char* name;
  const char* args;
};

// Innsbruck (the defaults), looking towards the sun or the moon.
const Scene kScenes[] = {
    {"noon", "--utc 2026-06-21T11:00:00Z --yaw 180"},
    {"sunset", "--sun-azimuth 300 --sun-elevation 0.3 --yaw 300"},
    {"sun_minus_4", "--sun-azimuth 300 --sun-elevation -4 --yaw 300"},
    {"sun_minus_9", "--sun-azimuth 300 --sun-elevation -9 --yaw 300"},
    {"sun_minus_15", "--sun-azimuth 300 --sun-elevation -15 --yaw 300"},
    {"full_moon_rising", "--utc 2026-12-25T17:40:00Z --yaw 60 --pitch 2"},
    {"moonless_winter_night", "--utc 2026-12-09T22:00:00Z --yaw 180 --pitch 30"},
    {"noon_12km_2deg_down", "--utc 2026-06-21T11:00:00Z --yaw 180 --alt 12000 --pitch -2"},
    // Low visibility (physics/weather): a 1 km haze from 600 m, and a 200 m ground fog of 400 m
    // visibility from inside it at 30 m and from 500 m above it.
    {"haze_1km", "--utc 2026-06-21T14:00:00Z --yaw 270 --alt 600 --pitch 3 --visibility 1"},
    {"fog_inside", "--utc 2026-06-21T09:00:00Z --yaw 270 --alt 30 --fog-visibility 0.4 --fog-top 200"},
    {"fog_above", "--utc 2026-06-21T09:00:00Z --yaw 270 --alt 500 --pitch -5 --fog-visibility 0.4 --fog-top 200"},
    // Cloud decks (physics/weather/cloud_deck.h): a full stratus deck 300-700 m from under it and
    // from 3 km above it (the sea of cloud), broken cumulus at 40 %, an altostratus deck at
    // sunset, and a broken stratocumulus under the full moon, seen by the eye and through a class A
    // goggle.
    {"overcast_below", "--utc 2026-06-21T10:00:00Z --yaw 180 --alt 2 --pitch 20 --cloud stratus:300:400:100"},
    {"sea_of_cloud", "--utc 2026-06-21T10:00:00Z --yaw 140 --alt 3000 --pitch -5 --cloud stratus:300:400:100"},
    {"broken_cumulus", "--utc 2026-06-21T10:00:00Z --yaw 140 --alt 2 --pitch 20 --cloud cumulus:1200:800:40"},
    {"sunset_deck", "--sun-azimuth 300 --sun-elevation -1 --yaw 300 --alt 2 --pitch 10 --cloud altostratus:3000:800:100"},
    {"goggle_under_cloud", "--utc 2026-12-25T17:40:00Z --yaw 60 --pitch 15 --alt 2 --goggle A --cloud stratocumulus:1500:500:60"},
    // The full moon 64 deg up in a gap of a broken stratocumulus deck (50 %), its cloud lit by it.
    {"moonlit_broken_deck", "--utc 2026-12-24T23:00:00Z --yaw 150 --pitch 25 --alt 2 --cloud stratocumulus:1500:500:50"},
    // Night-vision goggles (class A, P43; class B, P45): the moon with its halo, and the
    // moonless night's stars and airglow through the tube's noise (its hash is the frame's
    // instant: the same on every run).
    {"goggle_full_moon_rising", "--utc 2026-12-25T17:40:00Z --yaw 60 --pitch 2 --goggle A"},
    {"goggle_moonless_winter_night", "--utc 2026-12-09T22:00:00Z --yaw 180 --pitch 30 --goggle B --phosphor P45"},
};

struct Rgb {
  int width = 0, height = 0;
  std::vector<unsigned char> values;
};

Rgb readPng(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return {};
  image.format = PNG_FORMAT_RGB;
  Rgb out{static_cast<int>(image.width), static_cast<int>(image.height), std::vector<unsigned char>(PNG_IMAGE_SIZE(image))};
  if (!png_image_finish_read(&image, nullptr, out.values.data(), 0, nullptr)) return {};
  return out;
}

fs::path goldenDir() { return fs::path(SKYIG_SOURCE_DIR) / "tests" / "data" / "golden"; }

int render(const Scene& scene, const fs::path& png) {
  const std::string command = "XDG_CACHE_HOME=" + std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache " +
                              std::string(SKYIG_EXECUTABLE) + " render --config " + (goldenDir() / "look.toml").string() +
                              " " + scene.args + " --png " + png.string() + " >/dev/null 2>" + png.string() + ".err";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class GoldenLook : public ::testing::TestWithParam<Scene> {};

}  // namespace

TEST_P(GoldenLook, SceneLooksAsReviewed) {
  const Scene& scene = GetParam();
  const fs::path dir = fs::temp_directory_path() / ("skyig_golden_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path rendered = dir / (std::string(scene.name) + ".png");
  ASSERT_EQ(render(scene, rendered), 0) << "skyig render " << scene.args;
  const fs::path golden = goldenDir() / (std::string(scene.name) + ".png");
  if (std::getenv("SKYIG_UPDATE_GOLDEN")) {
    fs::copy_file(rendered, golden, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "updated " << golden;
  }
  const Rgb a = readPng(rendered), b = readPng(golden);
  ASSERT_FALSE(b.values.empty()) << golden << " is missing or unreadable";
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  double sum = 0.0;
  std::size_t within = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const int d = std::abs(int(a.values[i]) - int(b.values[i]));
    sum += d;
    within += d <= 6;
  }
  const double mean = sum / double(a.values.size()), share = double(within) / double(a.values.size());
  EXPECT_LE(mean, 1.5) << scene.name << ": mean difference " << mean << " codes (rendered: " << rendered << ")";
  EXPECT_GE(share, 0.99) << scene.name << ": " << 100.0 * share << "% of values within 6 codes";
  if (!HasFailure()) fs::remove_all(dir);  // kept, with the render and its log, when it differs
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenLook, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<Scene>& p) { return std::string(p.param.name); });
