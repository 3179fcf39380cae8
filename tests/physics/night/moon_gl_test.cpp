// The moon's GL pass on the real GL path (llvmpipe where there is no GPU): its energy on screen
// against the CPU's irradiance, and where its light falls on the disc.
#include "sky/camera.h"
#include "render/gl/gl_context.h"
#include "render/passes/night/moon_pass.h"
#include "render/gl/render_target.h"
#include "render/sky_renderer.h"
#include "render/glsl/uniforms.h"
#include "physics/physics.h"
#include "tests/physics/night/moon_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using namespace skyig::sky::night;
using namespace skyig::sky::testing;

namespace {

class MoonGl : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    renderer_ = new SkyRenderer();
    pass_ = new MoonPass();
  }
  static void TearDownTestSuite() {
    delete pass_;
    delete renderer_;
    delete context_;
  }

  // A channel looking straight at (azimuth, altitude) with the given half-angle.
  static ChannelConfig channel(int width, int height, double halfWidthDeg) {
    ChannelConfig c;
    c.width = width;
    c.height = height;
    const double halfHeight = std::atan(std::tan(halfWidthDeg * kDeg) * height / width) / kDeg;
    c.frustum = Frustum{halfWidthDeg, halfWidthDeg, halfHeight, halfHeight};
    return c;
  }

  // The moon pass alone into a black float target; returns Rec.709 per pixel (row 0 at top).
  // `drawn`, if given: the rectangle the pass says it may have drawn (x, y from the bottom).
  static std::vector<glm::dvec3> drawAlone(const MoonDisc& d, const glm::dmat3& m, const ChannelConfig& c,
                                           glm::ivec4* drawn = nullptr) {
    RenderTarget target(c.width, c.height, GL_RGBA32F);
    UniformBuffer frame(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
    FrameBlock b{};
    b.ndcToWorld = glm::mat4(glm::mat3(m));
    b.viewport = glm::vec4(static_cast<float>(c.width), static_cast<float>(c.height), 1.0f / static_cast<float>(c.width),
                           1.0f / static_cast<float>(c.height));
    frame.upload(b);
    frame.bind();
    target.bindForDrawing();
    const float black[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, black);
    const glm::ivec4 rectangle = pass_->draw(d, m, c);
    if (drawn) *drawn = rectangle;
    glFinish();
    std::vector<float> rgba(static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height) * 4);
    glGetTextureImage(target.texture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)), rgba.data());
    std::vector<glm::dvec3> out(static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height));
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        const float* p = &rgba[(static_cast<std::size_t>(c.height - 1 - y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)) * 4];
        out[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)] = glm::dvec3(p[0], p[1], p[2]);
      }
    return out;
  }

  static inline GlContext* context_ = nullptr;
  static inline SkyRenderer* renderer_ = nullptr;
  static inline MoonPass* pass_ = nullptr;
};

// Pixel (column, row from the top) where a world direction lands.
glm::dvec2 project(const glm::dmat3& ndcToWorldMatrix, const glm::dvec3& v, int width, int height) {
  const glm::dvec3 p = glm::inverse(ndcToWorldMatrix) * v;
  return {(p.x / p.z + 1.0) * 0.5 * width, (1.0 - p.y / p.z) * 0.5 * height};
}

// The moon's light in a frame rendered through the renderer: the frame minus the sky pass alone.
struct MoonImage {
  std::vector<double> luminance;
  glm::dvec2 centre;  // pixel of the disc's seen centre
  glm::dvec2 sunward;  // unit image vector towards the sun along the sky
  double radiusPx;
};

MoonImage renderMoon(SkyRenderer& renderer, const SkyState& s, const ChannelConfig& c) {
  renderer.drawSkyPass(s, c);
  const HdrImage sky = renderer.readHdr();
  renderer.draw(s, c);
  const HdrImage all = renderer.readHdr();
  MoonImage m;
  m.luminance.resize(static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height));
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const float* a = all.pixel(x, y);
      const float* b = sky.pixel(x, y);
      m.luminance[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)] =
          shader::rec709Luminance(glm::dvec3(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
  const MoonDisc d = *s.moonDisc;
  const glm::dmat3 ndc = ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum);
  m.centre = project(ndc, d.centreSeen, c.width, c.height);
  const glm::dvec3 sun = enuDirection(s.ephemeris->sun.azimuthRad, s.ephemeris->sun.altitudeRad);
  const glm::dvec3 along = glm::normalize(sun - glm::dot(sun, d.centre) * d.centre);
  m.sunward = glm::normalize(project(ndc, d.centreSeen + 1e-3 * along, c.width, c.height) - m.centre);
  m.radiusPx = glm::length(project(ndc, d.centreSeen + std::tan(d.angularRadiusRad) * along, c.width, c.height) - m.centre);
  return m;
}

SkyState lookAtMoon(ObserverState o) {
  SkyState probe = buildSkyState(o, SkyConditions{});
  o.attitude = {probe.ephemeris->moon.azimuthRad / kDeg, probe.ephemeris->moon.altitudeRefractedRad / kDeg, 0.0};
  return buildSkyState(o, SkyConditions{});
}

}  // namespace

// Sum of pixel radiance x pixel solid angle = the CPU's irradiance of the disc, at two
// resolutions (8 and 34 pixels across the disc): the limb's coverage ramp keeps the energy.
TEST_F(MoonGl, FrameEnergyEqualsCpuIrradianceAtTwoResolutions) {
  const MoonDisc d = makeMoonDisc(placeMoon(200.0, 40.0, 60.0, 70.0), seaLevelExtinction());
  const double cpu = integratedLux(d, 400);
  for (int width : {96, 384}) {
    const ChannelConfig c = channel(width, width * 3 / 4, 1.5);
    const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{200.0, 40.0, 0.0}, c.offset), c.frustum);
    const std::vector<glm::dvec3> rgb = drawAlone(d, m, c);
    const double pixelArea = (2.0 / c.width) * (2.0 / c.height);
    const double det = std::abs(glm::determinant(m));
    double sum = 0.0;
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        // d(Omega) = |det M| dx dy / |M (x, y, 1)|^3 for the ray M (x, y, 1) of eq. 22.
        const double l = glm::length(m * glm::dvec3((x + 0.5) / c.width * 2.0 - 1.0, 1.0 - (y + 0.5) / c.height * 2.0, 1.0));
        sum += shader::rec709Luminance(rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)]) * det *
               pixelArea / (l * l * l);
      }
    EXPECT_NEAR(sum, cpu, 0.03 * cpu) << width << " pixels wide";
    std::printf("%d px: GL %.6g lux, CPU %.6g lux\n", width, sum, cpu);
  }
}

// The rectangle the pass returns holds every pixel it lit (the tone pass maps only those again
// after a sky pass that mapped its own: SkyRenderer::drawChannel) and is not much larger than
// the quad: the moon in the middle of the channel, half out at its right edge, beside the view,
// behind the eye, and 90 deg off the view's axis (the quad across the eye's plane).
TEST_F(MoonGl, TheReturnedRectangleHoldsEveryPixelItLit) {
  const MoonDisc d = makeMoonDisc(placeMoon(200.0, 40.0, 60.0, 70.0), seaLevelExtinction());
  const ChannelConfig c = channel(160, 120, 3.0);
  for (const double yaw : {200.0, 197.0, 190.0, 20.0, 110.0}) {
    const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{yaw, 40.0, 0.0}, c.offset), c.frustum);
    glm::ivec4 r(-1);
    const std::vector<glm::dvec3> rgb = drawAlone(d, m, c, &r);
    int lit = 0;
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        if (rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)] == glm::dvec3(0.0))
          continue;
        ++lit;
        const int glRow = c.height - 1 - y;
        ASSERT_TRUE(x >= r.x && x < r.x + r.z && glRow >= r.y && glRow < r.y + r.w)
            << "yaw " << yaw << ": pixel " << x << "," << glRow << " outside " << r.x << "," << r.y << " " << r.z << "x" << r.w;
      }
    // The quad: 1.2 radii and 3 pixels each side of the centre (0.26 deg = 6.9 pixels here),
    // one pixel of margin: about 26 pixels square.
    if (yaw == 190.0 || yaw == 20.0 || yaw == 110.0) {  // beside the view, behind the eye, 90 deg off
      EXPECT_EQ(lit, 0);
      EXPECT_TRUE(r.z == 0 || r.w == 0) << yaw << ": nothing in view, nothing to map again";
    } else {
      EXPECT_GT(lit, 50) << yaw;
      EXPECT_LE(r.z, 28) << yaw;
      EXPECT_LE(r.w, 28) << yaw;
    }
  }
}

// A moon near first or last quarter: the brightness-weighted centre of the disc lies towards
// the sun's direction on the sky.
TEST_F(MoonGl, LitSideFacesTheSun) {
  const std::optional<ObserverState> night = nightWithMoon(70.0, 110.0, 20.0);
  ASSERT_TRUE(night.has_value());
  const SkyState s = lookAtMoon(*night);
  const ChannelConfig c = channel(160, 120, 1.0);
  const MoonImage m = renderMoon(*renderer_, s, c);
  double total = 0.0;
  glm::dvec2 centroid(0.0);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const double l = m.luminance[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)];
      total += l;
      centroid += l * (glm::dvec2(x + 0.5, y + 0.5) - m.centre);
    }
  ASSERT_GT(total, 0.0);
  centroid /= total;
  std::printf("radius %.2f px, centroid towards the sun %.2f px\n", m.radiusPx, glm::dot(centroid, m.sunward));
  EXPECT_GT(glm::dot(centroid, m.sunward), 0.25 * m.radiusPx) << "centroid " << centroid.x << "," << centroid.y;
}

// A crescent's horns point away from the sun: the lit pixels farthest from the sun-moon line
// lie behind the crescent's brightness-weighted centre, seen from the sun.
TEST_F(MoonGl, CrescentHornsPointAwayFromTheSun) {
  const std::optional<ObserverState> night = nightWithMoon(120.0, 150.0, 10.0);
  ASSERT_TRUE(night.has_value());
  const SkyState s = lookAtMoon(*night);
  const ChannelConfig c = channel(160, 120, 1.0);
  const MoonImage m = renderMoon(*renderer_, s, c);
  const double peak = *std::max_element(m.luminance.begin(), m.luminance.end());
  ASSERT_GT(peak, 0.0);
  const glm::dvec2 across(-m.sunward.y, m.sunward.x);
  struct Lit {
    double along, across;
  };
  std::vector<Lit> lit;
  double weight = 0.0, alongSum = 0.0;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const double l = m.luminance[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)];
      if (l < 0.2 * peak) continue;
      const glm::dvec2 r = glm::dvec2(x + 0.5, y + 0.5) - m.centre;
      lit.push_back({glm::dot(r, m.sunward), std::abs(glm::dot(r, across))});
      weight += l;
      alongSum += l * glm::dot(r, m.sunward);
    }
  ASSERT_GT(lit.size(), 20u);
  std::sort(lit.begin(), lit.end(), [](const Lit& a, const Lit& b) { return a.across > b.across; });
  double tips = 0.0;
  const std::size_t n = std::max<std::size_t>(4, lit.size() / 20);
  for (std::size_t i = 0; i < n; ++i) tips += lit[i].along;
  tips /= static_cast<double>(n);
  const double centre = alongSum / weight;
  std::printf("radius %.2f px, crescent %.2f px, horns %.2f px towards the sun\n", m.radiusPx, centre, tips);
  EXPECT_GT(centre, 0.5 * m.radiusPx);  // the crescent hugs the sunward limb
  EXPECT_LT(tips, centre - 0.3 * m.radiusPx) << "tips " << tips << ", crescent " << centre;
}

// On the GL path too the moon is dimmer and redder low over the horizon, and the pass's pixels
// agree with the CPU's radiance along the same rays (refraction, extinction, colour).
TEST_F(MoonGl, ExtinctionReddensTheMoonNearTheHorizon) {
  const ChannelConfig c = channel(64, 48, 0.5);
  glm::dvec3 centre[2];
  const double altitudes[2] = {60.0, 3.0};
  for (int k = 0; k < 2; ++k) {
    const MoonDisc d = makeMoonDisc(placeMoon(100.0, altitudes[k], 0.0), seaLevelExtinction());
    const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{100.0, altitudes[k], 0.0}, c.offset), c.frustum);
    const std::vector<glm::dvec3> rgb = drawAlone(d, m, c);
    // A 3x3 patch at the centre, against the CPU along the same rays.
    glm::dvec3 gl(0.0), cpu(0.0);
    for (int y = c.height / 2 - 1; y <= c.height / 2 + 1; ++y)
      for (int x = c.width / 2 - 1; x <= c.width / 2 + 1; ++x) {
        gl += rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(x)];
        cpu += moonDiscRadiance(d, pixelRay(m, x, y, c.width, c.height)).rec709;
      }
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(gl[ch], cpu[ch], 0.05 * cpu[ch]) << "altitude " << altitudes[k] << ", channel " << ch;
    centre[k] = gl;
  }
  EXPECT_LT(shader::rec709Luminance(centre[1]), 0.5 * shader::rec709Luminance(centre[0]));
  EXPECT_GT(centre[1].r / centre[1].b, 1.5 * centre[0].r / centre[0].b);
}
