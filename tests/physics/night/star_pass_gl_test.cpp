// The star pass on the real GL path (llvmpipe where there is no GPU): each source's energy on
// screen equals its illuminance at any resolution and field of view, lands where it is seen,
// and the host's star field intensity hides the stars.
#include "sky/camera.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/gl/render_target.h"
#include "render/sky_renderer.h"
#include "render/passes/night/star_culling.h"
#include "render/passes/night/star_pass.h"
#include "render/glsl/uniforms.h"
#include "physics/stars/star_physics.h"
#include "tests/physics/night/star_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using skyig::night_testing::kDeg;

namespace {

class StarPassGl : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    pass_ = new StarPass();
    frame_ = new UniformBuffer(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
  }
  static void TearDownTestSuite() {
    delete frame_;
    delete pass_;
    delete context_;
  }

  struct Frame {
    int width, height;
    glm::dmat3 ndcToWorld;
    std::vector<float> rgba;  // bottom row first, as GL reads it
  };

  // Renders `field` alone into a cleared float target.
  static Frame render(const std::shared_ptr<const night::StarField>& field, int width, int height,
                      const Attitude& attitude, const Frustum& frustum, bool viewCulling = true) {
    pass_->setViewCulling(viewCulling);
    Frame f{width, height, ndcToWorld(eyeToEnu(attitude, Attitude{}), frustum), {}};
    FrameBlock block{};
    block.ndcToWorld = glm::mat4(glm::mat3(f.ndcToWorld));
    block.viewport = glm::vec4(static_cast<float>(width), static_cast<float>(height), 1.0f / static_cast<float>(width),
                               1.0f / static_cast<float>(height));
    frame_->upload(block);
    frame_->bind();
    RenderTarget target(width, height, GL_RGBA32F);
    target.bindForDrawing();
    const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, black);
    pass_->draw(field, f.ndcToWorld);
    pass_->setViewCulling(true);
    f.rgba.resize(static_cast<size_t>(width) * height * 4);
    glGetTextureImage(target.texture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(f.rgba.size() * sizeof(float)),
                      f.rgba.data());
    return f;
  }

  // sum(radiance x pixel solid angle), per channel, with the brightest pixel's view ray.
  static std::pair<glm::dvec3, glm::dvec3> energy(const Frame& f) {
    glm::dvec3 sum(0.0), peakRay(0.0);
    double peak = -1.0;
    const double pixelArea = 4.0 / (static_cast<double>(f.width) * f.height);
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        const float* p = &f.rgba[(static_cast<size_t>(y) * f.width + x) * 4];
        const glm::dvec2 ndc((x + 0.5) * 2.0 / f.width - 1.0, (y + 0.5) * 2.0 / f.height - 1.0);
        sum += glm::dvec3(p[0], p[1], p[2]) * shader::pixelSolidAngle(f.ndcToWorld, ndc, pixelArea);
        if (static_cast<double>(p[1]) > peak) peak = p[1], peakRay = glm::normalize(f.ndcToWorld * glm::dvec3(ndc, 1.0));
      }
    return {sum, peakRay};
  }

  static inline GlContext* context_ = nullptr;
  static inline StarPass* pass_ = nullptr;
  static inline UniformBuffer* frame_ = nullptr;
};

night::PointSource source(double azimuthDeg, double altitudeDeg, const glm::dvec3& rec709Lux) {
  const double az = azimuthDeg * kDeg, alt = altitudeDeg * kDeg;
  night::PointSource s;
  s.direction = {std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
  s.rec709Lux = rec709Lux;
  s.illuminanceLux = 0.2126 * rec709Lux.r + 0.7152 * rec709Lux.g + 0.0722 * rec709Lux.b;
  return s;
}

}  // namespace

// One star off the axis, four channels (sizes 160x120 to 61x97, fields 20 to 100 degrees
// wide): sum(pixel radiance x pixel solid angle) is the star's illuminance within 1%, per
// channel, and the brightest pixel is the star's direction within a pixel.
TEST_F(StarPassGl, EnergyOnScreenEqualsIlluminanceAtAnySizeAndField) {
  auto field = std::make_shared<night::StarField>();
  const glm::dvec3 lux(2.0e-6, 1.5e-6, 1.0e-6);
  field->stars.push_back(source(40.0, 30.0, lux));
  const std::shared_ptr<const night::StarField> shared = field;
  struct Case {
    int width, height;
    Frustum frustum;
  };
  for (const Case& c : {Case{160, 120, {40, 40, 30, 30}}, Case{61, 97, {10, 12, 15, 12}},
                        Case{200, 80, {50, 50, 20, 20}}, Case{120, 120, {25, 35, 20, 30}}}) {
    const Frame f = render(shared, c.width, c.height, Attitude{30.0, 20.0, 5.0}, c.frustum);
    const auto [sum, peakRay] = energy(f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k], lux[k], 0.01 * lux[k]) << c.width << "x" << c.height << " channel " << k;
    const double pixelRad = (c.frustum.leftDeg + c.frustum.rightDeg) * kDeg / c.width;
    EXPECT_LT(std::acos(glm::dot(peakRay, field->stars[0].direction)), 1.0 * pixelRad) << c.width << "x" << c.height;
  }
}

// A source behind the eye or off the screen adds nothing; two sources add.
TEST_F(StarPassGl, OnlyVisibleSourcesAdd) {
  auto field = std::make_shared<night::StarField>();
  field->stars.push_back(source(210.0, -30.0, glm::dvec3(1e-6)));  // behind the eye
  field->stars.push_back(source(120.0, 20.0, glm::dvec3(1e-6)));   // far off to the side
  const Frame empty = render(field, 64, 48, Attitude{30.0, 20.0, 0.0}, Frustum{20, 20, 15, 15});
  EXPECT_EQ(energy(empty).first, glm::dvec3(0.0));
  auto more = std::make_shared<night::StarField>(*field);  // fields are immutable once drawn
  more->planets.push_back(source(28.0, 22.0, glm::dvec3(3e-6)));
  more->planets.push_back(source(34.0, 16.0, glm::dvec3(1e-6)));
  const Frame two = render(more, 64, 48, Attitude{30.0, 20.0, 0.0}, Frustum{20, 20, 15, 15});
  EXPECT_NEAR(energy(two).first.g, 4e-6, 0.04e-6);
}

// A star whose centre is just off the screen still lights the pixels its PSF reaches there (no
// pop at the edge): the energy on screen is its PSF's share inside the frame, summed on the CPU
// with the same shader code.
TEST_F(StarPassGl, StarJustOffTheEdgeKeepsItsShareInside) {
  constexpr int kW = 80, kH = 60;
  const Attitude attitude{10.0, 15.0, 0.0};
  const Frustum frustum{20, 20, 15, 15};
  const glm::dmat3 m = ndcToWorld(eyeToEnu(attitude, Attitude{}), frustum);
  const double pixelArea = 4.0 / (kW * kH);
  for (double beyond : {0.7, 2.0}) {
    const glm::dvec2 centre(kW - 0.5 + beyond, kH / 2.0 + 0.3);  // pixels; the last column's centre is W - 0.5
    const glm::dvec2 ndc = centre * 2.0 / glm::dvec2(kW, kH) - 1.0;
    auto field = std::make_shared<night::StarField>();
    night::PointSource s;
    s.direction = glm::normalize(m * glm::dvec3(ndc, 1.0));
    s.rec709Lux = glm::dvec3(1e-6);
    s.illuminanceLux = 1e-6;
    field->stars.push_back(s);
    const Frame f = render(field, kW, kH, attitude, frustum);
    double expected = 0.0;
    const double omegaCentre = shader::pixelSolidAngle(m, ndc, pixelArea);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const glm::dvec2 pc(x + 0.5, y + 0.5);
        expected += 1e-6 * shader::starPsfPixelWeight(pc - centre, shader::kStarPsfSigmaPx) *
                    shader::pixelSolidAngle(m, pc * 2.0 / glm::dvec2(kW, kH) - 1.0, pixelArea) / omegaCentre;
      }
    EXPECT_GT(expected, 0.03e-6) << beyond;
    EXPECT_NEAR(energy(f).first.g, expected, 0.02 * expected) << beyond;
  }
}

// Through the whole renderer at night: stars from the catalogue brighten the frame, and a
// star field intensity of 0 (CIGI Celestial Sphere Control) leaves the sky alone.
TEST_F(StarPassGl, StarFieldIntensityZeroHidesTheStars) {
  SkyRenderer renderer;
  ChannelConfig c;
  c.width = 96;
  c.height = 72;
  c.frustum = Frustum{40, 40, 30, 30};
  c.offset.pitchDeg = 40.0;
  ObserverState o;
  o.utc = {2026, 1, 15, 0.0};
  SkyConditions conditions;
  conditions.starCatalogue = std::make_shared<const night::StarCatalogue>(night_testing::catalogue(), o.utc);
  auto sum = [&](double intensity) {
    conditions.starFieldIntensity = intensity;
    renderer.draw(buildSkyState(o, conditions, SunOverride{0.0, -30.0}), c);
    const HdrImage im = renderer.readHdr();
    double s = 0.0;
    for (std::size_t i = 0; i < im.rgba.size(); ++i) s += i % 4 == 3 ? 0.0 : static_cast<double>(im.rgba[i]);
    return s;
  };
  const double sky = sum(0.0), full = sum(1.0), half = sum(0.5);
  EXPECT_GT(full - sky, 0.1 * full);  // the sky 30 degrees after sunset is far darker
  EXPECT_NEAR(half - sky, 0.5 * (full - sky), 0.05 * (full - sky));
}

// The passes send only the sources whose quads can touch the viewport (render/passes/
// star_culling.h). 3000 sources over the sphere and 400 on a band a few pixels either side of
// the frame's edges, in a wide, a usual and a narrow channel: the image is the same to the bit
// as with every source sent.
TEST_F(StarPassGl, SourcesOutsideTheViewAreNotSentAndChangeNothing) {
  struct Case {
    int width, height;
    Frustum frustum;
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Case& c : {Case{160, 120, {50, 50, 40, 40}}, Case{128, 96, {30, 30, 20, 20}}, Case{96, 80, {1, 1, 0.8, 0.8}}}) {
    const Attitude attitude{30.0, 20.0, 5.0};
    const glm::dmat3 m = ndcToWorld(eyeToEnu(attitude, Attitude{}), c.frustum);
    auto field = std::make_shared<night::StarField>();
    for (int i = 0; i < 3000; ++i) {
      night::PointSource s;
      s.direction = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
      s.rec709Lux = glm::dvec3(1e-6 * (1.0 + u(rng)));
      s.illuminanceLux = s.rec709Lux.g;
      field->stars.push_back(s);
    }
    for (int i = 0; i < 400; ++i) {  // around the edges, up to 12 pixels out and in
      const double along = u(rng), across = 1.0 + 12.0 * u(rng) * 2.0 / c.width;
      const glm::dvec2 ndc = i % 2 ? glm::dvec2(i % 4 == 1 ? across : -across, along) : glm::dvec2(along, i % 4 == 0 ? across : -across);
      night::PointSource s;
      s.direction = glm::normalize(m * glm::dvec3(ndc, 1.0));
      s.rec709Lux = glm::dvec3(1e-6);
      s.illuminanceLux = 1e-6;
      field->planets.push_back(s);
    }
    const Frame culled = render(field, c.width, c.height, attitude, c.frustum);
    const Frame all = render(field, c.width, c.height, attitude, c.frustum, false);
    EXPECT_EQ(culled.rgba, all.rgba) << c.width << "x" << c.height;
    double lit = 0.0;
    for (float v : culled.rgba) lit += v > 0.0f ? 1.0 : 0.0;
    EXPECT_GT(lit, 0.0);
  }
}

// A source whose illuminance is not a number (bad input upstream) is left out, not drawn as a
// NaN over its pixels, and the others are drawn as without it.
TEST_F(StarPassGl, ASourceWithoutAFiniteIlluminanceIsLeftOut) {
  auto field = std::make_shared<night::StarField>();
  field->stars.push_back(source(28.0, 22.0, glm::dvec3(3e-6)));
  field->stars.push_back(source(34.0, 16.0, glm::dvec3(1e-6)));
  const Frame clean = render(field, 64, 48, Attitude{30.0, 20.0, 0.0}, Frustum{20, 20, 15, 15});
  auto bad = std::make_shared<night::StarField>(*field);
  night::PointSource nan = source(30.0, 20.0, glm::dvec3(std::nan("")));
  bad->planets.push_back(nan);
  const Frame withBad = render(bad, 64, 48, Attitude{30.0, 20.0, 0.0}, Frustum{20, 20, 15, 15});
  EXPECT_EQ(withBad.rgba, clean.rgba);
}

// The reach the culling allows covers the quad of either pass at any point of the channel:
// sampled around the frame's edges of a wide, a usual and a 2-degree channel (where the displayed
// PSF's sigma of 2 arcmin is 32 pixels), every position whose quad, as render/passes/night/star.vert and
// render/passes/night/star_display.vert size it, overlaps the viewport is kept; one 3 reaches out is not.
TEST(StarCulling, KeepsEveryQuadThatCanTouchTheViewport) {
  struct Case {
    int width, height;
    Frustum frustum;
  };
  for (const Case& c : {Case{1920, 1200, {50, 50, 40, 40}}, Case{1280, 1024, {30, 30, 24, 24}}, Case{1920, 1200, {1, 1, 0.6, 0.6}}}) {
    const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{200.0, 10.0, 3.0}, Attitude{}), c.frustum);
    const glm::dmat3 worldToNdc = glm::inverse(m);
    const double reachPx = starQuadReachPx(m, c.width, c.height);
    const double reachX = 2.0 * reachPx / c.width, reachY = 2.0 * reachPx / c.height;
    const double area = 4.0 / (double(c.width) * c.height);
    int kept = 0, touching = 0;
    for (int i = 0; i <= 400; ++i)
      for (int j = -60; j <= 60; ++j) {
        // A point on the frame's border (i along it), j half-pixels out (+) or in (-), each side.
        for (int side = 0; side < 4; ++side) {
          const double t = -1.0 + i / 200.0;
          const double out = 1.0 + j * 0.5 * 2.0 / (side < 2 ? c.width : c.height);
          const glm::dvec2 ndc = side == 0 ? glm::dvec2(out, t) : side == 1 ? glm::dvec2(-out, t)
                               : side == 2 ? glm::dvec2(t, out) : glm::dvec2(t, -out);
          const glm::dvec2 px = (ndc * 0.5 + 0.5) * glm::dvec2(c.width, c.height);
          const double sigma = std::max(shader::kDisplayedPsfSigmaRad / std::sqrt(shader::pixelSolidAngle(m, ndc, area)),
                                        shader::kDisplayedPsfMinSigmaPx);
          const double half = shader::starPsfQuadHalfSizePx(std::max(sigma, shader::kStarPsfSigmaPx));
          const bool overlaps = px.x + half > 0.0 && px.x - half < c.width && px.y + half > 0.0 && px.y - half < c.height;
          const bool mayBe = starMayBeInView(worldToNdc, m * glm::dvec3(ndc, 1.0), reachX, reachY);
          if (overlaps) {
            ++touching;
            ASSERT_TRUE(mayBe) << c.width << "x" << c.height << " at pixel (" << px.x << ", " << px.y << "), quad half " << half;
          }
          kept += mayBe ? 1 : 0;
        }
      }
    EXPECT_GT(touching, 0);
    EXPECT_LT(kept, touching + 4 * 401 * 4);  // at most a couple of half-pixel steps beyond
    // Three reaches out, and behind the eye: left out.
    EXPECT_FALSE(starMayBeInView(worldToNdc, m * glm::dvec3(1.0 + 3.0 * reachX, 0.0, 1.0), reachX, reachY));
    EXPECT_FALSE(starMayBeInView(worldToNdc, -(m * glm::dvec3(0.0, 0.0, 1.0)), reachX, reachY));
    std::printf("%dx%d over %.0f deg: reach %.1f px\n", c.width, c.height, c.frustum.leftDeg + c.frustum.rightDeg, reachPx);
  }
}
