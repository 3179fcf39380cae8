// skyig::Sky as a host uses it (docs/library.md): only <skyig/sky.h> and <skyig/gl_sky.h>, and
// the skyig executable's own output to compare with.
#include <skyig/gl_sky.h>
#include <skyig/sky.h>

#include "examples/terrain_host/terrain_host.h"
#include "tests/library/library_test_support.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using skyig::testing::smallPhysicalSky;

skyig::Observer at(int hour, int minute, double heightM = 0.0) {
  return skyig::testing::innsbruckAt(hour, minute, heightM);
}

// `skyig ARGS` (the build's executable) -> its JSON on stdout.
nlohmann::json skyigJson(const std::string& args) {
  const std::string command = std::string(SKYIG_EXECUTABLE) + " " + args + " 2>/dev/null";
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) return nullptr;
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  if (::pclose(p) != 0) return nullptr;
  return nlohmann::json::parse(out, nullptr, false);
}

}  // namespace

// The sun's illuminance a host gets is `skyig probe --irradiance`'s direct sun (the same
// transmittance and solar spectrum), and the sky's ambient on a horizontal surface, integrated
// over skyig's sky radiance, agrees with the probe's sky irradiance from Bruneton's irradiance
// table (two independent computations of one quantity).
TEST(SkyLibrary, SunAndSkyLightAreTheProbesIrradiance) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(11, 0, 10.0), 0.0);  // 10 m above the ground: the probe's --alt
  const skyig::Light light = sky.light();
  const nlohmann::json probe =
      skyigJson("probe --irradiance --tables small --alt 10 --lat 47.2603 --lon 11.3439 --utc 2026-06-21T11:00:00Z");
  ASSERT_TRUE(probe.is_object());
  const double probeSun = probe["irradiance"]["direct_sun_lux"].get<double>();
  const double probeSky = probe["irradiance"]["sky_lux"].get<double>();
  std::printf("sun %.1f lux (probe %.1f), sky ambient %.1f lux (probe %.1f)\n", light.sun.horizontalLux, probeSun,
              light.ambientHorizontalLux, probeSky);
  EXPECT_NEAR(light.sun.horizontalLux / probeSun, 1.0, 1e-9);
  EXPECT_NEAR(light.ambientHorizontalLux / probeSky, 1.0, 0.03);
}

// `skyig probe --light` prints what the library gives a host: the command is a client of the
// same API, so the figures are equal to the last digit.
TEST(SkyLibrary, ProbeLightIsTheLibrarysLight) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(18, 50), 0.0);
  const skyig::Light light = sky.light();
  const nlohmann::json probe =
      skyigJson("probe --light --tables small --lat 47.2603 --lon 11.3439 --utc 2026-06-21T18:50:00Z");
  ASSERT_TRUE(probe.is_object());
  const nlohmann::json& l = probe["light"];
  EXPECT_DOUBLE_EQ(l["sun"]["horizontal_lux"].get<double>(), light.sun.horizontalLux);
  EXPECT_DOUBLE_EQ(l["moon"]["normal_lux"].get<double>(), light.moon.normalLux);
  EXPECT_DOUBLE_EQ(l["ambient_horizontal_lux"].get<double>(), light.ambientHorizontalLux);
  EXPECT_DOUBLE_EQ(l["sky_sh_rec709_cd_m2"][4][1].get<double>(), light.skySh[4][1]);
  EXPECT_DOUBLE_EQ(l["adaptation_cd_m2"].get<double>(), light.adaptationLuminance);
  EXPECT_GT(light.sun.direction[2], 0.0);  // 20:50 CEST, the sun low above the horizon
  EXPECT_LT(light.sun.direction[2], 0.1);
}

// A value the sky cannot use is refused with its name and value, and the last good frame stays.
TEST(SkyLibrary, BadObserverIsRefusedAndTheLastFrameKept) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(11, 0), 0.0);
  const double before = sky.light().sun.horizontalLux;
  skyig::Observer bad = at(11, 0);
  bad.latitudeDeg = std::nan("");
  try {
    sky.update(bad, 1.0);
    FAIL() << "a NaN latitude was accepted";
  } catch (const skyig::Error& e) {
    EXPECT_NE(std::string(e.what()).find("latitudeDeg = nan"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sky.update(at(11, 0), std::nan("")), skyig::Error);
  skyig::Observer month13 = at(11, 0);
  month13.utc.month = 13;
  EXPECT_THROW(sky.update(month13, 2.0), skyig::Error);
  EXPECT_EQ(sky.light().sun.horizontalLux, before);
}

// The calls a host can get wrong are refused with skyig::Error, naming the value: a Sky used
// after it was moved from, a non-finite aerial-perspective offset, a visibility below 10 m or
// negative, a zero normal, a height outside the range the sky state takes (the same range in
// the message the state's own check would give).
TEST(SkyLibrary, MisusedCallsThrowErrorsNotCrashes) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(11, 0), 0.0);
  for (const double x : {std::nan(""), HUGE_VAL})
    EXPECT_THROW(sky.aerialPerspective({x, 1000.0, 0.0}), skyig::Error);
  EXPECT_GT(sky.aerialPerspective({0.0, 1000.0, 0.0}).transmittance[1], 0.5);  // 1 km of clear air
  for (const double km : {-1.0, 1e-9, 0.005, HUGE_VAL}) {
    skyig::Weather w;
    w.visibilityKm = km;
    EXPECT_THROW(sky.update(at(11, 0), 1.0, w), skyig::Error) << km;
  }
  skyig::Observer deep = at(11, 0);
  deep.heightM = -700.0;
  try {
    sky.update(deep, 1.0);
    FAIL() << "a height of -700 m was accepted";
  } catch (const skyig::Error& e) {
    EXPECT_NE(std::string(e.what()).find("above -500 m"), std::string::npos) << e.what();
  }
  const skyig::Light light = sky.light();
  EXPECT_THROW(skyig::irradianceFromSh(light, {0.0, 0.0, 0.0}), skyig::Error);
  EXPECT_THROW(skyig::irradianceFromSh(light, {std::nan(""), 0.0, 1.0}), skyig::Error);
  // Any length: the normal is normalised.
  const skyig::Vec3 up = skyig::irradianceFromSh(light, {0.0, 0.0, 1.0});
  const skyig::Vec3 longUp = skyig::irradianceFromSh(light, {0.0, 0.0, 5.0});
  EXPECT_NEAR(longUp[1], up[1], 1e-9 * up[1]);

  skyig::Sky moved(std::move(sky));
  EXPECT_GT(moved.light().sun.horizontalLux, 10000.0);
  EXPECT_THROW((void)sky.light(), skyig::Error);  // NOLINT(bugprone-use-after-move): the test
  EXPECT_THROW(sky.update(at(11, 0), 2.0), skyig::Error);
  EXPECT_THROW((void)sky.aerialPerspective({0.0, 1000.0, 0.0}), skyig::Error);
}

// The pilot's eye adapts on the host's clock: nine minutes of dusk in a tenth of a second of
// host time leave the eye far above the darker scene's level (the level an eye adapted at once
// has); ten minutes of host time later it has come down to it.
TEST(SkyLibrary, TheEyeAdaptsOnTheHostsClock) {
  skyig::Sky adapted(smallPhysicalSky(/*temporal=*/false));
  adapted.update(at(19, 19), 0.0);
  const double target = adapted.light().adaptationLuminance;

  skyig::Sky eye(smallPhysicalSky(/*temporal=*/true));
  eye.update(at(19, 10), 0.0);
  eye.update(at(19, 19), 0.1);
  const double lagging = eye.light().adaptationLuminance;
  eye.update(at(19, 19), 600.0);
  const double later = eye.light().adaptationLuminance;
  std::printf("adapted at once %.4g cd/m^2; the eye after 0.1 s %.4g, after 600 s %.4g\n", target, lagging, later);
  EXPECT_GT(lagging / target, 1.2);
  EXPECT_NEAR(later / target, 1.0, 0.05);
}

TEST(SkyLibrary, AerialPerspectiveNeedsThePhysicalSky) {
  skyig::Settings s = smallPhysicalSky();
  s.model = "preetham";
  skyig::Sky sky(s);
  sky.update(at(11, 0), 0.0);
  EXPECT_GT(sky.light().sun.horizontalLux, 10000.0);
  EXPECT_THROW(sky.aerialPerspective({0.0, 1000.0, 0.0}), skyig::Error);
  s.model = "no such sky";
  EXPECT_THROW(skyig::Sky{s}, skyig::Error);
}

// The texture path: the sky a host composites itself is the sky SkyDraw draws into the host's
// framebuffer, pixel for pixel (linear light).
TEST(SkyLibrary, TextureIsTheSkyTheDrawShows) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(17, 0), 0.0);
  terrain_host::HeadlessContext context;
  terrain_host::Options o;
  o.width = 48;
  o.height = 32;
  o.terrainRadiusM = 1.0;  // no terrain to speak of: a sky frame
  o.pitchDeg = 20.0;
  const terrain_host::Frame frame = terrain_host::drawFrame(sky, o, terrain_host::HeadlessContext::procAddress());

  ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(terrain_host::HeadlessContext::procAddress())));
  skyig::SkyDraw draw(terrain_host::HeadlessContext::procAddress());
  // The same camera as the frame's.
  const terrain_host::Mat4 view = terrain_host::viewMatrix(o.yawDeg, o.pitchDeg);
  const terrain_host::Mat4 projection =
      terrain_host::projectionMatrix(o.horizontalFovDeg, double(o.width) / o.height, 10.0, 1.0e6, o.depth);
  const unsigned texture = draw.texture(sky, view.data(), projection.data(), o.width, o.height, skyig::Output::LinearLight);
  ASSERT_NE(texture, 0u);
  std::vector<float> rgba(static_cast<std::size_t>(o.width * o.height * 4));
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)), rgba.data());
  double worst = 0.0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(o.width * o.height); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const double a = rgba[i * 4 + c], b = frame.final[i * 3 + c];
      worst = std::max(worst, std::abs(a - b) / std::max(b, 1e-6));
    }
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(frame.final[(16 * 48 + 24) * 3 + 2], 100.0f);  // a blue afternoon sky, cd/m^2
}

// SkyDraw::prepare draws the day's lights and weathers into skyig's own targets first: the frame
// after it is the frame an unprepared SkyDraw shows, to the bit, and the host's framebuffer
// binding is as it was.
TEST(SkyLibrary, APreparedDrawShowsTheSameFrame) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(17, 0), 0.0);
  terrain_host::HeadlessContext context;
  ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(terrain_host::HeadlessContext::procAddress())));
  const int w = 48, h = 32;
  const terrain_host::Mat4 view = terrain_host::viewMatrix(250.0, 10.0);
  const terrain_host::Mat4 projection = terrain_host::projectionMatrix(60.0, double(w) / h, 10.0, 1.0e6, skyig::DepthConvention::Standard);
  auto frame = [&](skyig::SkyDraw& draw) {
    std::vector<float> rgba(static_cast<std::size_t>(w * h * 4));
    const unsigned texture = draw.texture(sky, view.data(), projection.data(), w, h, skyig::Output::LinearLight);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)), rgba.data());
    return rgba;
  };
  skyig::SkyDraw plain(terrain_host::HeadlessContext::procAddress());
  const std::vector<float> unprepared = frame(plain);
  skyig::SkyDraw prepared(terrain_host::HeadlessContext::procAddress());
  GLint framebufferBefore = -1, framebufferAfter = -2;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebufferBefore);
  prepared.prepare(sky, view.data(), projection.data(), skyig::Viewport{0, 0, w, h});
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebufferAfter);
  EXPECT_EQ(framebufferAfter, framebufferBefore);
  EXPECT_EQ(frame(prepared), unprepared);
  EXPECT_THROW(prepared.prepare(sky, nullptr, projection.data(), skyig::Viewport{0, 0, w, h}), skyig::Error);
}

// Fog of 100, 200 and 300 m (below the tables' lowest visibility: a fog layer over the 10 km
// tables, no table build): every update is usable, the light finite, and the eye adapts to a
// grey-white world. (Before the optical-depth tables a 0.3 km visibility threw on 572 of 600
// updates: "adaptation gain -nan".)
TEST(SkyLibrary, DenseFogUpdatesAreAllUsable) {
  skyig::Sky sky(smallPhysicalSky(true));
  double t = 0.0;
  for (const double km : {0.1, 0.2, 0.3}) {
    skyig::Weather w;
    w.visibilityKm = km;
    for (int i = 0; i < 60; ++i, t += 0.05) {
      ASSERT_NO_THROW(sky.update(at(11, 0, 600.0), t, w)) << km << " km, update " << i;
      const skyig::Light l = sky.light();
      ASSERT_TRUE(std::isfinite(l.adaptationLuminance) && l.adaptationLuminance > 0.0) << km;
      ASSERT_TRUE(std::isfinite(l.adaptationGain) && l.adaptationGain > 0.0) << km;
      ASSERT_TRUE(std::isfinite(l.sun.normalLux) && std::isfinite(l.ambientHorizontalLux)) << km;
    }
  }
}

// Koschmieder in the library's aerial perspective: at a visibility of 400 m (a fog layer over the
// 10 km tables) a black target 400 m away, level, shows the contrast 0.02 against the fog's
// horizon behind it (the in-scatter of a level path 20 km long, as dense as the horizon gets);
// and the sun reaching the host's terrain is dimmed through the fog.
// The same with an OPAC aerosol type over the tables: the fog is water droplets in both, as
// bright (within a third) as over Bruneton's aerosol.
double expectKoschmiederInFog(const skyig::Settings& settings) {
  skyig::Sky sky(settings);
  const skyig::Light clear = (sky.update(at(11, 0, 100.0), 0.0), sky.light());
  skyig::Weather fog;
  fog.visibilityKm = 0.4;
  sky.update(at(11, 0, 100.0), 1.0, fog);
  auto y = [](const skyig::Vec3& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
  const double target = y(sky.aerialPerspective({0.0, 400.0, 0.0}).inScattered);
  const double horizon = y(sky.aerialPerspective({0.0, 20000.0, 0.0}).inScattered);
  const double contrast = 1.0 - target / horizon;
  std::printf("fog of 400 m: black target at 400 m %.0f cd/m^2 against the horizon %.0f: contrast %.4f; "
              "sun on the terrain %.0f lux (clear %.0f)\n",
              target, horizon, contrast, sky.light().sun.horizontalLux, clear.sun.horizontalLux);
  EXPECT_NEAR(contrast, 0.02, 0.004);
  EXPECT_LT(sky.light().sun.horizontalLux, 0.01 * clear.sun.horizontalLux);  // 1.2 km of it overhead
  return horizon;
}

TEST(SkyLibrary, AerialPerspectiveInFogKeepsKoschmiedersContrast) { expectKoschmiederInFog(smallPhysicalSky()); }

TEST(SkyLibrary, AerialPerspectiveInFogOfAnOpacAerosolKeepsKoschmiedersContrast) {
  const std::string path = std::string(SKYIG_BINARY_DIR) + "/opac-fog-test.toml";
  std::ofstream(path) << "[atmosphere]\naerosol_type = \"continental_average\"\n";
  skyig::Settings settings = smallPhysicalSky();
  settings.configFile = path;
  const double opac = expectKoschmiederInFog(settings);
  const double bruneton = expectKoschmiederInFog(smallPhysicalSky());
  EXPECT_NEAR(opac / bruneton, 1.0, 0.33);
}

// A host's cloud layers through the library (Sky::setClouds): under a full stratus deck the sun
// is gone from the light and from every terrain point; under 50 % broken cumulus the terrain's
// share in the clouds' shade (sunThroughClouds under a half) is about half, on a 200 m grid
// 8 km square; a type the sky does not know is refused naming the layer, the last layers kept.
TEST(SkyLibrary, CloudLayersShadeTheSunAndTheTerrain) {
  skyig::Sky sky(smallPhysicalSky());
  sky.update(at(11, 0, 10.0), 0.0);
  const double clear = sky.light().sun.horizontalLux;
  EXPECT_DOUBLE_EQ(sky.sunThroughClouds({0.0, 0.0, 0.0}), 1.0);
  std::array<skyig::CloudLayer, 3> layers{};
  layers[0].enabled = true;
  layers[0].type = "stratus";
  layers[0].baseM = 300.0;
  layers[0].thicknessM = 400.0;
  sky.setClouds(layers);
  sky.update(at(11, 0, 10.0), 1.0);
  EXPECT_LT(sky.light().sun.horizontalLux, 1e-6 * clear);
  EXPECT_LT(sky.sunThroughClouds({1000.0, -2000.0, 0.0}), 1e-6);
  layers[0].type = "cumulus";
  layers[0].baseM = 1200.0;
  layers[0].thicknessM = 800.0;
  layers[0].coveragePct = 50.0;
  sky.setClouds(layers);
  sky.update(at(11, 0, 10.0), 2.0);
  int shaded = 0, all = 0;
  for (double x = -4000.0; x <= 4000.0; x += 200.0)
    for (double y = -4000.0; y <= 4000.0; y += 200.0, ++all) shaded += sky.sunThroughClouds({x, y, 0.0}) < 0.5 ? 1 : 0;
  std::printf("broken cumulus 50 %%: %.1f %% of the terrain in the clouds' shade\n", 100.0 * shaded / all);
  EXPECT_NEAR(100.0 * shaded / all, 50.0, 15.0);
  const double here = sky.sunThroughClouds({300.0, 700.0, 0.0});
  layers[1] = layers[0];
  layers[1].type = "fog bank";
  try {
    sky.setClouds(layers);
    ADD_FAILURE() << "an unknown cloud type was taken";
  } catch (const skyig::Error& e) {
    EXPECT_NE(std::string(e.what()).find("layer 2"), std::string::npos) << e.what();
  }
  sky.update(at(11, 0, 10.0), 2.0);
  EXPECT_EQ(sky.sunThroughClouds({300.0, 700.0, 0.0}), here);  // the cumulus kept
  EXPECT_EQ(sky.sunThroughClouds({0.0, 0.0, 5000.0}), 1.0);    // above the layer
}

// A layer's severity reaches the library: a full cirrus veil's optical depth along the sun's ray
// at severity 5 is 6 times that at severity 0 (the water content's factor, physics/weather/
// cloud_deck.h), so the sun gets through as T0^6; a severity beyond 5 is refused.
TEST(SkyLibrary, ACloudLayersSeverityThickensItsVeil) {
  skyig::Sky sky(smallPhysicalSky());
  std::array<skyig::CloudLayer, 3> layers{};
  layers[0].enabled = true;
  layers[0].type = "cirrostratus";
  layers[0].baseM = 8000.0;
  layers[0].thicknessM = 1000.0;
  auto through = [&](int severity, double t) {
    layers[0].severity = severity;
    sky.setClouds(layers);
    sky.update(at(11, 0, 10.0), t);
    return sky.sunThroughClouds({0.0, 0.0, 0.0});
  };
  const double light = through(0, 0.0), heavy = through(5, 1.0);
  std::printf("cirrostratus: the sun through severity 0 %.3f, severity 5 %.3g\n", light, heavy);
  ASSERT_GT(light, 0.05);
  ASSERT_LT(light, 0.95);
  EXPECT_NEAR(std::log(heavy) / std::log(light), 6.0, 0.06);
  layers[0].severity = 6;
  EXPECT_THROW(sky.setClouds(layers), skyig::Error);
}
