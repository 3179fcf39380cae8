// What the display shows, measured on `skyig render`'s own PNG and EXR (the histogram operator,
// the default): the cues a pilot needs survive the mapping. Figures: docs/tone-reproduction.md.
#include "render/image_io.h"
#include "physics/physics.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <png.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

constexpr double kDisplayMax = 100.0, kDisplayAmbient = 0.1, kGamma = 2.2;  // DisplayParams' defaults

struct Frame {
  int width = 0, height = 0;
  std::vector<unsigned char> png;  // RGB
  skyig::render::HdrImage exr;

  glm::dvec3 code(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    return {png[i], png[i + 1], png[i + 2]};
  }
  // Eq. 18 inverted: the display's linear Rec.709 light for a pixel's codes.
  glm::dvec3 displayed(int x, int y) const {
    const glm::dvec3 n = code(x, y) / 255.0;
    return kDisplayAmbient + kDisplayMax * glm::pow(n, glm::dvec3(kGamma));
  }
  glm::dvec3 world(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
    return {exr.rgba[i], exr.rgba[i + 1], exr.rgba[i + 2]};
  }
};

double luminance(const glm::dvec3& rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

// Hue as the angle of the chromaticity around D65's white (x 0.3127, y 0.3290), degrees: a
// colour desaturated towards white along its hue keeps it.
double hueDeg(const glm::dvec3& rec709) {
  const glm::dvec3 xyz = skyig::shader::rec709ToXyz(rec709);
  const double s = xyz.x + xyz.y + xyz.z;
  return std::atan2(xyz.y / s - 0.3290, xyz.x / s - 0.3127) * 180.0 / std::numbers::pi;
}

class DisplayLook : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("skyig_display_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // A 160x120 channel looking level, 10 deg below and 35 deg above the boresight, on the small
  // physical-sky tables with the eye adapted at once; `channels` replaces the channel.
  fs::path config(const std::string& channels = "") const {
    const fs::path path = dir_ / "c.toml";
    std::ofstream(path) << "[sky]\natmosphere_tables = \"small\"\n[eye]\nadaptation = \"instant\"\n"
                        << (channels.empty() ? "[[channel]]\nname = \"c\"\nwidth = 160\nheight = 120\nleft = 30\n"
                                               "right = 30\ndown = 10\nup = 35\n"
                                             : channels);
    return path;
  }

  int run(const std::string& args) const {
    const std::string command = "XDG_CACHE_HOME=" + std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache " +
                                std::string(SKYIG_EXECUTABLE) + " render " + args + " >" + (dir_ / "out.txt").string() +
                                " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // What the last run printed (stdout and stderr), for a failure's message.
  std::string said() const {
    std::stringstream words;
    words << std::ifstream(dir_ / "out.txt").rdbuf();
    return words.str();
  }

  Frame read(const std::string& stem) const {
    Frame f;
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    const std::string png = (dir_ / (stem + ".png")).string();
    EXPECT_TRUE(png_image_begin_read_from_file(&image, png.c_str())) << png;
    image.format = PNG_FORMAT_RGB;
    f.width = static_cast<int>(image.width);
    f.height = static_cast<int>(image.height);
    f.png.resize(PNG_IMAGE_SIZE(image));
    EXPECT_TRUE(png_image_finish_read(&image, nullptr, f.png.data(), 0, nullptr));
    f.exr = skyig::render::readExr((dir_ / (stem + ".exr")).string()).image;
    return f;
  }

  Frame render(const std::string& scene) {
    const int code = run("--config " + config().string() + " " + scene + " --png " + (dir_ / "f.png").string() +
                         " --exr " + (dir_ / "f.exr").string());
    EXPECT_EQ(code, 0) << scene << "; skyig said:\n" << said();
    return read("f");
  }

  // The row (from the top) where the horizon crosses a level channel of `down`/`up` degrees
  // pitched by `pitchDeg`.
  static double horizonRow(double pitchDeg, double downDeg, double upDeg, int height) {
    const double t = std::tan(-pitchDeg * std::numbers::pi / 180.0), top = std::tan(upDeg * std::numbers::pi / 180.0),
                 bottom = std::tan(downDeg * std::numbers::pi / 180.0);
    return (top - t) / (top + bottom) * height;
  }

  fs::path dir_;
};

}  // namespace

// Under a full moon, looking along the moonlit horizon (the moon 90 deg to the left), the sky
// just above the horizon and the terrain just below must differ on the display by more than the
// eye's threshold at the display's luminance (Weber contrast against the threshold-versus-
// intensity function of Ward Larson et al. 1997, eq. 7): the horizon is the night's first cue.
TEST_F(DisplayLook, FullMoonHorizonStaysVisible) {
  const Frame f = render("--utc 2026-12-25T17:40:00Z --yaw 150 --pitch 2");
  const double row = horizonRow(2.0, 10.0, 35.0, f.height);
  double sky = 0.0, ground = 0.0, skyWorld = 0.0, groundWorld = 0.0;
  for (int x = 0; x < f.width; ++x) {
    sky += luminance(f.displayed(x, static_cast<int>(row) - 4));
    ground += luminance(f.displayed(x, static_cast<int>(row) + 4));
    skyWorld += luminance(f.world(x, static_cast<int>(row) - 4));
    groundWorld += luminance(f.world(x, static_cast<int>(row) + 4));
  }
  sky /= f.width;
  ground /= f.width;
  ASSERT_GT(skyWorld, groundWorld) << "the moonlit sky is brighter than the terrain in the world";
  const double weber = (sky - ground) / ground;
  const double threshold = skyig::shader::thresholdLuminance(ground) / ground;
  std::cout << "full moon: display sky " << sky << " cd/m^2, terrain " << ground << " cd/m^2, Weber contrast " << weber
            << ", threshold " << threshold << " (world " << skyWorld / f.width << " / " << groundWorld / f.width << ")\n";
  EXPECT_GT(weber, 3.0 * threshold);
}

// At noon looking away from the sun, the pale band along the horizon keeps its hue on the
// display within a few degrees of the EXR's (no channel clips alone: no cyan fringe).
TEST_F(DisplayLook, NoonHorizonKeepsItsHue) {
  const Frame f = render("--utc 2026-06-21T11:00:00Z --yaw 0");
  const double row = horizonRow(5.0, 10.0, 35.0, f.height);  // the default pitch is 5 deg
  int checked = 0;
  for (int dy = 2; dy <= 10; dy += 2) {
    const int y = static_cast<int>(row) - dy;
    glm::dvec3 world(0.0), shown(0.0);
    for (int x = 0; x < f.width; ++x) {
      world += f.world(x, y);
      shown += f.displayed(x, y) - kDisplayAmbient;
    }
    const double dHue = std::remainder(hueDeg(shown) - hueDeg(world), 360.0);
    EXPECT_LT(std::abs(dHue), 4.0) << "row " << y << ": world hue " << hueDeg(world) << ", shown " << hueDeg(shown);
    ++checked;
  }
  EXPECT_EQ(checked, 5);
}

// At 12 km looking 2 deg down, the sunlit terrain and haze below the horizon are not clipped:
// no value of the terrain reaches the display's white.
TEST_F(DisplayLook, TerrainFromTwelveKilometresIsNotClipped) {
  const Frame f = render("--utc 2026-06-21T11:00:00Z --yaw 0 --alt 12000 --pitch -2");
  // From 12 km the horizon is 3.5 deg below level; the terrain is everything below that.
  const int first = static_cast<int>(horizonRow(-2.0 + 3.6, 10.0, 35.0, f.height)) + 2;
  ASSERT_LT(first, f.height - 5);
  int clipped = 0, values = 0;
  for (int y = first; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x)
      for (int k = 0; k < 3; ++k, ++values) clipped += f.code(x, y)[k] >= 255.0;
  EXPECT_EQ(clipped, 0) << "of " << values << " terrain values";
}

// No Inf or NaN, and no negative light (beyond the gamut's edge), in any EXR or display frame across day, twilight,
// night, haze and space.
TEST_F(DisplayLook, EveryFrameIsFiniteFromDayToSpace) {
  const char* scenes[] = {
      "--utc 2026-06-21T11:00:00Z --yaw 180 --pitch 40",       // the sun in view
      "--sun-azimuth 300 --sun-elevation 0.2 --yaw 300",       // the setting sun
      "--sun-azimuth 300 --sun-elevation 5 --yaw 300 --visibility 2",  // haze, the sun's aureole
      "--sun-azimuth 300 --sun-elevation -9 --yaw 300",
      "--utc 2026-12-09T22:00:00Z --yaw 180 --pitch 30",       // a moonless night
      "--utc 2026-12-25T17:40:00Z --yaw 60 --pitch 2",         // the full moon rising
      "--utc 2026-06-21T11:00:00Z --yaw 180 --alt 90000",      // the edge of space
  };
  for (const char* scene : scenes) {
    const Frame f = render(scene);
    std::size_t bad = 0;
    std::string first;
    for (std::size_t i = 0; i < f.exr.rgba.size(); ++i) {
      // A saturated red just outside the Rec.709 gamut may have a blue a hair below zero; more
      // than 1% of the pixel's brightest channel below zero is wrong light.
      const float v = f.exr.rgba[i];
      const std::size_t p = i / 4 * 4;
      const float top = std::max({f.exr.rgba[p], f.exr.rgba[p + 1], f.exr.rgba[p + 2]});
      if (std::isfinite(v) && v >= -0.01f * top) continue;
      if (bad++ == 0)
        first = "pixel (" + std::to_string(i / 4 % f.width) + ", " + std::to_string(i / 4 / f.width) + ") channel " +
                std::to_string(i % 4) + " = " + std::to_string(v);
    }
    EXPECT_EQ(bad, 0u) << scene << ": first " << first;
    EXPECT_EQ(f.png.size(), static_cast<std::size_t>(f.width) * f.height * 3) << scene;
  }
}

// Two channels sharing an edge map alike (one curve per state, not per channel's pixels): at
// their common edge, in the twilight glow that crosses it, they differ by at most 2 codes on
// average; and under broken cumulus, whose field is fixed to the ground (not to a channel), the
// same.
TEST_F(DisplayLook, ChannelsSharingAnEdgeMatchThere) {
  const std::string channels =
      "[[channel]]\nname = \"a\"\nwidth = 160\nheight = 120\nleft = 30\nright = 30\ndown = 10\nup = 35\n"
      "[[channel]]\nname = \"b\"\nyaw = 60.0\nwidth = 160\nheight = 120\nleft = 30\nright = 30\ndown = 10\nup = 35\n";
  for (const char* scene : {"--sun-azimuth 30 --sun-elevation -4", "--utc 2026-06-21T10:00:00Z --alt 2 --cloud cumulus:1200:800:50"}) {
    ASSERT_EQ(run("--config " + config(channels).string() + " " + scene + " --yaw 0 --all-channels --png " +
                  (dir_ / "e.png").string() + " --exr " + (dir_ / "e.exr").string()),
              0) << said();
    const Frame a = read("e_a"), b = read("e_b");
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
      for (int k = 0; k < 3; ++k) sum += std::abs(a.code(a.width - 1, y)[k] - b.code(0, y)[k]);
    const double mean = sum / (3.0 * a.height);
    std::cout << scene << ": shared edge mean difference " << mean << " codes\n";
    EXPECT_LE(mean, 2.0) << scene;
  }
}

// A stratus deck topped at 700 m seen from 3 km, the sun 15 deg up in the west: the deck towards
// the sun is brighter than away from it (the droplets' forward scattering, a sea of cloud's glare
// under a low sun), and its brightest pixel is in the channel's middle third, under the sun.
TEST_F(DisplayLook, SeaOfCloudShinesTowardsTheSun) {
  const std::string scene = "--sun-azimuth 270 --sun-elevation 15 --alt 3000 --pitch -12 --cloud stratus:300:400:100 ";
  const Frame toward = render(scene + "--yaw 270"), away = render(scene + "--yaw 90");
  // The deck fills the rows below the horizon of its top (1.5 deg down): the lower half.
  auto deck = [](const Frame& f, int& brightestColumn) {
    double sum = 0.0, best = -1.0;
    for (int y = f.height / 2; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        const double l = luminance(f.world(x, y));
        sum += l;
        if (l > best) best = l, brightestColumn = x;
      }
    return sum / (f.width * (f.height - f.height / 2));
  };
  int column = -1, ignored = -1;
  const double lit = deck(toward, column), shaded = deck(away, ignored);
  std::printf("sea of cloud from 3 km, sun 15 deg: %.0f cd/m^2 towards the sun, %.0f away; brightest at column %d of %d\n",
              lit, shaded, column, toward.width);
  EXPECT_GT(lit, 1.3 * shaded);
  EXPECT_GT(column, toward.width / 3);
  EXPECT_LT(column, 2 * toward.width / 3);
}

// An altostratus deck at 3 km, the sun set a degree ago: towards the sun it shines on the base
// from below (it is under the base's own horizon there, and above the earth's limb seen from
// 3 km) through the long path of air that reddens it, so the base there is redder than the base
// away from the sun (lit by the blue sky through the deck alone).
TEST_F(DisplayLook, SunsetLightsADecksBaseRedTowardsTheSun) {
  const std::string scene = "--sun-azimuth 300 --sun-elevation -1 --alt 2 --pitch 12 --cloud altostratus:3000:800:100 ";
  const Frame toward = render(scene + "--yaw 300"), away = render(scene + "--yaw 120");
  auto redness = [](const Frame& f) {
    glm::dvec3 sum(0.0);
    const int horizon = static_cast<int>(horizonRow(12.0, 10.0, 35.0, f.height));
    for (int y = 0; y < horizon - 4; ++y)
      for (int x = 0; x < f.width; ++x) sum += f.world(x, y);
    return sum.r / sum.b;
  };
  const double r = redness(toward), a = redness(away);
  std::printf("sunset under altostratus: base red/blue %.2f towards the sun, %.2f away\n", r, a);
  EXPECT_GT(r, 1.2 * a);
}

// The same sunset base towards the sun, against the light `skyig probe` says reaches it: what the
// base adds towards the sun over away from it (the diffuse light of the deck and the air, about
// alike both ways, taken out) is the sunlight the droplets scatter forward to the eye, the sun
// 7-21 deg behind the base, so its colour is that sunlight's as the eye gets it: the sun's own at
// the base times the air's between the base and the eye. Each from the probe's disc (the sun put
// in the view, its radiance after the transmittance to the top of the air): from 3 km with the sun
// at its local zenith there, and along the eye's view from the eye and from where it meets the
// base (their ratio is the segment between, taken channel by channel). Rows 6-20 deg up in the
// sun's azimuth: chromaticity x, y within 0.05 of the probe's (measured 0.033 at most; a grey base
// would be 0.27 off in x). Found by it: the face's light table clamped the deep red sunlight's
// negative Rec.709 blue to 0, a bluer base (0.05 off).
TEST_F(DisplayLook, SunsetBaseHasTheColourOfTheSunlightTheProbeSaysReachesIt) {
  const std::string scene = "--sun-azimuth 300 --sun-elevation -1 --alt 2 --pitch 12 --cloud altostratus:3000:800:100 ";
  const Frame f = render(scene + "--yaw 300"), away = render(scene + "--yaw 120");
  // The probe's disc colour (linear Rec.709, cd/m^2) from altM with the sun at zenithDeg, azimuth
  // 300, viewed at its centre.
  auto sunSeen = [&](double altM, double zenithDeg) {
    const fs::path out = dir_ / "probe.json";
    char args[160];
    std::snprintf(args, sizeof args, " probe --tables small --alt %.3f --sun-zenith %.6f --sun-azimuth 300 --view %.6f,300",
                  altM, zenithDeg, zenithDeg);
    const std::string command = "XDG_CACHE_HOME=" + std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache " +
                                std::string(SKYIG_EXECUTABLE) + args + " >" + out.string() + " 2>/dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(out), nullptr, false);
    const auto& sun = j["views"][0]["sun"];
    EXPECT_TRUE(sun.is_object()) << "no disc from " << altM << " m at zenith " << zenithDeg << " deg";
    return sun.is_object() ? glm::dvec3(sun["rgb_cd_m2"][0], sun["rgb_cd_m2"][1], sun["rgb_cd_m2"][2]) : glm::dvec3(1.0);
  };
  constexpr double kR = 6360e3, kEye = 2.0, kBase = 3000.0, kDeg = std::numbers::pi / 180.0;
  const double top = std::tan(35.0 * kDeg), bottom = std::tan(10.0 * kDeg);
  double worst = 0.0;
  for (double elevation : {6.0, 10.0, 15.0, 20.0}) {
    // The row whose centre looks `elevation` up (the channel pitched 12 deg), the two columns
    // either side of the sun's azimuth.
    const int y = static_cast<int>(std::lround((top - std::tan((elevation - 12.0) * kDeg)) / (top + bottom) * f.height - 0.5));
    const double e = 12.0 + std::atan(top - (y + 0.5) / f.height * (top + bottom)) / kDeg;
    const glm::dvec3 base = 0.5 * (f.world(f.width / 2 - 1, y) + f.world(f.width / 2, y)) -
                            0.5 * (away.world(f.width / 2 - 1, y) + away.world(f.width / 2, y));
    // Where the view meets the base: d along it, gamma round the earth from the eye.
    const double r = kR + kEye, mu = std::sin(e * kDeg), rb = kR + kBase;
    const double d = -r * mu + std::sqrt(r * r * mu * mu + rb * rb - r * r);
    const double gamma = std::atan2(d * std::cos(e * kDeg), r + d * mu) / kDeg;
    const glm::dvec3 sunAtBase = sunSeen(kBase, 91.0 - gamma);
    const glm::dvec3 segment = sunSeen(kEye, 90.0 - e) / sunSeen(kBase, 90.0 - e - gamma);
    const glm::dvec3 expected = sunAtBase * segment;
    auto xy = [](const glm::dvec3& rgb) {
      const glm::dvec3 c = skyig::shader::rec709ToXyz(rgb);
      return glm::dvec2(c.x, c.y) / (c.x + c.y + c.z);
    };
    const glm::dvec2 a = xy(base), b = xy(expected), sb = xy(sunAtBase);
    std::printf("sunset base %.1f deg up (%.1f km off): towards the sun over away x, y %.4f, %.4f; the probe's "
                "sunlight there %.4f, %.4f (the sun's at the base %.4f, %.4f)\n", e, d / 1000.0, a.x, a.y, b.x, b.y, sb.x, sb.y);
    worst = std::max({worst, std::abs(a.x - b.x), std::abs(a.y - b.y)});
  }
  std::printf("the base's chromaticity at most %.4f off the probe's sunlight\n", worst);
  EXPECT_LT(worst, 0.05);
}

// A 200 m ground fog of 400 m visibility (render --fog-*), the sun 30 deg up behind the pilot's
// left shoulder (Innsbruck, 2026-06-21T09:00Z, looking west): inside it at 30 m the frame is
// grey-white (no channel 30% from the others: the droplets are grey, and sunlight of about 5500 K
// is that much redder than the D65 white of linear Rec.709), brighter up than down; from 500 m
// above, blue sky over a sunlit white sea; climbing through the top, 10 cm in a frame (6 m/s at
// 60 Hz), the frame's mean light changes by under 2%.
TEST_F(DisplayLook, InsideAboveAndThroughAGroundFog) {
  const std::string scene = "--utc 2026-06-21T09:00:00Z --yaw 270 --fog-visibility 0.4 --fog-top 200 ";
  auto mean = [](const Frame& f, int y0, int y1) {
    glm::dvec3 m(0.0);
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < f.width; ++x) m += f.world(x, y);
    return m / double((y1 - y0) * f.width);
  };
  const Frame inside = render(scene + "--alt 30 --pitch 0");
  const glm::dvec3 up = mean(inside, 0, inside.height / 4), down = mean(inside, 3 * inside.height / 4, inside.height);
  for (const glm::dvec3& c : {up, down}) {
    const double lo = std::min({c.r, c.g, c.b}), hi = std::max({c.r, c.g, c.b});
    EXPECT_LT(hi / lo, 1.3) << "inside the fog: " << c.r << ", " << c.g << ", " << c.b;
  }
  EXPECT_GT(luminance(up), luminance(down));
  const Frame above = render(scene + "--alt 500 --pitch 0");
  const double row = horizonRow(0.0, 10.0, 35.0, above.height);
  const glm::dvec3 sky = mean(above, 0, above.height / 4);
  const glm::dvec3 sea = mean(above, static_cast<int>(row) + 4, above.height);
  EXPECT_GT(sky.b, 1.3 * sky.r) << "the sky above the fog is blue";
  EXPECT_LT(std::max({sea.r, sea.g, sea.b}) / std::min({sea.r, sea.g, sea.b}), 1.3) << "the sea is white";
  EXPECT_GT(luminance(sea), 5000.0) << "a sunlit white sea";
  const double below = luminance(mean(render(scene + "--alt 199.95 --pitch 0"), 0, 120));
  const double over = luminance(mean(render(scene + "--alt 200.05 --pitch 0"), 0, 120));
  std::printf("fog 200 m of 400 m: inside up %.0f down %.0f cd/m^2; from 500 m sky (%.0f, %.0f, %.0f) sea %.0f; "
              "climbing through the top %.0f -> %.0f cd/m^2\n",
              luminance(up), luminance(down), sky.r, sky.g, sky.b, luminance(sea), below, over);
  EXPECT_NEAR(over / below, 1.0, 0.02);
}

// Precipitation and dust from the ground to 1500 m (render --precipitation), the same morning
// from 30 m: heavy rain (severity 3, 10 mm/h, 2.5 km) greys the frame like fog (no channel 30%
// from the others); a dust storm (severity 2, 1 km) turns it brown, red over blue by more than a
// clear sky's ground does (the particles absorb blue, Dubovik et al. 2002), the same in the
// display's PNG codes; a layer of 0% coverage changes nothing.
TEST_F(DisplayLook, RainGreysAndDustBrownsTheFrame) {
  const std::string scene = "--utc 2026-06-21T09:00:00Z --yaw 270 --alt 30 --pitch 0 ";
  auto mean = [](const Frame& f) {
    glm::dvec3 m(0.0);
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) m += f.world(x, y);
    return m / double(f.height * f.width);
  };
  auto meanCode = [](const Frame& f) {
    glm::dvec3 m(0.0);
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) m += f.code(x, y);
    return m / double(f.height * f.width);
  };
  const Frame clear = render(scene);
  const Frame rain = render(scene + "--precipitation rain --precipitation-severity 3");
  const Frame dust = render(scene + "--precipitation dust --precipitation-severity 2");
  const Frame none = render(scene + "--precipitation dust --precipitation-coverage 0");
  const glm::dvec3 r = mean(rain), d = mean(dust), c = mean(clear);
  EXPECT_LT(std::max({r.r, r.g, r.b}) / std::min({r.r, r.g, r.b}), 1.3) << "rain is grey: " << r.r << ", " << r.g << ", " << r.b;
  EXPECT_GT(d.r / d.b, 1.25 * (c.r / c.b)) << "dust is brown";
  EXPECT_GT(d.r, d.g);
  EXPECT_GT(d.g, d.b);
  const glm::dvec3 dc = meanCode(dust), rc = meanCode(rain);
  EXPECT_GT(dc.r - dc.b, 10.0) << "on the display too";
  EXPECT_LT(std::abs(rc.r - rc.b), 15.0);
  EXPECT_EQ(mean(none), c);
  std::printf("30 m, rain severity 3: (%.0f, %.0f, %.0f) cd/m^2, codes (%.0f, %.0f, %.0f); dust severity 2: "
              "(%.0f, %.0f, %.0f) cd/m^2, codes (%.0f, %.0f, %.0f)\n",
              r.r, r.g, r.b, rc.r, rc.g, rc.b, d.r, d.g, d.b, dc.r, dc.g, dc.b);
}

// Looking at the noon sun through a full stratus deck: no disc (the clear sky's frame has it at
// over a million cd/m^2); the deck's brightest pixel is within twice its mean.
TEST_F(DisplayLook, NoSunDiscThroughAnOvercast) {
  const std::string scene = "--utc 2026-06-21T10:00:00Z --yaw 141 --pitch 50 --alt 2 ";
  auto brightest = [](const Frame& f, double& mean) {
    double best = 0.0, sum = 0.0;
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        const double l = luminance(f.world(x, y));
        best = std::max(best, l);
        sum += l;
      }
    mean = sum / (f.width * f.height);
    return best;
  };
  double clearMean = 0.0, overcastMean = 0.0;
  const double clear = brightest(render(scene), clearMean);
  const double overcast = brightest(render(scene + "--cloud stratus:300:400:100"), overcastMean);
  std::printf("towards the noon sun: brightest %.3g cd/m^2 clear, %.3g under the deck (mean %.3g)\n", clear, overcast,
              overcastMean);
  EXPECT_GT(clear, 1e6);
  EXPECT_LT(overcast, 2.0 * overcastMean);
}
