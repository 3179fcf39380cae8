// The goggle channel on the GL path (llvmpipe where there is no GPU): the image intensifier
// (render/passes/goggle/goggle_pass.h) fed scenes of known NVIS radiance, and whole goggle channels of
// the sky drawn by SkyRenderer against the probe's NVIS radiance.
#include "render/gl/gl_context.h"
#include "render/gl/render_target.h"
#include "render/passes/goggle/goggle_pass.h"
#include "render/sky_renderer.h"
#include "tests/render/shared_renderer_test.h"
#include "render/glsl/uniforms.h"
#include "physics/goggle/goggle_physics.h"
#include "sky/night_probe.h"
#include "physics/goggle/night_spectra.h"
#include "sky/nvis_weights.h"
#include "sky/fog_state.h"
#include "sky/sky_state.h"
#include "physics/weather/weather_physics.h"
#include "tests/physics/atmosphere/shared_models.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <numbers>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;

namespace {

using skyig::kDeg;
constexpr int kW = 480, kH = 400;  // the tube's field: a circle of 200 pixels' radius, 0.104 deg a pixel

// The natural illuminance of the ground at night (RCA Electro-Optics Handbook, 1974, the table
// the NVG literature quotes): full moon 1e-1 lux, quarter moon 1e-2, clear starlight 1e-3,
// overcast starlight 1e-4.
struct Night {
  const char* name;
  double lux;
  bool moonlit;
};
constexpr Night kNights[] = {{"full moon", 1e-1, true}, {"quarter moon", 1e-2, true},
                             {"clear starlight", 1e-3, false}, {"overcast starlight", 1e-4, false}};

// The class A NVIS radiance of grass and soil of reflectance 0.3 under that light: by moonlight,
// or by the moonless sky, whose light is mostly the airglow's in the goggles' band.
double sceneNvis(const Night& n) {
  const nvis::Spectrum& s = n.moonlit ? nvis::moonlightSpectrum() : nvis::airglowSpectrum();
  return 0.3 / std::numbers::pi * nvis::nvisFromLuminance(s, nvis::unitTransmittance(), n.lux).a;
}

ChannelConfig goggleChannel() {
  ChannelConfig c;
  c.name = "nvg";
  c.width = kW;
  c.height = kH;
  c.band = SpectralBand::NvisClassA;
  c.goggle.nvisClass = SpectralBand::NvisClassA;
  return c;
}

struct Screen {
  std::vector<float> rgba;  // GL rows, bottom first
  double y(int x, int yy) const {
    const float* p = &rgba[(static_cast<std::size_t>(yy) * kW + static_cast<std::size_t>(x)) * 4];
    return 0.2126 * static_cast<double>(p[0]) + 0.7152 * static_cast<double>(p[1]) + 0.0722 * static_cast<double>(p[2]);
  }
};

// Pixels of the field within `fromPx` to `toPx` of its centre.
template <typename F>
void forRing(double fromPx, double toPx, F&& f) {
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double r = std::hypot(x + 0.5 - 0.5 * kW, y + 0.5 - 0.5 * kH);
      if (r >= fromPx && r < toPx) f(x, y);
    }
}

class GogglePassGl : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    pass_ = new GogglePass();
    input_ = new RenderTarget(kW, kH, GL_RGBA32F);
    screen_ = new RenderTarget(kW, kH, GL_RGBA32F);
  }
  static void TearDownTestSuite() {
    delete screen_;
    delete input_;
    delete pass_;
    delete context_;
  }

  // The screen (cd/m^2) for an NVIS image given per pixel (W m^-2 sr^-1).
  static Screen draw(const std::vector<float>& nvis, std::uint32_t seed, const ChannelConfig& c = goggleChannel()) {
    std::vector<float> rgba(nvis.size() * 4, 1.0f);
    for (std::size_t i = 0; i < nvis.size(); ++i) rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = nvis[i];
    glTextureSubImage2D(input_->texture(), 0, 0, 0, kW, kH, GL_RGBA, GL_FLOAT, rgba.data());
    pass_->draw(input_->texture(), c, nvisPerLuxOfBlackbody(kIlluminantAKelvin, nvis::NvisClass::A), seed, *screen_, true);
    Screen s{std::vector<float>(static_cast<std::size_t>(kW) * kH * 4)};
    glGetTextureImage(screen_->texture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(s.rgba.size() * sizeof(float)), s.rgba.data());
    return s;
  }
  static std::vector<float> uniformField(double nvis) { return std::vector<float>(static_cast<std::size_t>(kW) * kH, static_cast<float>(nvis)); }
  // A uniform field with a moon-sized disc (radius 0.26 deg, 2.5 pixels) at the centre giving
  // the full moon's NVIS irradiance (0.1 lux of moonlight above the air).
  static std::vector<float> fieldWithMoon(double background) {
    std::vector<float> f = uniformField(background);
    const double radiusRad = 0.26 * kDeg;
    const double radiance =
        nvis::nvisFromLuminance(nvis::moonlightSpectrum(), nvis::unitTransmittance(), 0.1).a / (std::numbers::pi * radiusRad * radiusRad);
    const double radiusPx = radiusRad / goggleGeometry(goggleChannel()).pixelAngleRad;
    forRing(0.0, radiusPx, [&](int x, int y) { f[static_cast<std::size_t>(y) * kW + x] = static_cast<float>(radiance); });
    return f;
  }

  static inline GlContext* context_ = nullptr;
  static inline GogglePass* pass_ = nullptr;
  static inline RenderTarget* input_ = nullptr;
  static inline RenderTarget* screen_ = nullptr;
};

struct FieldStats {
  double mean = 0.0, relativeSigma = 0.0;
};
FieldStats stats(const Screen& s, double fromPx, double toPx) {
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  forRing(fromPx, toPx, [&](int x, int y) {
    const double v = s.y(x, y);
    sum += v;
    sum2 += v * v;
    ++n;
  });
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(sum2 / n - mean * mean, 0.0)) / mean};
}

}  // namespace

// From full moon to overcast starlight the scene's light falls a thousandfold. The automatic
// brightness control holds the screen's mean at its level (8.57 cd/m^2, 2.5 fL) while the
// tube's full gain would pass it, and never lets it above; below that the gain is at its
// maximum and the screen dims with the scene, to a level the display still shows above black.
TEST_F(GogglePassGl, AutomaticBrightnessKeepsTheScreenInItsRangeFromFullMoonToOvercastStarlight) {
  double previous = 1e30;
  for (const Night& n : kNights) {
    const Screen s = draw(uniformField(sceneNvis(n)), 7u);
    const double mean = stats(s, 0.0, 0.95 * kH / 2).mean;
    const double cathodeLux = shader::cathodeIlluminance(sceneNvis(n) / nvisPerLuxOfBlackbody(kIlluminantAKelvin, nvis::NvisClass::A));
    const bool aboveKnee = cathodeLux * shader::kMaxLuminanceGain > shader::kAbcScreenCdM2;
    std::cout << n.name << ": scene " << sceneNvis(n) << " W m^-2 sr^-1, cathode " << cathodeLux << " lux, gain "
              << pass_->readGain() << " cd/m^2/lux, screen " << mean << " cd/m^2\n";
    // The control's gain: the one that holds the mean where the full gain would pass it (no
    // pixel saturates in a uniform scene), the full gain below.
    const double gain = pass_->readGain();
    if (aboveKnee) {
      EXPECT_NEAR(mean, shader::kAbcScreenCdM2, 0.03 * shader::kAbcScreenCdM2) << n.name;
      EXPECT_NEAR(gain, shader::kAbcScreenCdM2 / cathodeLux, 0.02 * gain) << n.name;
    } else {
      EXPECT_NEAR(mean, cathodeLux * shader::kMaxLuminanceGain, 0.05 * mean) << n.name;
      EXPECT_NEAR(gain, shader::kMaxLuminanceGain, 1e-4 * gain) << n.name;
    }
    EXPECT_LE(mean, 1.03 * shader::kAbcScreenCdM2) << n.name;
    EXPECT_LT(mean, previous) << n.name;
    // On the default display (0.1 cd/m^2 ambient, 100 cd/m^2 peak, gamma 2.2) the dimmest
    // screen is still above the 8-bit display's first codes.
    EXPECT_GT(std::pow(mean / 100.0, 1.0 / 2.2) * 255.0, 4.0) << n.name;
    previous = mean;
  }
}

// The screen's grain is the photoelectrons' shot noise times the plate's excess noise factor:
// its relative deviation is sqrt(F / N) for N photoelectrons in a pixel and a frame, which
// grows as light falls: checked against that closed form from full moon (hundreds of electrons)
// to overcast starlight (one or two, where the count's discreteness is the scintillation).
TEST_F(GogglePassGl, NoiseGrowsAsLightFalls) {
  const GoggleGeometry g = goggleGeometry(goggleChannel());
  double previous = 0.0;
  for (const Night& n : kNights) {
    const Screen s = draw(uniformField(sceneNvis(n)), 11u);
    const FieldStats f = stats(s, 0.0, 0.9 * kH / 2);
    const double lux = shader::cathodeIlluminance(sceneNvis(n) / nvisPerLuxOfBlackbody(kIlluminantAKelvin, nvis::NvisClass::A));
    const double electrons = lux * g.electronsPerLux;
    const double expected = std::sqrt(shader::kExcessNoiseFactor / electrons);
    std::cout << n.name << ": " << electrons << " photoelectrons a pixel and frame, relative deviation " << f.relativeSigma
              << " (sqrt(F/N) " << expected << ")\n";
    EXPECT_NEAR(f.relativeSigma, expected, 0.1 * expected) << n.name;
    EXPECT_GT(f.relativeSigma, previous) << n.name;
    previous = f.relativeSigma;
  }
}

// The halo: a full moon's light in a disc of 0.26 deg at the centre. Its halo is a fixed share
// of its light, but the gain that lets the scene show rises as the scene darkens, so the halo
// outshines the scene farther out: its visible radius (where the screen is twice the scene's)
// grows as light falls, up to the reach of the halo's Gaussian (3 sigma, 1.35 deg) beyond the
// moon's edge, and the blocks it is computed on (1.5 of them, at most 8 pixels each: 1.25 deg
// at this channel's 0.104 deg pixels).
TEST_F(GogglePassGl, HaloGrowsAsLightFalls) {
  const GoggleGeometry g = goggleGeometry(goggleChannel());
  double previous = 0.0;
  std::vector<double> radii;
  for (const Night& n : kNights) {
    // The mean of four frames, so the grain of starlight does not decide the edge.
    std::vector<double> sum(static_cast<std::size_t>(kW) * kH, 0.0);
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      const Screen s = draw(fieldWithMoon(sceneNvis(n)), seed);
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) sum[static_cast<std::size_t>(y) * kW + x] += 0.25 * s.y(x, y);
    }
    double background = 0.0;
    int count = 0;
    forRing(0.6 * kH / 2, 0.8 * kH / 2, [&](int x, int y) {
      background += sum[static_cast<std::size_t>(y) * kW + x];
      ++count;
    });
    background /= count;
    double visible = 0.0;
    for (double r = 0.0; r < 60.0; r += 1.0) {
      double ring = 0.0;
      int m = 0;
      forRing(r, r + 1.0, [&](int x, int y) {
        ring += sum[static_cast<std::size_t>(y) * kW + x];
        ++m;
      });
      if (ring / m > 2.0 * background) visible = r + 1.0;
    }
    const double visibleDeg = visible * g.pixelAngleRad / kDeg;
    std::cout << n.name << ": halo visible out to " << visibleDeg << " deg (" << visible << " px)\n";
    RecordProperty(std::string("halo_deg_") + (n.moonlit ? (n.lux > 0.05 ? "full_moon" : "quarter_moon") : (n.lux > 5e-4 ? "clear_starlight" : "overcast")),
                   std::to_string(visibleDeg));
    EXPECT_GE(visible, previous) << n.name;
    EXPECT_LE(visibleDeg, 3.0 * shader::kHaloSigmaDeg + 0.26 + 1.5 * 8.0 * g.pixelAngleRad / kDeg) << n.name;
    previous = visible;
    radii.push_back(visibleDeg);
  }
  EXPECT_GT(radii.back(), radii.front() + 0.3);
}

// The same frame drawn again (a replay) is the same to the bit; another seed (another frame)
// is not.
TEST_F(GogglePassGl, AFrameDrawnAgainIsTheSameToTheBit) {
  const std::vector<float> scene = fieldWithMoon(sceneNvis(kNights[2]));
  const Screen a = draw(scene, 42u), b = draw(scene, 42u), c = draw(scene, 43u);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_NE(a.rgba, c.rgba);
}

// Outside the tube's circle the goggle shows its housing: black.
TEST_F(GogglePassGl, OutsideTheFieldIsBlack) {
  const Screen s = draw(uniformField(sceneNvis(kNights[0])), 1u);
  forRing(0.5 * kH + 1.0, 1e9, [&](int x, int y) { ASSERT_EQ(s.y(x, y), 0.0) << x << "," << y; });
  EXPECT_GT(stats(s, 0.0, 0.5 * kH - 2.0).mean, 1.0);
}

namespace {

std::shared_ptr<const atmosphere::AtmosphereModel> tinyModel() { return atmosphere::testing::tinyNightModel(); }

// A dark site in the Alps (2000 m) on the moonless night of 18 January 2026, sun 30 deg down.
SkyState alpsMoonless(double extraSeconds = 0.0) {
  ObserverState o;
  o.latitudeDeg = 47.26;
  o.longitudeDeg = 11.34;
  o.heightM = 2000.0;
  o.utc = {2026, 1, 18, 20.0 * 3600.0 + extraSeconds};
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = tinyModel();
  return buildSkyState(o, c);
}

}  // namespace

class GoggleChannelGl : public skyig::render::testing::SharedRendererTest {};

// One model for the eye and the goggle: a goggle channel's image is, pixel by pixel, the NVIS
// radiance `skyig probe` reports for the same view (the sum of its lights but the stars, which
// are left out of the state here, and the moon, which is down).
TEST_F(GoggleChannelGl, ImageIsTheProbesNvisRadiance) {
  SkyState s = alpsMoonless();
  s.starField = nullptr;
  ChannelConfig c = goggleChannel();
  c.width = 64;
  c.height = 48;
  c.offset = {180.0, 40.0, 0.0};
  renderer_->draw(s, Attitude{0.0, 0.0, 0.0}, c);
  const HdrImage hdr = renderer_->readHdr();
  const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{0.0, 0.0, 0.0}, c.offset), goggleFrustum(c));
  atmosphere::ProbeRequest request;
  request.altitudeM = s.observer.heightM;
  for (auto [x, y] : {std::pair{32, 24}, {20, 10}, {44, 38}}) {
    const glm::dvec3 v = glm::normalize(pixelRay(m, x, y, c.width, c.height));
    request.views.push_back({90.0 - std::asin(v.z) / kDeg, std::atan2(v.x, v.y) / kDeg});
  }
  const NightProbeResult probe = nightProbe(*tinyModel(), s, request);
  int i = 0;
  for (auto [x, y] : {std::pair{32, 24}, {20, 10}, {44, 38}}) {
    double expected = 0.0;
    for (const NamedProbeLight& l : probe.views[static_cast<std::size_t>(i)].lights)
      if (l.name != "total" && l.name != "stars_planets") expected += l.nvis.a;
    const float* p = hdr.pixel(x, y);
    std::cout << "pixel " << x << "," << y << ": goggle " << p[1] << " W m^-2 sr^-1, probe " << expected << "\n";
    EXPECT_NEAR(static_cast<double>(p[1]), expected, 0.05 * expected) << x << "," << y;
    EXPECT_EQ(p[0], p[1]);
    EXPECT_EQ(p[2], p[1]);
    ++i;
  }
}

// A replay draws the same goggle frame to the bit, on another renderer too (another node); the
// next second of the night is another frame of noise.
TEST_F(GoggleChannelGl, ReplayedFramesAreBitIdentical) {
  const SkyState s = alpsMoonless(), later = alpsMoonless(1.0);
  ChannelConfig c = goggleChannel();
  c.width = 96;
  c.height = 80;
  c.offset = {90.0, 20.0, 0.0};
  renderer_->draw(s, c);
  const DisplayImage first = renderer_->readDisplay();
  SkyRenderer other;
  other.draw(s, c);
  const DisplayImage again = other.readDisplay();
  EXPECT_EQ(first.rgba, again.rgba);
  renderer_->draw(later, c);
  EXPECT_NE(renderer_->readDisplay().rgba, first.rgba);
}

namespace {

// A full moon 64 deg up over Innsbruck (24 December 2026, 23:00 UTC) under a broken
// stratocumulus deck, 50 % cover from 1500 to 2000 m.
SkyState fullMoonUnderABrokenDeck() {
  ObserverState o;
  o.latitudeDeg = 47.26;
  o.longitudeDeg = 11.34;
  o.heightM = 600.0;
  o.utc = {2026, 12, 24, 23.0 * 3600.0};
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = tinyModel();
  CloudLayer& deck = c.clouds[0];
  deck.enabled = true;
  deck.type = CloudType::Stratocumulus;
  deck.baseM = 1500.0;
  deck.thicknessM = 500.0;
  deck.coveragePct = 50.0;
  SkyState s = buildSkyState(o, c);
  s.starField = nullptr;  // the stars are point sources of their own (their test is the star field's)
  return s;
}

// A fog table's entry for a view of cosine mu to the vertical, read as the sky pass's sampler1D
// reads it (linear between texel centres, fogTableU's axis).
glm::dvec4 tableAt(const std::vector<glm::vec4>& table, double mu) {
  const double x = skyig::shader::fogTableU(mu) * static_cast<double>(table.size()) - 0.5;
  const double i = std::clamp(std::floor(x), 0.0, static_cast<double>(table.size() - 2));
  const double f = std::clamp(x - i, 0.0, 1.0);
  const auto k = static_cast<std::size_t>(i);
  return glm::mix(glm::dvec4(table[k]), glm::dvec4(table[k + 1]), f);
}

}  // namespace

// Under a moonlit broken deck the goggle's image is the probe's NVIS radiance composed with the
// deck as the field has it: in a gap the clear sky's (the probe's lights), behind a cloud the
// deck's own light (its moonlit top's light through it, weighed as moonlight: sky/nvis_weights.h)
// and the little of the moonlit sky behind it its transmittance lets through, and the night's
// light (airglow, zodiacal light, the Milky Way) as the probe has it on each view: behind the
// cloud or in a gap. The goggle agrees with those figures within 5 %.
TEST_F(GoggleChannelGl, UnderAMoonlitBrokenDeckTheImageIsTheProbesNvisRadianceThroughTheDeck) {
  const SkyState s = fullMoonUnderABrokenDeck();
  ASSERT_TRUE(s.fog.broken());
  ASSERT_TRUE(s.fog.tables.nvisA && s.fog.tables.clearNvisA);
  ChannelConfig c = goggleChannel();
  c.width = 64;
  c.height = 48;
  c.offset = {320.0, 60.0, 0.0};  // north-west, away from the moon in the south-east
  renderer_->draw(s, Attitude{0.0, 0.0, 0.0}, c);
  const HdrImage hdr = renderer_->readHdr();
  const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{0.0, 0.0, 0.0}, c.offset), goggleFrustum(c));
  const atmosphere::AtmosphereModel& model = *tinyModel();
  const double h = glm::length(atmosphere::physicalCamera(model, s.observer.heightM)) - model.parameters(0).bottom_radius;

  // Every 4th pixel inside the tube's circle, sorted into cloud and gap by the deck's field.
  struct Pixel {
    int x, y;
    glm::dvec3 view;
    double share;
  };
  std::vector<Pixel> cloud, gap;
  for (int y = 2; y < c.height; y += 4)
    for (int x = 2; x < c.width; x += 4) {
      if (std::hypot(x + 0.5 - 0.5 * c.width, y + 0.5 - 0.5 * c.height) > 0.45 * c.height) continue;
      const glm::dvec3 v = glm::normalize(pixelRay(m, x, y, c.width, c.height));
      const double t = decksTransmittanceAlong(s.fog, h, glm::dvec2(0.0), v);
      if (t < 1e-3) cloud.push_back({x, y, v, 1.0});
      if (t > 1.0 - 1e-3) gap.push_back({x, y, v, 0.0});
    }
  std::cout << cloud.size() << " pixels behind cloud, " << gap.size() << " in gaps\n";
  ASSERT_GE(cloud.size(), 5u);
  ASSERT_GE(gap.size(), 5u);

  auto check = [&](const std::vector<Pixel>& pixels, const char* where) {
    atmosphere::ProbeRequest request;
    request.altitudeM = s.observer.heightM;
    for (const Pixel& p : pixels) request.views.push_back({90.0 - std::asin(p.view.z) / kDeg, std::atan2(p.view.x, p.view.y) / kDeg});
    const NightProbeResult probe = nightProbe(model, s, request);
    double goggleSum = 0.0, worst = 0.0, behind = 0.0;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      double sky = 0.0, night = 0.0;  // the air's light (the layers in front of it), the night's own
      for (const NamedProbeLight& l : probe.views[i].lights) {
        if (l.name == "sunlit_sky" || l.name == "moonlit_sky") sky += l.nvis.a;
        if (l.name == "airglow" || l.name == "zodiacal_light" || l.name == "milky_way") night += l.nvis.a;
      }
      const glm::dvec4 fog = glm::mix(tableAt(*s.fog.tables.clearNvisA, pixels[i].view.z),
                                      tableAt(*s.fog.tables.nvisA, pixels[i].view.z), pixels[i].share);
      const double expected = sky * fog.a + skyig::shader::rec709Luminance(glm::dvec3(fog)) + night;
      const double goggle = static_cast<double>(hdr.pixel(pixels[i].x, pixels[i].y)[1]);
      worst = std::max(worst, std::abs(goggle / expected - 1.0));
      behind = std::max(behind, sky * fog.a / expected);
      EXPECT_NEAR(goggle, expected, 0.05 * expected) << where << " pixel " << pixels[i].x << "," << pixels[i].y;
      goggleSum += goggle;
    }
    std::cout << where << ": goggle " << goggleSum / static_cast<double>(pixels.size())
              << " W m^-2 sr^-1 on average, worst " << 100.0 * worst << " % from the probe's figures; the air behind "
              << 100.0 * behind << " % of it at most\n";
    return behind;
  };
  EXPECT_LT(check(cloud, "behind cloud"), 1e-3) << "a deck 25 optical depths thick hides the moonlit sky behind it";
  EXPECT_GT(check(gap, "in the gaps"), 0.5) << "in a gap the moonlit sky is most of the light";
}
