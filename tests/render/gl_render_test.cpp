// Headless renders on the real GL path (llvmpipe where there is no GPU), checked for physics
// and against the same shader code evaluated in double precision on the CPU.
#include "physics/analytic/analytic_sky.h"
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/precompute/rec709_tables.h"
#include "tables/table_cache.h"
#include "render/passes/sky/physical_sky_pass.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/sky_renderer.h"
#include "tests/render/shared_renderer_test.h"
#include "render/texture_readback.h"
#include "render/passes/night/night_diffuse_pass.h"
#include "render/passes/tone/tone_pass.h"
#include "physics/physics.h"
#include "ephemeris/refraction.h"

#include "tests/physics/night/star_test_support.h"
#include "physics/common/units.h"
#include "physics/weather/fog_table.h"
#include "sky/fog_state.h"
#include "sky/nvis_weights.h"
#include "physics/atmosphere/physical_camera.h"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <unistd.h>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
namespace atmosphere = skyig::atmosphere;

namespace {

using skyig::kDeg;
constexpr int kW = 160, kH = 120;

class GlRender : public skyig::render::testing::SharedRendererTest {
 protected:

  static ChannelConfig channel(double pitchUp = 0.0, Frustum f = Frustum{40, 40, 30, 30}) {
    ChannelConfig c;
    c.width = kW;
    c.height = kH;
    c.frustum = f;
    c.offset.pitchDeg = pitchUp;
    return c;
  }

  static SkyState state(double yaw, double sunAz, double sunAlt, SkyConditions c = {}) {
    ObserverState o;
    o.attitude = {yaw, 0.0, 0.0};
    return buildSkyState(o, c, SunOverride{sunAz, sunAlt});
  }

  static glm::dvec3 ray(const SkyState& s, const ChannelConfig& c, int x, int y) {
    return pixelRay(ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum), x, y, c.width, c.height);
  }

  // The display values (0-1) the tone pass gives the analytic sky along `r`, from the CPU's
  // evaluation of the same shader code: the sky's radiance, the glare veil of every source per
  // pixel (physics/eye/glare.glsl), the display's operator.
  static glm::dvec3 cpuDisplayValues(const SkyState& s, const ChannelConfig& c, const glm::dvec3& r) {
    const shader::DisplayModel d{c.display.maxLuminance, c.display.ambientLuminance, c.display.gamma,
                                 c.display.viewerAdaptationLuminance};
    glm::dvec3 world = analyticSkyRadiance(s.sky.params, r);
    for (const eye::GlareSource& g : s.glare) {
      const glm::dvec3 v = glm::normalize(r);
      const double theta = std::atan2(glm::length(glm::cross(v, g.direction)), glm::dot(v, g.direction)) * 180.0 / std::numbers::pi;
      world += g.rec709Lux * shader::veilingLuminancePerLux(theta, g.angularRadiusRad * 180.0 / std::numbers::pi,
                                                           eye::kGlareObserverAgeYears, eye::kGlareOcularPigmentation);
    }
    if (c.display.toneOperator == ToneOperator::TumblinRushmeier) return shader::toneReproduce(world, s.worldAdaptationLuminance, d);
    const eye::ToneCurve curve = toneCurveFor(s, c.display);
    const glm::dvec3 xyY = shader::mesopicxyY(shader::rec709ToXyz(glm::max(world, glm::dvec3(0.0))));
    return shader::displayValues(shader::toneReproduceLinearWithCurve(xyY, std::log10(curve.displayLuminance(xyY.z)), d), d);
  }

  static glm::dvec3 rgb(const HdrImage& im, int x, int y) {
    const float* p = im.pixel(x, y);
    return {p[0], p[1], p[2]};
  }

};

double blueness(const glm::dvec3& c) { return c.b / (c.r + c.g + c.b); }

}  // namespace

// Noon, looking up across the sky: the zenith is bluer than the horizon.
TEST_F(GlRender, ZenithBluerThanHorizonAtNoon) {
  const ChannelConfig c = channel(45.0, Frustum{50, 50, 50, 50});
  const SkyState s = state(0.0, 180.0, 60.0);  // looking north, sun high in the south
  renderer_->draw(s, c);
  const HdrImage im = renderer_->readHdr();
  int zx = 0, zy = 0, hx = 0, hy = 0;
  double best = -1.0, lowest = 1.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::dvec3 r = ray(s, c, x, y);
      if (r.z > best) best = r.z, zx = x, zy = y;
      if (r.z > 0.0 && r.z < lowest) lowest = r.z, hx = x, hy = y;
    }
  ASSERT_GT(best, 0.99);
  ASSERT_LT(lowest, 0.05);
  EXPECT_GT(blueness(rgb(im, zx, zy)), blueness(rgb(im, hx, hy)) + 0.02);
}

// The pixels nearest the sun are the brightest of the frame.
TEST_F(GlRender, BrightestPixelsAreNearestTheSun) {
  const ChannelConfig c = channel();
  const SkyState s = state(100.0, 110.0, 12.0);
  renderer_->draw(s, c);
  const HdrImage im = renderer_->readHdr();
  double brightest = 0.0, angleOfBrightest = 180.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double l = shader::rec709Luminance(rgb(im, x, y));
      if (l > brightest)
        brightest = l, angleOfBrightest = std::acos(glm::dot(ray(s, c, x, y), s.sky.params.sunDirection)) / kDeg;
    }
  const double pixelDeg = 80.0 / kW;
  EXPECT_LT(angleOfBrightest, 1.5 * pixelDeg);
}

// An overcast sky is grey: no pixel of it has more than 1% chroma.
TEST_F(GlRender, OvercastSkyIsGrey) {
  SkyConditions overcast;
  overcast.model = SkyModel::Cie;
  overcast.cieType = 1;
  const ChannelConfig c = channel(20.0);
  const SkyState s = state(0.0, 200.0, 35.0, overcast);
  renderer_->draw(s, c);
  const HdrImage im = renderer_->readHdr();
  for (int y = 0; y < kH; y += 7)
    for (int x = 0; x < kW; x += 7) {
      const glm::dvec3 p = rgb(im, x, y);
      EXPECT_LT((std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b})) / std::max({p.r, p.g, p.b}), 0.01);
    }
}

// The EXR holds the model's radiance in cd/m^2: every sky and ground pixel read back equals
// the CPU evaluation of the same shader code within half-float precision (plus float
// rounding on the GPU). Pixels on the sun's disc edge and the horizon row are skipped.
TEST_F(GlRender, ExrValuesEqualTheModelInCandelaPerSquareMetre) {
  const ChannelConfig c = channel(10.0);
  const SkyState s = state(30.0, 40.0, 25.0);
  renderer_->draw(s, c);
  const std::string path = (std::filesystem::temp_directory_path() / ("skyig_test_exr_values-" + std::to_string(::getpid()) + ".exr")).string();
  writeExr(path, renderer_->readHdr(), {{"skyig:channel", c.name}});
  const ExrFile file = readExr(path);
  std::filesystem::remove(path);
  EXPECT_EQ(file.whiteLuminance, 1.0f);
  EXPECT_EQ(std::get<std::string>(file.attributes.at("skyig:channel")), c.name);
  ASSERT_EQ(file.image.width, kW);
  int compared = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::dvec3 r = ray(s, c, x, y);
      if (std::abs(r.z) < 2e-3 || glm::dot(r, s.sky.params.sunDirection) > std::cos(1.0 * kDeg)) continue;
      const glm::dvec3 expected = analyticSkyRadiance(s.sky.params, r);
      const glm::dvec3 got = rgb(file.image, x, y);
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(got[k], expected[k], 2e-3 * std::abs(expected[k]) + 1e-3) << x << "," << y << " channel " << k;
      ++compared;
    }
  EXPECT_GT(compared, kW * kH * 9 / 10);
}

// The 8-bit frame equals the CPU's tone reproduction of the CPU's radiance within the
// +-1 LSB dither and rounding.
TEST_F(GlRender, DisplayFrameEqualsCpuToneReproduction) {
  for (const ToneOperator op : {ToneOperator::Histogram, ToneOperator::TumblinRushmeier}) {
    ChannelConfig c = channel(5.0);
    c.display.toneOperator = op;
    const SkyState s = state(200.0, 230.0, 8.0);
    renderer_->draw(s, c);
    const DisplayImage im = renderer_->readDisplay();
    for (int y = 1; y < kH; y += 5)
      for (int x = 1; x < kW; x += 5) {
        const glm::dvec3 r = ray(s, c, x, y);
        if (std::abs(r.z) < 2e-3) continue;
        const glm::dvec3 n = cpuDisplayValues(s, c, r);
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(im.rgba[(static_cast<size_t>(y) * kW + x) * 4 + k], n[k] * 255.0, 2.0)
              << (op == ToneOperator::Histogram ? "histogram " : "tumblin-rushmeier ") << x << "," << y;
      }
  }
}

// Where the tone pass reads the glare veil from its grid (render/passes/tone/tone_pass.h: away from
// the sun) and where it evaluates it per pixel (the box of cells around the sun), the display
// codes equal the CPU's with the veil per pixel, as above. 640x400 over 60 x 40 deg, the sun
// in view: about two thirds of the frame are outside the sun's box.
TEST_F(GlRender, GlareVeilFromTheGridEqualsThePerPixelVeil) {
  ChannelConfig c = channel(5.0, Frustum{30, 30, 20, 20});
  c.width = 640;
  c.height = 400;
  const SkyState s = state(200.0, 215.0, 12.0);
  renderer_->draw(s, c);
  const DisplayImage im = renderer_->readDisplay();
  const GlareGrid grid = glareGrid(ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum), c.width, c.height,
                                   {s.glare[0].direction});
  const glm::ivec4 box = grid.nearBoxes[0];
  ASSERT_LT(box.x, box.y);  // the sun's box is in view
  int fromGrid = 0, perPixel = 0;
  double gridError = 0.0;
  for (int y = 1; y < c.height; y += 7)
    for (int x = 1; x < c.width; x += 7) {
      const glm::dvec3 r = ray(s, c, x, y);
      if (std::abs(r.z) < 2e-3) continue;
      const glm::dvec3 n = cpuDisplayValues(s, c, r);
      const int cx = x / kGlareCellPx, cy = (c.height - 1 - y) / kGlareCellPx;  // GL rows from the bottom
      const bool inBox = cx >= box.x && cx < box.y && cy >= box.z && cy < box.w;
      for (int k = 0; k < 3; ++k) {
        const double d = im.rgba[(static_cast<size_t>(y) * c.width + x) * 4 + k] - n[k] * 255.0;
        ASSERT_NEAR(d, 0.0, 2.0) << x << "," << y;
        if (!inBox) gridError += d;
      }
      ++(inBox ? perPixel : fromGrid);
    }
  EXPECT_GT(perPixel, 100);
  EXPECT_GT(fromGrid, perPixel);
  // Without bias, too: the dither's and the rounding's errors average out over the ~10 000
  // values (to about 0.005 of a code), an interpolation that misses its grid by half a cell
  // does not (0.07).
  EXPECT_LT(std::abs(gridError / (3 * fromGrid)), 0.02);
}

// GlareGrid::cellAngleRad bounds the angle of every cell edge of the grid (the vertices of
// render/glsl/pixel_grid.glsl, measured one by one), and is the widest within 0.1% where the eye's axis
// is in view (no edge need be centred on it): a frustum around the axis, and one beside it (10 to
// 50 deg right), for 8- and 3-pixel cells of about 2 and 0.8 deg.
TEST(GlareGrid, CellAngleBoundsEveryCellEdge) {
  const int w = 301, h = 203;
  for (const Frustum f : {Frustum{35, 25, 20, 28}, Frustum{-10, 50, 20, 28}})
    for (const int cellPx : {kGlareCellPx, 3}) {
      const glm::dmat3 m = ndcToWorld(eyeToEnu({30.0, 10.0, 0.0}, {}), f);
      const GlareGrid g = glareGrid(m, w, h, {}, cellPx);
      const auto vertex = [&](int i, int j) {
        return glm::normalize(m * glm::dvec3(2.0 * i * cellPx / w - 1.0, 2.0 * j * cellPx / h - 1.0, 1.0));
      };
      double widest = 0.0;
      for (int j = 0; j <= g.rows; ++j)
        for (int i = 0; i <= g.columns; ++i)
          for (const glm::dvec3 next : {vertex(i + 1, j), vertex(i, j + 1)}) {
            const glm::dvec3 v = vertex(i, j);
            widest = std::max(widest, std::atan2(glm::length(glm::cross(v, next)), glm::dot(v, next)));
          }
      EXPECT_GE(g.cellAngleRad, widest * (1.0 - 1e-12)) << cellPx;
      if (f.leftDeg > 0.0) {
        EXPECT_NEAR(g.cellAngleRad, widest, widest * 1e-3) << cellPx;
      }
    }
}

// The box of cells around a source holds every pixel within kGlareExactCells - 1 cells' angle
// of it, wherever the source is: in view, at the edge, just outside, behind; for the veil's own
// grid and for a night's layer of 3-pixel cells.
TEST(GlareGrid, EveryPixelNearASourceIsInItsBox) {
  const int w = 301, h = 203;  // not whole cells
  const glm::dmat3 m = ndcToWorld(eyeToEnu({0.0, 0.0, 0.0}, {}), Frustum{35, 25, 20, 28});
  for (const int cellPx : {kGlareCellPx, 3})
  for (const glm::dvec3 source : {pixelRay(m, 150, 100, w, h), pixelRay(m, 3, 5, w, h), pixelRay(m, 290, 190, w, h),
                                  glm::normalize(m * glm::dvec3(1.3, 0.2, 1.0)), glm::normalize(m * glm::dvec3(0.1, -0.2, -1.0))}) {
    const GlareGrid g = glareGrid(m, w, h, {source}, cellPx);
    ASSERT_EQ(g.cellPx, cellPx);
    ASSERT_GT(g.cellAngleRad, 0.0);
    const glm::ivec4 b = g.nearBoxes[0];
    int near = 0;
    for (int row = 0; row < h; ++row)
      for (int x = 0; x < w; ++x) {
        if (glm::dot(pixelRay(m, x, row, w, h), source) <= std::cos((kGlareExactCells - 1.0) * g.cellAngleRad)) continue;
        ++near;
        const int cx = x / cellPx, cy = (h - 1 - row) / cellPx;
        ASSERT_TRUE(cx >= b.x && cx < b.y && cy >= b.z && cy < b.w) << "pixel " << x << "," << row << ", cell " << cellPx;
      }
    if (near == 0) {
      EXPECT_EQ(b.x, b.y) << "an empty box where no pixel is near";
    }
  }
}

// Looking along the horizon at sunset: no NaN or Inf anywhere, in either target.
TEST_F(GlRender, HorizonFrameIsFinite) {
  for (double sunAlt : {0.0, -0.2, 0.3, -10.0}) {
    const ChannelConfig c = channel(0.0, Frustum{60, 60, 2, 2});
    const SkyState s = state(270.0, 270.0, sunAlt);
    renderer_->draw(s, c);
    const HdrImage im = renderer_->readHdr();
    for (float v : im.rgba) ASSERT_TRUE(std::isfinite(v)) << "sun altitude " << sunAlt;
  }
}

// The PNG is written, readable, the channel's size, and not flat.
TEST_F(GlRender, PngIsWrittenAndNotFlat) {
  const ChannelConfig c = channel(15.0);
  const SkyState s = state(250.0, 260.0, 20.0);
  renderer_->draw(s, c);
  const std::string path = (std::filesystem::temp_directory_path() / ("skyig_test_not_flat-" + std::to_string(::getpid()) + ".png")).string();
  writePng(path, renderer_->readDisplay(), c.display.gamma);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&image, path.c_str())) << image.message;
  image.format = PNG_FORMAT_GRAY;
  std::vector<unsigned char> grey(PNG_IMAGE_SIZE(image));
  ASSERT_TRUE(png_image_finish_read(&image, nullptr, grey.data(), 0, nullptr));
  std::filesystem::remove(path);
  EXPECT_EQ(image.width, static_cast<unsigned>(kW));
  EXPECT_EQ(image.height, static_cast<unsigned>(kH));
  double mean = 0.0, sq = 0.0;
  for (unsigned char g : grey) mean += g, sq += double(g) * g;
  const double count = static_cast<double>(grey.size());
  mean /= count;
  EXPECT_GT(std::sqrt(sq / count - mean * mean), 10.0);  // levels of standard deviation
}

// Rendering the same state twice gives the same pixels (determinism on one driver).
TEST_F(GlRender, SameStateSameFrame) {
  const ChannelConfig c = channel();
  const SkyState s = state(10.0, 20.0, 30.0);
  renderer_->draw(s, c);
  const HdrImage a = renderer_->readHdr();
  renderer_->draw(state(200.0, 20.0, 5.0), c);
  renderer_->draw(s, c);
  EXPECT_EQ(a.rgba, renderer_->readHdr().rgba);
}

namespace {

// The small tables the atmosphere tests share through the build tree's cache.
std::shared_ptr<const atmosphere::AtmosphereModel> smallModel(double visibilityKm = 0.0, bool tiny = false) {
  atmosphere::ModelConfig config;
  config.sizes = atmosphere::TableSizes::small();
  if (tiny) {  // a few texels a side and 12 radii: computed in a second, uploaded in 6 frames
    config.sizes.transmittanceMu = 16;
    config.sizes.transmittanceR = 8;
    config.sizes.irradianceMuS = 8;
    config.sizes.irradianceR = 4;
    config.sizes.scatteringR = 12;
    config.sizes.scatteringMu = 8;
    config.sizes.scatteringMuS = 4;
    config.sizes.scatteringNu = 2;
  }
  if (visibilityKm > 0.0) {
    atmosphere::Conditions c;
    c.visibilityKm = visibilityKm;
    config.medium = atmosphere::applyConditions(config.medium, c);
  }
  return std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(config, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache"));
}

SkyConditions physicalConditions(std::shared_ptr<const atmosphere::AtmosphereModel> model) {
  SkyConditions physical;
  physical.model = SkyModel::Physical;
  physical.atmosphere = std::move(model);
  return physical;
}

// The ground point along view, if the ray meets it.
std::optional<glm::dvec3> groundPoint(const atmosphere::AtmosphereModel& model, const glm::dvec3& camera,
                                      const glm::dvec3& view) {
  const double rmu = glm::dot(camera, view);
  const double r = glm::length(camera), bottom = model.parameters(0).bottom_radius;
  const double discriminant = rmu * rmu - r * r + bottom * bottom;
  if (rmu < 0.0 && discriminant >= 0.0) return camera + view * (-rmu - std::sqrt(discriminant));
  return std::nullopt;
}

// What the pass draws, from the spectral CPU model: sky + sun disc, or sky + the ground's
// reflection attenuated along the ray (its in-scatter is in the sky term).
glm::dvec3 spectralView(const atmosphere::AtmosphereModel& model, const glm::dvec3& camera, const glm::dvec3& view,
                        const glm::dvec3& sun) {
  std::vector<double> radiance = model.skyRadiance(camera, view, sun);
  if (const auto point = groundPoint(model, camera, view)) {
    std::vector<double> t;
    model.skyRadianceToPoint(camera, *point, sun, &t);
    const auto sunE = model.sunIrradiance(*point, glm::normalize(*point), sun);
    const auto skyE = model.skyIrradiance(*point, glm::normalize(*point), sun);
    const double albedo = model.parameters(0).ground_albedo.x;
    for (std::size_t i = 0; i < radiance.size(); ++i) radiance[i] += albedo / std::numbers::pi * (sunE[i] + skyE[i]) * t[i];
  } else {
    const std::vector<double> disc = model.sunDiscRadiance(camera, view, sun);
    for (std::size_t i = 0; i < radiance.size(); ++i) radiance[i] += disc[i];
  }
  return model.converter().toRec709(radiance);
}

}  // namespace

// The physical sky pass (Bruneton & Neyret 2008 from the tables folded into Rec.709 at half
// float) equals the CPU evaluation of the same GLSL on the same packed tables in double
// precision (float arithmetic and texture filtering: 0.5% of the luminance), and the spectral
// CPU model within the packing's documented approximation (sky: half floats; ground: the XYZ
// transmittance, 3%; docs/atmosphere.md).
TEST_F(GlRender, PhysicalSkyMatchesTheCpuModel) {
  const auto model = smallModel();
  const atmosphere::PackedRec709Tables packed = atmosphere::packRec709(*model);
  const ChannelConfig c = channel(-5.0, Frustum{40, 40, 30, 30});  // sky and ground
  const SkyState s = state(120.0, 140.0, 8.0, physicalConditions(model));
  renderer_->draw(s, c);
  const HdrImage im = renderer_->readHdr();
  const glm::dvec3 camera = physicalCamera(*model, s.observer.heightM);
  const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunAltitude);
  int compared = 0, ground = 0;
  double worstSpectralSky = 0.0, worstSpectralGround = 0.0;
  for (int y = 2; y < kH; y += 6)
    for (int x = 2; x < kW; x += 6) {
      const glm::dvec3 view = ray(s, c, x, y);
      if (std::abs(view.z) < 0.01) continue;  // the horizon's steep gradient, sampled differently
      const bool onGround = groundPoint(*model, camera, view).has_value();
      ground += onGround ? 1 : 0;
      const glm::dvec3 expected = atmosphere::packedRadianceRec709(*model, packed, camera, view, sun);
      const glm::dvec3 got = rgb(im, x, y);
      const double scale = shader::rec709Luminance(expected);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(got[k], expected[k], 5e-3 * scale + 1e-4) << x << "," << y << " channel " << k;
      const glm::dvec3 spectral = spectralView(*model, camera, view, sun);
      double& worst = onGround ? worstSpectralGround : worstSpectralSky;
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(got[k] - spectral[k]) / shader::rec709Luminance(spectral));
      ++compared;
    }
  std::printf("GPU vs spectral CPU model: sky %.2e, ground %.2e of the luminance\n", worstSpectralSky, worstSpectralGround);
  EXPECT_LT(worstSpectralSky, 6e-3);
  EXPECT_LT(worstSpectralGround, 0.03);
  EXPECT_GT(compared, 400);
  EXPECT_GT(ground, 50);
  EXPECT_GT(s.worldAdaptationLuminance, 100.0);  // a sunlit sky, from the model
}

// Looking along the horizon (the tables' discontinuity between ground and sky rays), with the
// sun on it, below it, and from high up: no pixel is NaN, infinite or negative.
TEST_F(GlRender, PhysicalHorizonHasNoInvalidPixel) {
  const auto physical = physicalConditions(smallModel());
  const ChannelConfig c = channel(0.0, Frustum{40, 40, 2, 2});
  for (double sunAlt : {30.0, 0.2, -0.3, -10.0}) {
    for (double height : {0.5, 3000.0, 90e3}) {
      ObserverState o;
      o.attitude = {140.0, 0.0, 0.0};
      o.heightM = height;
      const SkyState s = buildSkyState(o, physical, SunOverride{140.0, sunAlt});
      renderer_->draw(s, c);
      const HdrImage im = renderer_->readHdr();
      for (float v : im.rgba) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << "sun " << sunAlt << " height " << height;
    }
  }
}

// A second light (the moon, Jensen et al. 2001) adds the same tables lit from its direction
// times its Rec.709 scale; a zero scale draws the sun alone.
TEST_F(GlRender, PhysicalMoonlightAddsTheScaledSkyFromTheMoon) {
  const auto model = smallModel();
  const atmosphere::PackedRec709Tables packed = atmosphere::packRec709(*model);
  const ChannelConfig c = channel(20.0, Frustum{40, 40, 30, 30});
  SkyState s = state(10.0, 140.0, -20.0, physicalConditions(model));  // sun far below: night
  renderer_->draw(s, c);
  const HdrImage dark = renderer_->readHdr();
  s.moonDirection = enuDirection(30.0 * kDeg, 40.0 * kDeg);
  s.moonlightScale = glm::dvec3(2.0e-6, 2.2e-6, 2.5e-6);
  renderer_->draw(s, c);
  const HdrImage moonlit = renderer_->readHdr();
  const glm::dvec3 camera = physicalCamera(*model, s.observer.heightM);
  int compared = 0;
  for (int y = 3; y < kH; y += 12)
    for (int x = 3; x < kW; x += 12) {
      const glm::dvec3 view = ray(s, c, x, y);
      if (view.z < 0.01) continue;  // the sky (the ground adds the moon's reflection too)
      const glm::dvec3 moonSky = atmosphere::packedSkyRec709(*model, packed, camera, view, s.moonDirection) * s.moonlightScale;
      const glm::dvec3 added = rgb(moonlit, x, y) - rgb(dark, x, y);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(added[k], moonSky[k], 0.01 * shader::rec709Luminance(moonSky)) << x << "," << y;
      const glm::dvec3 cpu = atmosphere::moonlitSkyRec709(*model, camera, view, s.moonDirection, s.moonlightScale);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(added[k], cpu[k], 0.01 * shader::rec709Luminance(cpu)) << x << "," << y;
      ++compared;
    }
  EXPECT_GT(compared, 50);
  EXPECT_GT(shader::rec709Luminance(rgb(moonlit, kW / 2, kH / 4)), 1e-4);  // a moonlit sky, ~1e-3 cd/m^2
}

// A new model (the host changed the visibility) is uploaded across frames while the old one
// is drawn: the frames before the announced one equal the old model's, that one and the next
// the new model's, and no frame uploads more than its slices.
TEST_F(GlRender, PhysicalTablesSwapAfterTheAnnouncedFrames) {
  const auto clear = smallModel(0.0, true);
  const auto hazy = smallModel(20.0, true);
  const ChannelConfig c = channel(-5.0, Frustum{40, 40, 30, 30});
  const SkyState clearState = state(30.0, 140.0, 25.0, physicalConditions(clear));
  const SkyState hazyState = state(30.0, 140.0, 25.0, physicalConditions(hazy));
  SkyRenderer renderer;  // its own pass: a fresh upload state
  renderer.draw(hazyState, c);
  const HdrImage hazyFrame = renderer.readHdr();
  SkyRenderer fresh;
  fresh.draw(clearState, c);
  const HdrImage clearFrame = fresh.readHdr();
  ASSERT_NE(clearFrame.rgba, hazyFrame.rgba);

  fresh.draw(hazyState, c);  // announces the swap and uploads the first slices
  const PhysicalSkyPass* pass = fresh.physicalPass();
  ASSERT_EQ(pass->pending(), hazy.get());
  const int slices = hazy->tables(0).scattering.depth;
  constexpr int perFrame = PhysicalSkyPass::kDefaultSlicesPerFrame;
  const int frames = (slices + perFrame - 1) / perFrame;
  EXPECT_EQ(pass->framesUntilSwap(), frames - 1);
  EXPECT_EQ(fresh.readHdr().rgba, clearFrame.rgba);
  const std::size_t sliceBytes = static_cast<std::size_t>(hazy->tables(0).scattering.width) *
                                 static_cast<std::size_t>(hazy->tables(0).scattering.height) * 12;
  std::printf("frame 1: uploaded %zu bytes in %.2f ms\n", pass->lastUploadBytes(), pass->lastUploadSeconds() * 1e3);
  for (int f = 2; f <= frames; ++f) {
    fresh.draw(hazyState, c);
    EXPECT_LE(pass->lastUploadBytes(), perFrame * sliceBytes) << "frame " << f;
    std::printf("frame %d: uploaded %zu bytes in %.2f ms\n", f, pass->lastUploadBytes(), pass->lastUploadSeconds() * 1e3);
    if (f < frames) {
      EXPECT_EQ(fresh.readHdr().rgba, clearFrame.rgba) << "frame " << f;
      EXPECT_EQ(pass->current(), clear.get());
    }
  }
  EXPECT_EQ(pass->current(), hazy.get());
  EXPECT_EQ(pass->pending(), nullptr);
  EXPECT_EQ(fresh.readHdr().rgba, hazyFrame.rgba);
  fresh.draw(hazyState, c);
  EXPECT_EQ(pass->lastUploadBytes(), 0u);
  EXPECT_EQ(fresh.readHdr().rgba, hazyFrame.rgba);
}

// Every value is kept: the sun's disc (~1.6e9 cd/m^2 at noon) reaches the EXR in 32-bit float
// with the model's luminance, at noon, at sunset and in haze with its aureole, and no pixel of
// the frame or of the file is infinite or NaN (half float overflowed at 65504).
TEST_F(GlRender, SunDiscKeepsItsLuminanceInTheExr) {
  const std::filesystem::path exr = std::filesystem::temp_directory_path() / ("skyig_sun_disc-" + std::to_string(::getpid()) + ".exr");
  struct Case {
    double sunAltitude, visibilityKm;
  };
  for (const Case k : {Case{60.0, 0.0}, Case{2.0, 0.0}, Case{30.0, 8.0}}) {
    const auto model = smallModel(k.visibilityKm);
    const SkyState s = state(0.0, 200.0, k.sunAltitude, physicalConditions(model));
    // A 2-degree channel on the sun: its disc (0.53 deg) is ~30 pixels across.
    ChannelConfig c = channel(0.0, Frustum{1, 1, 0.75, 0.75});
    c.offset = {200.0, s.sunApparentAltitude / kDeg, 0.0};
    renderer_->draw(s, c);
    while (renderer_->physicalPass()->current() != model.get()) renderer_->draw(s, c);  // a new model uploads over frames
    writeExr(exr.string(), renderer_->readHdr(), {});
    const HdrImage im = readExr(exr.string()).image;
    double peak = 0.0;
    for (std::size_t i = 0; i < im.rgba.size(); ++i) {
      ASSERT_TRUE(std::isfinite(im.rgba[i])) << "sun at " << k.sunAltitude << ": value " << i;
      if (i % 4 == 1) peak = std::max(peak, static_cast<double>(im.rgba[i]));  // G ~ luminance at the disc
    }
    const glm::dvec3 centre = rgb(im, kW / 2, kH / 2);
    const glm::dvec3 camera = physicalCamera(*model, s.observer.heightM);
    // The disc's centre is seen where refraction lifts it, its light arriving along the view:
    // the CPU model's sun there (the sky it lights differs by a part in 1e3 of the disc).
    const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunApparentAltitude);
    const glm::dvec3 view = ray(s, c, kW / 2, kH / 2);
    const glm::dvec3 expected = spectralView(*model, camera, view, sun);
    EXPECT_NEAR(shader::rec709Luminance(centre) / shader::rec709Luminance(expected), 1.0, 0.05)
        << "sun at " << k.sunAltitude << " deg, visibility " << k.visibilityKm << " km";
    EXPECT_GT(shader::rec709Luminance(centre), k.sunAltitude > 10.0 ? 1e8 : 1e6);
    EXPECT_GT(peak, 65504.0);  // what half float could not hold
  }
  std::filesystem::remove(exr);
}

// The setting sun is flattened by refraction as the real one is: with the true sun on the
// horizon (seen at ~0.48 deg), its lower limb is lifted ~5.5 arcmin more than its upper, so the
// disc is ~17% shorter than it is wide. Its extents in a 2-degree channel (~43 pixels across)
// match the ephemeris' refraction (Saemundsson, evaluated exactly at each limb, not the
// quadratic the shader uses) to a pixel (with the pixels its limbs cross), and the disc is smooth: limb darkening and the
// transmittance along each pixel's own ray change by a few per cent between neighbours, and
// nothing more (no speckle).
TEST_F(GlRender, RefractionFlattensTheSettingSun) {
  const auto model = smallModel();
  const SkyState s = state(0.0, 200.0, 0.0, physicalConditions(model));
  ChannelConfig c = channel(0.0, Frustum{1, 1, 0.75, 0.75});
  c.offset = {200.0, s.sunApparentAltitude / kDeg, 0.0};
  renderer_->draw(s, c);
  while (renderer_->physicalPass()->current() != model.get()) renderer_->draw(s, c);
  const HdrImage im = renderer_->readHdr();
  const double perPixel = 2.0 * kDeg / kW;  // square pixels: 0.75 / 60 = 1 / 80 deg
  const double radius = model->parameters(0).sun_angular_radius;
  auto lum = [&](int x, int y) { return shader::rec709Luminance(rgb(im, x, y)); };
  const double sky = std::max({lum(0, 0), lum(kW - 1, 0), lum(0, kH - 1), lum(kW - 1, kH - 1)});
  ASSERT_GT(lum(kW / 2, kH / 2), 100.0 * sky) << "the sun is at the channel's centre";
  // The disc's pixels along the column and the row through its brightest pixel.
  int cx = kW / 2, cy = kH / 2;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (lum(x, y) > lum(cx, cy)) cx = x, cy = y;
  auto onDisc = [&](int x, int y) { return lum(x, y) > 10.0 * sky; };
  int top = cy, bottom = cy, left = cx, right = cx;  // y grows downwards
  while (top > 0 && onDisc(cx, top - 1)) --top;
  while (bottom < kH - 1 && onDisc(cx, bottom + 1)) ++bottom;
  const int midRow = (top + bottom) / 2;
  while (left > 0 && onDisc(left - 1, midRow)) --left;
  while (right < kW - 1 && onDisc(right + 1, midRow)) ++right;
  const double tall = bottom - top + 1, wide = right - left + 1;
  // Where the true limbs are seen: h = a + R(a) at a = a0 +- radius.
  const double a0 = s.sunAltitude;
  auto seen = [&](double a) { return a + ephemeris::refractionSaemundsson(a, s.observer.pressureHpa, s.observer.temperatureC); };
  const double expectedTall = (seen(a0 + radius) - seen(a0 - radius)) / perPixel, expectedWide = 2.0 * radius / perPixel;
  std::printf("sun at %.3f deg apparent: %g x %g pixels, refraction gives %.2f x %.2f\n", s.sunApparentAltitude / kDeg,
              wide, tall, expectedWide, expectedTall);
  EXPECT_LT(expectedTall / expectedWide, 0.9) << "the refraction model flattens the disc";
  // The pixels the disc touches: its limbs anti-aliased (physical_sky.frag), the pixels they cross
  // show their part of it, one more than its extent on average.
  EXPECT_NEAR(wide, expectedWide + 1.0, 1.0);
  EXPECT_NEAR(tall, expectedTall + 1.0, 1.0);
  // Smooth: within the inner 70% of the disc, each pixel within a few per cent of the mean of
  // its neighbours on either side, across and along.
  double worst = 0.0;
  for (int y = top; y <= bottom; ++y)
    for (int x = left; x <= right; ++x) {
      const double u = (x - 0.5 * (left + right)) / (0.5 * wide), v = (y - 0.5 * (top + bottom)) / (0.5 * tall);
      if (u * u + v * v > 0.7 * 0.7) continue;
      const glm::dvec3 p = rgb(im, x, y);
      for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
        const glm::dvec3 mean = 0.5 * (rgb(im, x - d.x, y - d.y) + rgb(im, x + d.x, y + d.y));
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(p[k] - mean[k]) / shader::rec709Luminance(p));
      }
    }
  std::printf("largest step from the neighbours' mean inside the disc: %.2e of the luminance\n", worst);
  EXPECT_LT(worst, 0.02);
}

// In haze the sky brightens towards the horizon and meets the ground's aerial perspective there;
// it has no dark line just above it. The line was the tables' last sky texel (the ray grazing
// the ground), computed from a ratio of two transmittances that both underflow in single
// precision (exp(-90) along the ground in a 10 km haze): up to half as bright as its neighbours,
// 0.5 deg high. Looking towards the sun and away from it, the luminance of each row in the
// 1.5 deg above the horizon is at least that of the darker of the ground just below the horizon
// and the sky 1.5 deg up, less 5%.
TEST_F(GlRender, HazyHorizonHasNoDarkLine) {
  const auto model = smallModel(10.0);
  for (double yaw : {300.0, 120.0}) {
    const SkyState s = state(yaw, 300.0, 10.0, physicalConditions(model));
    const glm::dvec3 camera = physicalCamera(*model, s.observer.heightM);
    const double dip = std::acos(model->parameters(0).bottom_radius / glm::length(camera)) / kDeg;
    ChannelConfig c = channel(0.5 - dip, Frustum{2, 2, 1.5, 1.5});  // 0.025 deg a row, the horizon 0.5 deg low
    renderer_->draw(s, c);
    while (renderer_->physicalPass()->current() != model.get()) renderer_->draw(s, c);
    const HdrImage im = renderer_->readHdr();
    const int x = kW / 2;
    int horizon = 0;  // the first row (from the top) on the ground
    while (horizon < kH && !groundPoint(*model, camera, ray(s, c, x, horizon))) ++horizon;
    ASSERT_GT(horizon, 70);
    ASSERT_LT(horizon, kH - 2);
    const int rows = static_cast<int>(1.5 / 0.025);
    const double ground = shader::rec709Luminance(rgb(im, x, horizon + 1));
    const double above = shader::rec709Luminance(rgb(im, x, horizon - rows));
    double darkest = above;
    for (int y = horizon - rows; y < horizon; ++y) darkest = std::min(darkest, shader::rec709Luminance(rgb(im, x, y)));
    std::printf("yaw %.0f: ground %.1f, sky 1.5 deg up %.1f, darkest row between %.1f cd/m^2\n", yaw, ground, above, darkest);
    EXPECT_GT(darkest, 0.95 * std::min(ground, above)) << "looking at azimuth " << yaw;
  }
}

namespace {

// A 1280 x 800 channel over 60 deg, 10 deg up (0.047 deg a pixel: the night's layer has cells of
// 3 pixels), and the state of `utc` under the small tables with the observer at `yaw` and
// `pitch`, mapped for the channel's display.
struct NightView {
  ChannelConfig channel;
  SkyState state;
};
NightView nightView(const char* utc, double yaw, double pitch) {
  ChannelConfig c;
  c.width = 1280;
  c.height = 800;
  c.frustum = Frustum{30, 30, 19.3, 19.3};
  c.offset.pitchDeg = 10.0;
  ObserverState o;
  o.utc = *ephemeris::parseIso8601Utc(utc);
  o.attitude = {yaw, pitch, 0.0};
  SkyState s = buildSkyState(o, physicalConditions(smallModel()));
  mapForDisplays(s, {c.display});
  return {c, s};
}

// The state of `utc` (ISO 8601) at the default site under the small physical tables, looking
// along `yaw`, mapped for `c`'s display as the sky worker maps it.
SkyState mappedState(const char* utc, double yaw, const ChannelConfig& c) {
  ObserverState o;
  o.utc = *ephemeris::parseIso8601Utc(utc);
  o.attitude = {yaw, 0.0, 0.0};
  SkyConditions conditions = physicalConditions(smallModel());
  conditions.starCatalogue = std::make_shared<const night::StarCatalogue>(night_testing::catalogue(), o.utc);
  SkyState s = buildSkyState(o, conditions);
  mapForDisplays(s, {c.display});
  return s;
}

// Display codes (RGB) differing by more than one, and by exactly one.
std::pair<int, int> codeDifferences(const DisplayImage& a, const DisplayImage& b) {
  int moreThanOne = 0, one = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const int d = std::abs(int(a.rgba[i]) - int(b.rgba[i]));
    moreThanOne += d > 1 ? 1 : 0;
    one += d == 1 ? 1 : 0;
  }
  return {moreThanOne, one};
}

}  // namespace

// Faint layers no display would show are left out of the frame (sky/shown_layers.h): the
// moonlit sky by day (the moon 25 deg up, the sun 20 deg), both in civil twilight, and the
// sun's own sky and ground once night has fallen. The frame drawn without them shows the codes
// of the frame drawn with every layer: none differs by more than one, and under 1% by one (the
// float sum's last bit under the dither). On a moonlit and on a moonless night the moon's and
// the night's light are drawn; in twilight and by day the sun's sky is.
TEST_F(GlRender, LayersLeftOutChangeNoDisplayCode) {
  const ChannelConfig c = channel(10.0, Frustum{40, 40, 30, 30});
  struct Case {
    const char* utc;
    double yaw;
    bool sunlit, moonlit, night;
  };
  // The moon up by day; the sun 5 deg down in the north-west after a June sunset (the night's
  // light is first shown at about -8 deg, the moonlit sky at -6.6); a full moon rising (its sky
  // outshines the sun's, 45 deg down); a moonless December night (the tables' floor of the
  // sun's sky, 5e-6 cd/m^2 at most, is within the margin of the darkest cells, the terrain's
  // 2.5e-5).
  for (const Case& k : {Case{"2026-06-23T17:00:00Z", 150.0, true, false, false},
                        Case{"2026-06-21T19:45:00Z", 315.0, true, false, false},
                        Case{"2026-12-24T20:00:00Z", 60.0, false, true, true},
                        Case{"2026-12-09T22:00:00Z", 180.0, true, false, true}}) {
    SkyState s = mappedState(k.utc, k.yaw, c);
    std::printf("%s: sun %.1f deg, adaptation %.3g cd/m^2, the sun's sky %s, moonlit sky %s, night light %s, point sources %s\n", k.utc,
                s.sunAltitude / kDeg, s.worldAdaptationLuminance, s.shown.sunlitSky ? "drawn" : "left out",
                s.shown.moonlitSky ? "drawn" : "left out",
                s.shown.nightLight ? "drawn" : "left out", s.shown.pointSources ? "drawn" : "left out");
    EXPECT_EQ(s.shown.sunlitSky, k.sunlit) << k.utc;
    EXPECT_EQ(s.shown.moonlitSky, k.moonlit) << k.utc;
    EXPECT_EQ(s.shown.nightLight, k.night) << k.utc;
    renderer_->draw(s, c);
    const DisplayImage shown = renderer_->readDisplay();
    s.shown = ShownLayers{};  // every layer
    renderer_->draw(s, c);
    const DisplayImage all = renderer_->readDisplay();
    const auto [moreThanOne, one] = codeDifferences(shown, all);
    if (k.sunlit && k.moonlit && k.night) continue;  // nothing was left out
    EXPECT_EQ(moreThanOne, 0) << k.utc;
    EXPECT_LT(one, kW * kH * 3 / 100) << k.utc;
  }
}

// Where the sky pass maps its own pixels to the display (SkyRenderer::drawChannel: no
// full-screen pass follows it) the channel shows, to the bit, what the tone pass mapping every
// pixel after all the others shows: the same function on the same float, and the tone pass
// again wherever a later pass drew. At noon with the sun in view (its box of the exact veil);
// the moon up by day, in view (its quad and box); the sun 5 deg down after a June sunset (the
// night's light left out, a few faint displayed stars); at 12 km; a moonless night (the night's
// light added by the sky pass, the displayed stars mapped again on their quads), the same
// with the night's light left out by hand, and a full moon with stars in its box (the sky pass
// maps the box with the veil per pixel, the stars' quads there are mapped again the same way).
TEST_F(GlRender, SkyPassMappingItsOwnPixelsShowsWhatTheTonePassShows) {
  const ChannelConfig c = channel(10.0, Frustum{40, 40, 30, 30});
  struct Case {
    const char* utc;
    double yaw;
    double heightM;
    bool stars;  // displayed stars expected in view
    bool leaveOutNightLight = false;  // by hand: the stars of a moonless night over a folded sky
    double pitch = 0.0;
  };
  for (const Case& k : {Case{"2026-06-21T11:00:00Z", 180.0, 0.0, false}, Case{"2026-06-23T17:00:00Z", 150.0, 0.0, false},
                        Case{"2026-06-21T19:45:00Z", 315.0, 0.0, true}, Case{"2026-06-21T11:00:00Z", 200.0, 12000.0, false},
                        Case{"2026-12-09T22:00:00Z", 180.0, 0.0, true},
                        Case{"2026-12-09T22:00:00Z", 180.0, 0.0, true, true},
                        Case{"2026-01-03T21:00:00Z", 108.0, 0.0, true, false, 20.0}}) {
    ObserverState o;
    o.utc = *ephemeris::parseIso8601Utc(k.utc);
    o.attitude = {k.yaw, k.pitch, 0.0};
    o.heightM = k.heightM;
    SkyConditions conditions = physicalConditions(smallModel());
    conditions.starCatalogue = std::make_shared<const night::StarCatalogue>(night_testing::catalogue(), o.utc);
    SkyState s = buildSkyState(o, conditions);
    mapForDisplays(s, {c.display});
    if (k.leaveOutNightLight) s.shown.nightLight = false;
    renderer_->setToneFolding(false);
    renderer_->draw(s, c);
    const DisplayImage everyPixel = renderer_->readDisplay();
    const HdrImage light = renderer_->readHdr();
    const HdrImage stars = renderer_->readPointSources();
    renderer_->setToneFolding(true);
    renderer_->draw(s, c);
    const DisplayImage folded = renderer_->readDisplay();
    int starPixels = 0;
    float brightest = 0.0f;
    for (std::size_t i = 0; i < stars.rgba.size(); i += 4) {
      starPixels += stars.rgba[i + 1] > 0.0f ? 1 : 0;
      brightest = std::max(brightest, stars.rgba[i + 1]);
    }
    std::printf("brightest star pixel %g cd/m^2 on the display\n", double(brightest));
    std::printf("%s yaw %.0f, %.0f m: sun %.1f deg, glare sources %zu, displayed-star pixels %d, night light %s\n",
                k.utc, k.yaw, k.heightM, s.sunAltitude / kDeg, s.glare.size(), starPixels,
                s.shown.nightLight ? "drawn" : "left out");
    EXPECT_EQ(renderer_->readHdr().rgba, light.rgba) << k.utc << ": the light written for the EXR";
    const auto [moreThanOne, one] = codeDifferences(everyPixel, folded);
    EXPECT_EQ(moreThanOne + one, 0) << k.utc;
    if (k.stars) {
      EXPECT_GT(starPixels, 0) << k.utc;
    }
  }
  renderer_->setToneFolding(true);
}

// On a night with one glare source, the full moon, the night's layer holds its veil at the
// vertices of its grid (3-pixel cells at 1280 x 800 over 60 deg; NightDiffusePass::drawLayer) and
// the sky pass reads it with the night's light: the display codes are those of the same frame
// with the veil from its own grid of 8-pixel cells (render/passes/tone/tone_pass.h, checked against
// the per-pixel veil above) to within one code and without bias: the mean difference under 0.01
// of a code over the frame's 3 million values (measured 0.0003). Facing the moon 30 deg up, its
// veil over the whole frame; a layer without the veil, or read half a cell off, fails.
TEST_F(GlRender, GlareVeilFromTheNightLayerShowsWhatItsOwnGridShows) {
  const auto [c, s] = nightView("2026-01-03T21:00:00Z", 108.0, 20.0);
  ASSERT_TRUE(s.shown.nightLight);
  int lit = 0;
  for (const eye::GlareSource& g : s.glare) lit += g.rec709Lux != glm::dvec3(0.0) ? 1 : 0;
  ASSERT_EQ(lit, 1);  // the moon; the sun is 53 deg down
  renderer_->draw(s, c);
  const DisplayImage fromLayer = renderer_->readDisplay();
  renderer_->setGlareVeilInNightLayer(false);
  renderer_->draw(s, c);
  const DisplayImage fromGrid = renderer_->readDisplay();
  renderer_->setGlareVeilInNightLayer(true);
  double sum = 0.0;
  int worst = 0, values = 0, differ = 0;
  for (std::size_t i = 0; i < fromLayer.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const int d = int(fromLayer.rgba[i]) - int(fromGrid.rgba[i]);
    worst = std::max(worst, std::abs(d));
    differ += d != 0 ? 1 : 0;
    sum += d;
    ++values;
  }
  std::printf("veil from the night's layer against its own grid: %d of %d values differ, by %d at most, %.4f on average\n",
              differ, values, worst, sum / values);
  EXPECT_LE(worst, 1);
  EXPECT_LT(std::abs(sum / values), 0.01);
}

// Where no star or planet can pass the eye's threshold (sky/shown_layers.h) the displayed-star
// pass is not drawn, and what an earlier frame drew into its target does not stay: a moonless
// night's stars, then a day whose point sources are left out, shows the codes of the same day
// with the pass drawn (no star passes the threshold in that view) and an empty target.
TEST_F(GlRender, PointSourcesLeftOutLeaveNoStarsBehind) {
  const ChannelConfig c = channel(10.0, Frustum{40, 40, 30, 30});
  SkyState day = mappedState("2026-06-23T17:00:00Z", 150.0, c);
  ASSERT_TRUE(day.shown.pointSources);  // Venus and Jupiter are up: they can be seen by day
  renderer_->draw(day, c);
  const DisplayImage drawn = renderer_->readDisplay();
  for (float v : renderer_->readPointSources().rgba) ASSERT_EQ(v, 0.0f) << "no star is shown in this view";
  renderer_->draw(mappedState("2026-12-09T22:00:00Z", 180.0, c), c);
  int starTexels = 0;
  for (float v : renderer_->readPointSources().rgba) starTexels += v > 0.0f ? 1 : 0;
  ASSERT_GT(starTexels, 0);
  day.shown.pointSources = false;
  renderer_->draw(day, c);
  for (float v : renderer_->readPointSources().rgba) ASSERT_EQ(v, 0.0f) << "the night's stars were cleared";
  const auto [moreThanOne, one] = codeDifferences(drawn, renderer_->readDisplay());
  EXPECT_EQ(moreThanOne + one, 0);
}

// The displayed-star pass is sent only the sources above the faintest the eye can see anywhere
// in the view (ShownLayers::pointSourceFloorLux): by day 3 of the 4400 sources above the
// horizon, on a moonless night 4300 of 4600 (the catalogue's faintest are fainter than any
// dark sky lets the eye see). Those left out
// would each have failed the pass's own test against the sky at their pixel, so the displayed
// stars are the same to the bit as with every source sent.
TEST_F(GlRender, StarsBelowTheFaintestSeenAreNotSentAndChangeNothing) {
  // By day, the channel centred on the brightest planet (Venus, 45 deg up); at night 10 deg up.
  const SkyState probe = mappedState("2026-06-23T17:00:00Z", 0.0, channel());
  const auto venus = std::max_element(probe.starField->planets.begin(), probe.starField->planets.end(),
                                      [](const auto& a, const auto& b) { return a.illuminanceLux < b.illuminanceLux; });
  const double venusYaw = std::atan2(venus->direction.x, venus->direction.y) / kDeg;
  const double venusPitch = std::asin(venus->direction.z) / kDeg;
  for (const auto& [utc, yaw] : {std::pair{"2026-06-23T17:00:00Z", venusYaw}, std::pair{"2026-12-09T22:00:00Z", 180.0}}) {
    const ChannelConfig c = channel(yaw == venusYaw ? venusPitch : 10.0, Frustum{40, 40, 30, 30});
    SkyState s = mappedState(utc, yaw, c);
    ASSERT_TRUE(s.shown.pointSources);
    std::size_t sources = 0, sent = 0;
    for (const auto* list : {&s.starField->stars, &s.starField->planets})
      for (const night::PointSource& p : *list) {
        ++sources;
        sent += p.illuminanceLux > s.shown.pointSourceFloorLux ? 1 : 0;
      }
    std::printf("%s, yaw %.1f: %zu of %zu sources above the floor %.3g lux\n", utc, yaw, sent, sources,
                s.shown.pointSourceFloorLux);
    EXPECT_GT(sent, 0u);
    EXPECT_LT(sent, s.sunAltitude > 0.0 ? 10u : sources);
    renderer_->draw(s, c);
    const HdrImage floored = renderer_->readPointSources();
    const DisplayImage flooredDisplay = renderer_->readDisplay();
    int lit = 0;
    for (float v : floored.rgba) lit += v > 0.0f ? 1 : 0;
    EXPECT_GT(lit, 0) << utc;
    s.shown.pointSourceFloorLux = 0.0;  // every source sent
    renderer_->draw(s, c);
    EXPECT_EQ(floored.rgba, renderer_->readPointSources().rgba) << utc;
    EXPECT_EQ(flooredDisplay.rgba, renderer_->readDisplay().rgba) << utc;
  }
}

// The physical sky pass adds the night's own light from a layer of about the Milky Way map's
// texel (0.18 deg; NightDiffusePass::drawLayer), read bilinearly, where the night's pass drew
// it at every pixel: the same light. A moonless winter night at 1280 x 800 over 60 deg (0.047
// deg a pixel: a layer texel of 3 pixels), looking south 10 deg up with the horizon in view,
// the night's light in the frame (the frame less the sky pass alone) against the night's pass
// drawn alone at full resolution: the frame's mean within 0.3%, the median sky pixel within
// 0.5%, 99% within 5% (measured: 0.0005% and 0.015%: the map is smooth at its own texel); the
// terrain's light below the horizon, 99% within 1% (measured 0%); within 1.7 deg of the
// horizon, where the transmittance falls fast, every pixel within 2% (measured 0.5%): the
// transmittance and the terrain's step are applied per pixel there, not read from the layer.
// From 8 to 16 deg up (kNightLayerBandDeg and twice it), where the sky pass reads the layer
// already dimmed at its texels, 99% within 0.2% (measured 0.009%).
TEST_F(GlRender, NightLayerShowsTheNightsLightOfEveryPixel) {
  const auto [c, s] = nightView("2026-12-09T22:00:00Z", 180.0, 0.0);
  ASSERT_TRUE(s.shown.nightLight);
  ASSERT_LT(s.moonDirection.z, -0.2);  // no moon
  renderer_->draw(s, c);
  const HdrImage frame = renderer_->readHdr();
  renderer_->drawSkyPass(s, c);
  const HdrImage sky = renderer_->readHdr();
  // The night's pass alone, every pixel, into a cleared target of the channel.
  RenderTarget target(c.width, c.height, GL_RGBA32F);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, zero);
  target.bindForDrawing();
  NightDiffusePass pass;
  ASSERT_EQ(pass.layerScale(2.0 * std::tan(30.0 * kDeg) / c.width), 3);  // the renderer's scale here
  pass.draw(s);  // the renderer's frame block is still bound, for this channel
  const HdrImage full = readFloatTexture(target.texture(), c.width, c.height);
  double sumLayer = 0.0, sumFull = 0.0;
  std::vector<double> errors, groundErrors;
  double horizonWorst = 0.0;
  std::vector<double> aboveBand;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const float* f = frame.pixel(x, y);
      const float* k = sky.pixel(x, y);
      const float* n = full.pixel(x, y);
      const double layer = shader::rec709Luminance(glm::dvec3(f[0] - k[0], f[1] - k[1], f[2] - k[2]));
      const double exact = shader::rec709Luminance(glm::dvec3(n[0], n[1], n[2]));
      sumLayer += layer;
      sumFull += exact;
      const double z = ray(s, c, x, y).z;
      const double e = std::abs(layer / exact - 1.0);
      if (std::abs(z) < 0.03) horizonWorst = std::max(horizonWorst, e);  // within 1.7 deg of the horizon
      else (z < 0.0 ? groundErrors : errors).push_back(e);
      // Just above the band where the sky pass applies the transmittance per pixel.
      if (z > std::sin(kNightLayerBandDeg * kDeg) && z < std::sin(2.0 * kNightLayerBandDeg * kDeg))
        aboveBand.push_back(e);
    }
  std::sort(errors.begin(), errors.end());
  std::sort(groundErrors.begin(), groundErrors.end());
  std::sort(aboveBand.begin(), aboveBand.end());
  ASSERT_GT(groundErrors.size(), 1000u);
  ASSERT_GT(aboveBand.size(), 1000u);
  const double aboveBandP99 = aboveBand[aboveBand.size() * 99 / 100];
  const double groundP99 = groundErrors[groundErrors.size() * 99 / 100];
  const double pixels = double(c.width) * double(c.height);
  const double median = errors[errors.size() / 2], p99 = errors[errors.size() * 99 / 100];
  std::printf("night light: mean %.4g (layer) against %.4g cd/m^2, sky pixels off by %.3g%% (median), %.3g%% (99th), "
              "ground pixels %.3g%% (99th), within 1.7 deg of the horizon %.3g%% at most, from %.0f to %.0f deg up, where "
              "the layer holds the transmittance, %.3g%% (99th)\n", sumLayer / pixels, sumFull / pixels, 100.0 * median,
              100.0 * p99, 100.0 * groundP99, 100.0 * horizonWorst, kNightLayerBandDeg, 2.0 * kNightLayerBandDeg,
              100.0 * aboveBandP99);
  EXPECT_NEAR(sumLayer / sumFull, 1.0, 0.003);
  EXPECT_LT(median, 0.005);
  EXPECT_LT(p99, 0.05);
  EXPECT_LT(groundP99, 0.01);
  EXPECT_LT(horizonWorst, 0.02);
  EXPECT_LT(aboveBandP99, 0.002);
}

// The weather's table is made with the sky state (on the node's worker), not by each channel's
// renderer on the render thread: the state's tables are the weather's own at the renderer's eye
// height, the eye's and each goggle class's (apart where there is haze to thin), the frame drawn
// from them is the frame the pass's own table gives to the bit, and the pass does draw from the
// state's (a state carrying another fog's table draws another frame).
TEST_F(GlRender, TheFogTableMadeWithTheStateDrawsTheFrameTheRenderThreadWould) {
  SkyConditions c = physicalConditions(smallModel());
  c.fog = {0.0, 200.0, 0.4};
  c.haze = weather::hazeBelowTables(2.0, 1200.0);
  const SkyState s = state(270.0, 120.0, 40.0, c);
  const FogTables& t = s.fog.tables;
  ASSERT_TRUE(t.eye && t.nvisA && t.nvisB);
  const double h = glm::length(atmosphere::physicalCamera(*c.atmosphere, s.observer.heightM)) -
                   c.atmosphere->parameters(0).bottom_radius;
  EXPECT_EQ(t.heightM, h);
  EXPECT_EQ(*t.eye, weather::fogTable(drawnFogLayers(s.fog), h));
  EXPECT_EQ(*t.nvisB, weather::fogTable(goggleFogLayers(s, nvis::NvisClass::B), h));
  EXPECT_NE(*t.nvisA, *t.eye);  // the haze thinner in the goggle's band

  const ChannelConfig ch = channel(-2.0);
  renderer_->draw(s, ch);
  const HdrImage fromState = renderer_->readHdr();
  SkyState own = s;
  own.fog.tables = FogTables{};
  renderer_->draw(own, ch);
  EXPECT_EQ(renderer_->readHdr().rgba, fromState.rgba);

  SkyConditions thicker = c;
  thicker.fog.visibilityKm = 0.1;
  SkyState mixed = s;
  mixed.fog.tables = state(270.0, 120.0, 40.0, thicker).fog.tables;
  renderer_->draw(mixed, ch);
  EXPECT_NE(renderer_->readHdr().rgba, fromState.rgba);
}

// A moonless night under a broken stratocumulus deck (50 %, 1500-2000 m, about 25 optical depths
// thick): the night's own light (airglow, zodiacal light, the Milky Way, the sky pass's night
// layer) shows in the deck's gaps as under a clear sky and is gone behind its cloud, pixel by
// pixel as the deck's field has it, as a star is. The state's extinction profile weighs the deck
// by its coverage; drawn by that alone, both would show half the clear night's light. Within 1 %
// in a gap and under 2 % behind cloud (measured 0.6 % and at most 1.0 %): the weather table's
// alpha the factor is made of keeps the air's own light in front of the deck (1 - its
// transmittance to the deck, in the deck's shade), which light from beyond the air does not
// have (render/passes/common/cloud_field.glsl).
TEST_F(GlRender, TheNightsOwnLightShowsInABrokenDecksGapsAndNotBehindItsCloud) {
  ChannelConfig ch;
  ch.width = 96;
  ch.height = 64;
  ch.frustum = Frustum{30, 30, 20, 20};
  ch.offset.pitchDeg = 50.0;
  ObserverState o;
  o.utc = *ephemeris::parseIso8601Utc("2026-12-09T22:00:00Z");
  o.attitude = {180.0, 0.0, 0.0};
  SkyConditions clearAir = physicalConditions(smallModel()), overcast = clearAir;
  CloudLayer& deck = overcast.clouds[0];
  deck.enabled = true;
  deck.type = CloudType::Stratocumulus;
  deck.baseM = 1500.0;
  deck.thicknessM = 500.0;
  deck.coveragePct = 50.0;
  SkyState clear = buildSkyState(o, clearAir), under = buildSkyState(o, overcast);
  mapForDisplays(clear, {ch.display});
  mapForDisplays(under, {ch.display});
  ASSERT_TRUE(under.fog.broken());
  ASSERT_TRUE(clear.shown.nightLight && under.shown.nightLight);
  ASSERT_LT(clear.moonDirection.z, -0.2);  // no moon
  clear.starField = under.starField = nullptr;  // the diffuse light alone
  renderer_->draw(clear, ch);
  const HdrImage open = renderer_->readHdr();
  renderer_->draw(under, ch);
  const HdrImage shaded = renderer_->readHdr();
  const double h = glm::length(atmosphere::physicalCamera(*clearAir.atmosphere, o.heightM)) -
                   clearAir.atmosphere->parameters(0).bottom_radius;
  std::vector<double> gap, cloud;
  for (int y = 0; y < ch.height; y += 2)
    for (int x = 0; x < ch.width; x += 2) {
      const double t = decksTransmittanceAlong(under.fog, h, glm::dvec2(0.0), glm::normalize(ray(under, ch, x, y)));
      const float* a = open.pixel(x, y);
      const float* b = shaded.pixel(x, y);
      const double ratio = shader::rec709Luminance(glm::dvec3(b[0], b[1], b[2])) /
                           shader::rec709Luminance(glm::dvec3(a[0], a[1], a[2]));
      if (t > 0.999) gap.push_back(ratio);
      if (t < 1e-3) cloud.push_back(ratio);
    }
  ASSERT_GT(gap.size(), 100u);
  ASSERT_GT(cloud.size(), 100u);
  std::sort(gap.begin(), gap.end());
  std::sort(cloud.begin(), cloud.end());
  std::printf("the night's own light under 50 %% stratocumulus against the clear night: %zu pixels in gaps %.4f-%.4f "
              "(median %.4f), %zu behind cloud at most %.3g (median %.3g)\n", gap.size(), gap.front(), gap.back(),
              gap[gap.size() / 2], cloud.size(), cloud.back(), cloud[cloud.size() / 2]);
  EXPECT_NEAR(gap.front(), 1.0, 0.01);
  EXPECT_NEAR(gap.back(), 1.0, 0.01);
  EXPECT_LT(cloud.back(), 0.02);
}
