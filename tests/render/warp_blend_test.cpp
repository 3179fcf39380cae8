// The warp-and-blend pass of projector channels (render/passes/projector/warp_blend_pass.h) on the real
// GL path, with synthetic calibrations: two projectors side by side on a flat strip of screen,
// whose overlap has a smooth alpha ramp summing to 1 and the black-level lift
// beta = alpha b (k_max - k) of a dome generator. The projector's light is modelled as a real
// projector's: black b plus (1 - b) n^gamma of its white.
#include "calibration/load.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/passes/projector/warp_blend_pass.h"
#include "render/sky_renderer.h"
#include "render/texture_readback.h"
#include "physics/physics.h"
#include "sky/sky_state.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using skyig::calibration::FloatMap;
using skyig::calibration::ProjectorCalibration;

namespace {

// The screen strip: kScreen columns by kRows rows, seen by one channel image of that size.
// Projector 0 shows screen columns [0, kProjector), projector 1 [kScreen - kProjector, kScreen).
constexpr int kScreen = 200, kRows = 40, kProjector = 120;
constexpr int kOverlapBegin = kScreen - kProjector, kOverlapEnd = kProjector;  // [80, 120)
constexpr double kGamma = 2.2;
constexpr double kBlack = 1.0 / 1000.0;  // the projector's black relative to its white (1:1000)

int firstColumn(int projector) { return projector == 0 ? 0 : kScreen - kProjector; }

// Projector `projector`'s share of screen column c: a smooth ramp (smoothstep) across the
// overlap, the two shares adding up to 1.
double alphaAt(int projector, int column) {
  if (column < kOverlapBegin) return projector == 0 ? 1.0 : 0.0;
  if (column >= kOverlapEnd) return projector == 0 ? 0.0 : 1.0;
  const double t = (column - kOverlapBegin + 0.5) / (kOverlapEnd - kOverlapBegin);
  const double s = t * t * (3.0 - 2.0 * t);
  return projector == 0 ? 1.0 - s : s;
}

bool inOverlap(int column) { return column >= kOverlapBegin && column < kOverlapEnd; }

// The calibration of one projector; `warpColumns` samples across its warp map (first and last
// on the centres of its first and last pixels), which is linear, so any count is exact.
std::shared_ptr<ProjectorCalibration> sideBySide(int projector, bool withBeta, int warpColumns = kProjector) {
  auto c = std::make_shared<ProjectorCalibration>();
  c->source = "synthetic projector " + std::to_string(projector);
  c->width = kProjector;
  c->height = kRows;
  c->warp = FloatMap{warpColumns, kRows, 2, std::vector<float>(static_cast<std::size_t>(warpColumns) * kRows * 2)};
  for (int y = 0; y < kRows; ++y)
    for (int j = 0; j < warpColumns; ++j) {
      const double x = j * (kProjector - 1.0) / (warpColumns - 1.0);
      c->warp.at(j, y, 0) = static_cast<float>((firstColumn(projector) + x + 0.5) / kScreen);
      c->warp.at(j, y, 1) = static_cast<float>((y + 0.5) / kRows);
    }
  c->alpha = FloatMap{kProjector, 1, 1, std::vector<float>(kProjector)};
  if (withBeta) c->beta = FloatMap{kProjector, 1, 1, std::vector<float>(kProjector)};
  for (int x = 0; x < kProjector; ++x) {
    const int column = firstColumn(projector) + x;
    const double alpha = alphaAt(projector, column);
    c->alpha.at(x, 0) = static_cast<float>(alpha);
    const int k = inOverlap(column) ? 2 : 1, kMax = 2;
    if (withBeta) c->beta.at(x, 0) = static_cast<float>(alpha * kBlack * (kMax - k));
  }
  return c;
}

// The light of a projector pixel driven with the 8-bit value `code`, relative to its white.
double emitted(double code) { return kBlack + (1.0 - kBlack) * std::pow(code / 255.0, kGamma); }

GLuint uniformTexture(GLenum internalFormat, int width, int height, float value) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, internalFormat, width, height);
  const float rgba[4] = {value, value, value, 1.0f};
  glClearTexImage(t, 0, GL_RGBA, GL_FLOAT, rgba);
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

class WarpBlend : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    pass_ = new WarpBlendPass();
    renderer_ = new SkyRenderer();
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete pass_;
    delete context_;
  }

  // One projector's 8-bit image and light for a uniform channel image of display value n and
  // `light` cd/m^2.
  static std::pair<DisplayImage, HdrImage> projectOne(const ProjectorCalibration& c, float n, float light) {
    const GLuint display = uniformTexture(GL_RGBA16F, kScreen, kRows, n);
    const GLuint hdr = uniformTexture(GL_RGBA32F, kScreen, kRows, light);
    const ProjectorMaps maps(c);
    pass_->draw(maps, display, hdr, kGamma, 1.0);
    std::pair<DisplayImage, HdrImage> out{readDisplayTexture(pass_->displayTexture(), pass_->width(), pass_->height()),
                                          readFloatTexture(pass_->lightTexture(), pass_->width(), pass_->height())};
    const GLuint textures[] = {display, hdr};
    glDeleteTextures(2, textures);
    return out;
  }

  // Both projectors' 8-bit images for a uniform channel image of display value n (and HDR
  // `light` cd/m^2).
  static std::vector<DisplayImage> projectUniform(float n, bool withBeta, float light = 1.0f) {
    const GLuint display = uniformTexture(GL_RGBA16F, kScreen, kRows, n);
    const GLuint hdr = uniformTexture(GL_RGBA32F, kScreen, kRows, light);
    std::vector<DisplayImage> images;
    for (int p = 0; p < 2; ++p) {
      const ProjectorMaps maps(*sideBySide(p, withBeta));
      pass_->draw(maps, display, hdr, kGamma, 1.0);
      images.push_back(readDisplayTexture(pass_->displayTexture(), pass_->width(), pass_->height()));
    }
    const GLuint textures[] = {display, hdr};
    glDeleteTextures(2, textures);
    return images;
  }

  // The light on the screen (relative to one projector's white) averaged over screen columns
  // [c0, c0 + w), all rows: the sum of what every projector covering it emits.
  static double screenLight(const std::vector<DisplayImage>& images, int c0, int w) {
    double sum = 0.0;
    for (int c = c0; c < c0 + w; ++c)
      for (int y = 0; y < kRows; ++y)
        for (int p = 0; p < 2; ++p) {
          const int x = c - firstColumn(p);
          if (x < 0 || x >= kProjector) continue;
          sum += emitted(images[static_cast<std::size_t>(p)].rgba[(static_cast<std::size_t>(y) * kProjector + x) * 4 + 1]);
        }
    return sum / (w * kRows);
  }

  // Across the overlap, every 4-column patch's light is within `tolerance` of one projector's.
  static void expectOverlapSumsToOneProjector(float n, double tolerance) {
    const std::vector<DisplayImage> images = projectUniform(n, true);
    const double single = screenLight(images, 0, 40);
    EXPECT_NEAR(screenLight(images, kScreen - 40, 40), single, tolerance * single);
    for (int c = kOverlapBegin; c < kOverlapEnd; c += 4)
      EXPECT_NEAR(screenLight(images, c, 4), single, tolerance * single) << "screen columns " << c << " to " << c + 3;
  }

  static inline GlContext* context_ = nullptr;
  static inline WarpBlendPass* pass_ = nullptr;
  static inline SkyRenderer* renderer_ = nullptr;
};

double luminance(const HdrImage& im, int x, int y) {
  const float* p = im.pixel(x, y);
  return shader::rec709Luminance(glm::dvec3(p[0], p[1], p[2]));
}

}  // namespace

// The blend formula as the GPU runs it, on the CPU: alphas that add up to 1 add the light of
// the projectors up to one projector's, whatever the gamma; blending the display values
// instead would not.
TEST(ProjectorBlend, AlphasAddUpInLightNotInDisplayValues) {
  for (double n : {0.05, 0.3, 0.7, 1.0})
    for (double a : {0.1, 0.25, 0.5}) {
      const double l0 = std::pow(shader::blendedDisplayValue(n, a, 0.0, kGamma), kGamma);
      const double l1 = std::pow(shader::blendedDisplayValue(n, 1.0 - a, 0.0, kGamma), kGamma);
      EXPECT_NEAR(l0 + l1, std::pow(n, kGamma), 1e-12 * std::pow(n, kGamma) + 1e-15);
      EXPECT_LT(std::pow(a * n, kGamma) + std::pow((1.0 - a) * n, kGamma), 0.9 * std::pow(n, kGamma));
    }
}

// Beta lifts black to beta and leaves white white; alpha 1 and beta 0 change nothing.
TEST(ProjectorBlend, BetaLiftsBlackAndKeepsWhite) {
  EXPECT_NEAR(std::pow(shader::blendedDisplayValue(0.0, 1.0, 0.002, kGamma), kGamma), 0.002, 1e-12);
  EXPECT_NEAR(shader::blendedDisplayValue(1.0, 1.0, 0.002, kGamma), 1.0, 1e-12);
  EXPECT_NEAR(shader::blendedDisplayValue(0.42, 1.0, 0.0, kGamma), 0.42, 1e-12);
  EXPECT_EQ(shader::blendedDisplayValue(0.42, 0.0, 0.0, kGamma), 0.0);
}

// A day-level sky (display value 0.7): the two projectors' light summed across the overlap is
// within 2% of one projector's.
TEST_F(WarpBlend, OverlapLightEqualsOneProjectorAtDayLevel) { expectOverlapSumsToOneProjector(0.7f, 0.02); }

// A night-level sky (display value 0.05, a few codes above black): the same, the black floor
// included.
TEST_F(WarpBlend, OverlapLightEqualsOneProjectorAtNightLevel) { expectOverlapSumsToOneProjector(0.05f, 0.02); }

// A black sky: with the beta map the overlap's black (two projectors' black) and the single
// projector's (its black plus the lift) match within one display step; without it the overlap
// is a band brighter by more than a step.
TEST_F(WarpBlend, BetaMatchesTheBlackOfOverlapAndSingleProjector) {
  const double lifted = 255.0 * shader::blendedDisplayValue(0.0, 1.0, kBlack, kGamma);
  const double step = emitted(lifted + 1.0) - emitted(lifted);
  const std::vector<DisplayImage> withBeta = projectUniform(0.0f, true);
  const double single = screenLight(withBeta, 0, 40);
  EXPECT_NEAR(single, 2.0 * kBlack, step);  // its own black and the lift
  for (int c = kOverlapBegin; c < kOverlapEnd; c += 8)
    EXPECT_NEAR(screenLight(withBeta, c, 8), single, step) << "screen columns " << c << " to " << c + 7;
  const std::vector<DisplayImage> noBeta = projectUniform(0.0f, false);
  EXPECT_GT(screenLight(noBeta, 96, 8) - screenLight(noBeta, 0, 40), step);
}

// The GPU's projector pixels are the CPU's blend formula of the channel's value, within the
// dither (+-1 LSB) and the rounding.
TEST_F(WarpBlend, ProjectorPixelsAreTheCpuBlend) {
  const float n = 0.6f;
  const std::vector<DisplayImage> images = projectUniform(n, true);
  for (int p = 0; p < 2; ++p)
    for (int x = 0; x < kProjector; x += 7) {
      const int column = firstColumn(p) + x;
      const double alpha = alphaAt(p, column);
      const double beta = alpha * kBlack * (inOverlap(column) ? 0.0 : 1.0);
      const double expected = 255.0 * shader::blendedDisplayValue(n, alpha, beta, kGamma);
      for (int y = 0; y < kRows; y += 13)
        EXPECT_NEAR(images[static_cast<std::size_t>(p)].rgba[(static_cast<std::size_t>(y) * kProjector + x) * 4], expected, 1.5)
            << "projector " << p << " pixel " << x << "," << y;
    }
}

// An alpha map of three components (MPCDI componentDepth 3): each colour of the projector blends
// with its own, red by 1, green by 0.5, blue by 0.2, and its light too.
TEST_F(WarpBlend, AThreeComponentAlphaBlendsEachColourByItsOwn) {
  auto c = sideBySide(0, false);
  const std::array<float, 3> weights{1.0f, 0.5f, 0.2f};
  c->alpha = {c->width, c->height, 3, {}};
  for (int i = 0; i < c->width * c->height; ++i) c->alpha.values.insert(c->alpha.values.end(), weights.begin(), weights.end());
  const float n = 0.6f;
  const auto [image, light] = projectOne(*c, n, 5000.0f);
  for (int ch = 0; ch < 3; ++ch) {
    const double expected = 255.0 * shader::blendedDisplayValue(n, weights[static_cast<std::size_t>(ch)], 0.0, kGamma);
    for (int x = 0; x < kProjector; x += 17)
      EXPECT_NEAR(image.rgba[(static_cast<std::size_t>(kRows / 2) * kProjector + x) * 4 + ch], expected, 1.5)
          << "channel " << ch << " pixel " << x;
    EXPECT_NEAR(light.rgba[(static_cast<std::size_t>(kRows / 2) * kProjector + 40) * 4 + ch],
                5000.0 * static_cast<double>(weights[static_cast<std::size_t>(ch)]), 1.0);
  }
}

// Where the warp has NaN the projector sends nothing: black, not even the black-level lift,
// and no light; the mapped pixels beside it are drawn.
TEST_F(WarpBlend, UnmappedPixelsAreBlack) {
  auto c = sideBySide(0, true);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 30; ++x) c->warp.at(x, y, 0) = c->warp.at(x, y, 1) = nan;
  const auto [image, light] = projectOne(*c, 0.7f, 5000.0f);
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < 40; ++x) {
      const std::uint8_t* px = &image.rgba[(static_cast<std::size_t>(y) * kProjector + x) * 4];
      if (y < 10 && x < 30) {
        EXPECT_EQ(px[0] + px[1] + px[2], 0) << x << "," << y;
        EXPECT_EQ(light.pixel(x, y)[1], 0.0f) << x << "," << y;
      } else {
        EXPECT_GT(px[1], 150) << x << "," << y;
        EXPECT_FLOAT_EQ(light.pixel(x, y)[1], 5000.0f) << x << "," << y;
      }
    }
}

// A warp map coarser than the projector (13 samples across 120 pixels) is interpolated: the
// same image as the full map, where the warp is linear.
TEST_F(WarpBlend, CoarseWarpMapIsInterpolatedToTheProjector) {
  const GLuint display = uniformTexture(GL_RGBA16F, kScreen, kRows, 0.0f);
  // A ramp across the channel image, so where each pixel reads shows.
  std::vector<float> ramp(static_cast<std::size_t>(kScreen) * kRows * 4);
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < kScreen; ++x)
      for (int ch = 0; ch < 4; ++ch) ramp[(static_cast<std::size_t>(y) * kScreen + x) * 4 + ch] = (static_cast<float>(x) + 0.5f) / static_cast<float>(kScreen);
  glTextureSubImage2D(display, 0, 0, 0, kScreen, kRows, GL_RGBA, GL_FLOAT, ramp.data());
  const GLuint hdr = uniformTexture(GL_RGBA32F, kScreen, kRows, 1.0f);
  std::vector<DisplayImage> images;
  for (int columns : {kProjector, 13}) {
    const ProjectorMaps maps(*sideBySide(1, false, columns));
    pass_->draw(maps, display, hdr, kGamma, 0.0);
    images.push_back(readDisplayTexture(pass_->displayTexture(), pass_->width(), pass_->height()));
  }
  const GLuint textures[] = {display, hdr};
  glDeleteTextures(2, textures);
  int worst = 0;
  for (std::size_t i = 0; i < images[0].rgba.size(); ++i)
    worst = std::max(worst, std::abs(images[0].rgba[i] - images[1].rgba[i]));
  EXPECT_LE(worst, 1);
  // And the full map reads the channel where it says: projector 1's last pixel, column 199.
  EXPECT_NEAR(images[0].rgba[(kProjector - 1) * 4], 255.0 * shader::blendedDisplayValue(199.5 / kScreen, 1.0, 0.0, kGamma), 1.0);
}

// An identity warp (the projector's pixels are the channel's) with no blend reproduces the
// channel's own frame: the same 8-bit image within the rounding, the same HDR light.
TEST_F(WarpBlend, IdentityWarpReproducesTheChannelImage) {
  sky::ChannelConfig channel;
  channel.width = 160;
  channel.height = 120;
  channel.frustum = sky::Frustum{40, 40, 30, 30};
  channel.offset.pitchDeg = 20.0;
  auto c = std::make_shared<ProjectorCalibration>();
  c->width = channel.width;
  c->height = channel.height;
  c->camera = {channel.offset, channel.frustum};
  c->cameraGiven = true;
  c->warp = FloatMap{c->width, c->height, 2, std::vector<float>(static_cast<std::size_t>(c->width) * c->height * 2)};
  for (int y = 0; y < c->height; ++y)
    for (int x = 0; x < c->width; ++x) {
      c->warp.at(x, y, 0) = (static_cast<float>(x) + 0.5f) / static_cast<float>(c->width);
      c->warp.at(x, y, 1) = (static_cast<float>(y) + 0.5f) / static_cast<float>(c->height);
    }
  sky::ObserverState o;
  o.attitude = {30.0, 0.0, 0.0};
  const sky::SkyState s = sky::buildSkyState(o, {}, sky::SunOverride{250.0, 8.0});
  renderer_->draw(s, channel);
  const DisplayImage direct = renderer_->readDisplay();
  const HdrImage directHdr = renderer_->readHdr();
  renderer_->drawProjector(s, channel, c);
  const DisplayImage projected = renderer_->readProjectorDisplay();
  const HdrImage projectedHdr = renderer_->readProjectorHdr();
  ASSERT_EQ(projected.width, direct.width);
  ASSERT_EQ(projected.height, direct.height);
  int worst = 0;
  for (std::size_t i = 0; i < direct.rgba.size(); ++i) worst = std::max(worst, std::abs(direct.rgba[i] - projected.rgba[i]));
  EXPECT_LE(worst, 1);
  double worstRelative = 0.0;
  for (int y = 0; y < c->height; ++y)
    for (int x = 0; x < c->width; ++x)
      worstRelative = std::max(worstRelative, std::abs(luminance(projectedHdr, x, y) / luminance(directHdr, x, y) - 1.0));
  EXPECT_LT(worstRelative, 1e-4);
}

// The light images of two projectors side by side (the channel's cd/m^2 warped, times alpha)
// add up, on every screen point, to the sky's luminance there.
TEST_F(WarpBlend, ProjectorsLightAddsUpToTheSky) {
  sky::ChannelConfig channel;
  channel.width = kScreen;
  channel.height = kRows;
  channel.frustum = sky::Frustum{50, 50, 10, 10};
  sky::ObserverState o;
  o.attitude = {0.0, 0.0, 0.0};
  const sky::SkyState s = sky::buildSkyState(o, {}, sky::SunOverride{150.0, 30.0});
  std::vector<HdrImage> light;
  for (int p = 0; p < 2; ++p) {
    auto c = sideBySide(p, true);
    c->camera = {channel.offset, channel.frustum};
    c->cameraGiven = true;
  c->cameraGiven = true;
    renderer_->drawProjector(s, channel, c);
    light.push_back(renderer_->readProjectorHdr());
  }
  renderer_->draw(s, channel);
  const HdrImage sky = renderer_->readHdr();
  double worst = 0.0;
  for (int y = 0; y < kRows; ++y)
    for (int column = 0; column < kScreen; ++column) {
      double sum = 0.0;
      for (int p = 0; p < 2; ++p) {
        const int x = column - firstColumn(p);
        if (x >= 0 && x < kProjector) sum += luminance(light[static_cast<std::size_t>(p)], x, y);
      }
      worst = std::max(worst, std::abs(sum / luminance(sky, column, y) - 1.0));
    }
  EXPECT_LT(worst, 1e-3);
}

// The same warp written as absolute coordinates and as offsets from the grid (the two PFM
// conventions, tests/data/calibration), read by the loader, sends the projector the same image.
TEST_F(WarpBlend, BothPfmConventionsSendTheSameImage) {
  const std::string dir = std::string(SKYIG_SOURCE_DIR) + "/tests/data/calibration/";
  sky::ChannelConfig channel;
  channel.width = 96;
  channel.height = 64;
  channel.frustum = sky::Frustum{40, 40, 25, 25};
  const sky::SkyState s = sky::buildSkyState(sky::ObserverState{}, {}, sky::SunOverride{200.0, 25.0});
  std::vector<DisplayImage> images;
  for (const auto& source : {calibration::mpcdiSource(dir + "warp_absolute.mpcdi", "p1", calibration::WarpValues::Absolute),
                             calibration::mpcdiSource(dir + "warp_offset", "p1", calibration::WarpValues::Offset)}) {
    const auto projector = std::make_shared<const ProjectorCalibration>(calibration::loadProjector(source));
    renderer_->drawProjector(s, channel, projector);
    images.push_back(renderer_->readProjectorDisplay());
  }
  ASSERT_EQ(images[0].width, images[1].width);
  int worst = 0, lit = 0;
  for (std::size_t i = 0; i < images[0].rgba.size(); ++i) {
    worst = std::max(worst, std::abs(images[0].rgba[i] - images[1].rgba[i]));
    if (i % 4 == 1 && images[0].rgba[i] > 20) ++lit;
  }
  EXPECT_LE(worst, 1);
  EXPECT_GT(lit, images[0].width * images[0].height / 2);  // and it is not black
}
