// Stars and planets on the display, through the whole renderer on the real GL path (llvmpipe
// where there is no GPU): the displayed star keeps the visibility the eye has of it against the
// sky behind it (physics/eye/point_source_visibility.glsl, docs/night-sky-stars.md), so a star
// at the threshold just appears, brighter ones rank by magnitude, and the result does not depend
// on the channel's resolution.
#include "render/image_io.h"
#include "render/sky_renderer.h"
#include "physics/stars/star_physics.h"
#include "tests/physics/night/night_gl_fixture.h"
#include "tests/physics/night/star_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using skyig::night_testing::kDeg;

namespace {

class StarDisplay : public night_testing::NightGlTest {
 protected:
  // The physical sky over Innsbruck; at a chosen sun altitude (no moon, no diffuse night light)
  // or, without one, on the moonless night of 2026-01-18 21:00 UTC with the night light.
  static SkyState sky(std::optional<double> sunAltitudeDeg = std::nullopt) {
    SkyConditions c;
    c.model = SkyModel::Physical;
    c.atmosphere = *model_;
    ObserverState o;
    o.utc = {2026, 1, 18, 21 * 3600.0};
    o.attitude = Attitude{180.0, 0.0, 0.0};
    if (sunAltitudeDeg) return buildSkyState(o, c, SunOverride{0.0, *sunAltitudeDeg});
    return buildSkyState(o, c);
  }

  static ChannelConfig channel(int width, int height, Frustum frustum = Frustum{20, 20, 15, 15}) {
    ChannelConfig ch;
    ch.width = width;
    ch.height = height;
    ch.frustum = frustum;
    ch.offset = Attitude{0.0, 40.0, 0.0};  // the middle of the view at 40 degrees up, due south
    return ch;
  }

  static night::PointSource source(double azimuthDeg, double altitudeDeg, double magnitude) {
    const double az = azimuthDeg * kDeg, alt = altitudeDeg * kDeg;
    night::PointSource s;
    s.direction = {std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
    s.illuminanceLux = shader::illuminanceOfMagnitude(magnitude);
    s.rec709Lux = glm::dvec3(s.illuminanceLux);  // white: Y of (1, 1, 1) is 1
    return s;
  }

  struct Frame {
    HdrImage points;       // display cd/m^2 added by the stars
    DisplayImage display;  // the 8-bit frame
    glm::dmat3 ndcToWorld;
  };

  static Frame render(SkyState state, const std::vector<night::PointSource>& stars, const ChannelConfig& ch) {
    auto field = std::make_shared<night::StarField>();
    field->stars = stars;
    state.starField = field;
    renderer_->draw(state, ch);
    return {renderer_->readPointSources(), renderer_->readDisplay(),
            ndcToWorld(eyeToEnu(state.observer.attitude, ch.offset), ch.frustum)};
  }

  static glm::dvec2 pixelOf(const Frame& f, const glm::dvec3& direction) {
    const glm::dvec3 p = glm::inverse(f.ndcToWorld) * direction;
    const glm::dvec2 ndc(p.x / p.z, p.y / p.z);
    return {(ndc.x * 0.5 + 0.5) * f.points.width, (0.5 - ndc.y * 0.5) * f.points.height};  // rows from the top
  }

  // sum(display luminance x pixel solid angle) within `radiusDeg` of `direction`: the displayed
  // illuminance at the viewer, lux.
  static double displayedLux(const Frame& f, const glm::dvec3& direction, double radiusDeg = 0.5) {
    const double pixelArea = 4.0 / (static_cast<double>(f.points.width) * f.points.height);
    double sum = 0.0;
    for (int y = 0; y < f.points.height; ++y)
      for (int x = 0; x < f.points.width; ++x) {
        const glm::dvec2 ndc((x + 0.5) * 2.0 / f.points.width - 1.0, 1.0 - (y + 0.5) * 2.0 / f.points.height);
        const glm::dvec3 ray = glm::normalize(f.ndcToWorld * glm::dvec3(ndc, 1.0));
        if (glm::dot(ray, direction) < std::cos(radiusDeg * kDeg)) continue;
        const float* p = f.points.pixel(x, y);
        sum += shader::rec709Luminance(glm::dvec3(p[0], p[1], p[2])) * shader::pixelSolidAngle(f.ndcToWorld, ndc, pixelArea);
      }
    return sum;
  }

  // The display luminance (cd/m^2) of the frame around `direction`: eq. 18 inverted, averaged
  // over 9 x 9 pixels (the dither is +-1 LSB).
  static double displayedSky(const Frame& f, const glm::dvec3& direction, const ChannelConfig& ch) {
    const glm::dvec2 px = pixelOf(f, direction);
    double n = 0.0;
    for (int y = static_cast<int>(px.y) - 4; y <= static_cast<int>(px.y) + 4; ++y)
      for (int x = static_cast<int>(px.x) - 4; x <= static_cast<int>(px.x) + 4; ++x)
        n += f.display.rgba[(static_cast<std::size_t>(y) * f.display.width + x) * 4 + 1] / 255.0 / 81.0;
    return ch.display.ambientLuminance + ch.display.maxLuminance * std::pow(n, ch.display.gamma);
  }

  // The display's threshold (lux) and slope where `direction` lands on a displayed sky of
  // `displayedCdM2`, as the displayed-star pass computes them (physics/eye/point_source_visibility.glsl).
  struct Law {
    double thresholdLux, exponent;
  };
  static Law displayLaw(const Frame& f, const glm::dvec3& direction, double displayedCdM2, const ChannelConfig& ch) {
    const glm::dvec3 p = glm::inverse(f.ndcToWorld) * direction;
    const glm::dvec2 ndc(p.x / p.z, p.y / p.z);
    const double pixelSr = shader::pixelSolidAngle(f.ndcToWorld, ndc, 4.0 / (static_cast<double>(ch.width) * ch.height));
    const double sigmaPx = std::max(shader::kDisplayedPsfSigmaRad / std::sqrt(pixelSr), shader::kDisplayedPsfMinSigmaPx);
    const double peakSr = shader::starPsfPeakSolidAngle(pixelSr, sigmaPx);
    const DisplayParams& d = ch.display;
    const double step = shader::displayThresholdStep(displayedCdM2, d.ambientLuminance, d.maxLuminance, d.gamma);
    const double threshold = shader::displayedThresholdLux(displayedCdM2, step, peakSr);
    const double range = shader::maxDisplayVisibility(displayedCdM2, d.ambientLuminance + d.maxLuminance, threshold, peakSr);
    return {threshold, shader::displayedVisibilityExponent(range)};
  }

  // The sky's luminance (cd/m^2, without stars) in `direction`.
  static double skyLuminance(const SkyState& state, const ChannelConfig& ch, const glm::dvec3& direction) {
    SkyState bare = state;
    bare.starField = nullptr;
    renderer_->draw(bare, ch);
    const HdrImage hdr = renderer_->readHdr();
    Frame f{hdr, {}, ndcToWorld(eyeToEnu(state.observer.attitude, ch.offset), ch.frustum)};
    const glm::dvec2 px = pixelOf(f, direction);
    const float* p = hdr.pixel(static_cast<int>(px.x), static_cast<int>(px.y));
    return shader::rec709Luminance(glm::dvec3(p[0], p[1], p[2]));
  }

};

}  // namespace

// Eight stars of magnitude -4 to 5 at 40 degrees up on a moonless night: each brighter star
// shows more light, and the ratio of two stars' displayed illuminances is the ratio of their
// displayed visibilities (kept up to the knee, compressed with the slope s above it, as the
// default display's range allows on the displayed sky around them; docs/night-sky-stars.md).
TEST_F(StarDisplay, DisplayedStarContrastRanksWithMagnitude) {
  const SkyState night = sky();
  const double mags[] = {-4.0, -2.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  std::vector<night::PointSource> stars;
  for (int i = 0; i < 8; ++i) stars.push_back(source(180.0 - 14.0 + 4.0 * i, 40.0, mags[i]));
  // Both operators: the stars are drawn apart from the sky's mapping, against it.
  for (ToneOperator op : {ToneOperator::TumblinRushmeier, ToneOperator::Histogram}) {
    ChannelConfig ch = channel(320, 240);
    ch.display.toneOperator = op;
    SCOPED_TRACE(op == ToneOperator::Histogram ? "histogram" : "Tumblin-Rushmeier");
    const Frame f = render(night, stars, ch);
    const Frame bare = render(night, {}, ch);
    const double k = displayLaw(bare, stars[2].direction, displayedSky(bare, stars[2].direction, ch), ch).exponent;
    std::vector<double> lux;
    for (const auto& s : stars) lux.push_back(displayedLux(f, s.direction, 1.5));
    const double b = skyLuminance(night, ch, stars[0].direction);
    std::printf("night sky %.3g cd/m^2 (limiting magnitude %.2f), k %.3f\n", b, shader::limitingMagnitude(b), k);
    // The slope at the displayed night sky: below the 0.61 of the display's black, above 0.3.
    EXPECT_LT(k, 0.609);
    EXPECT_GT(k, 0.3);
    for (int i = 0; i < 8; ++i) std::printf("  magnitude %+.0f: displayed %.3g lux\n", mags[i], lux[i]);
    for (int i = 1; i < 8; ++i) {
      EXPECT_GT(lux[i - 1], lux[i]) << mags[i];
      EXPECT_GT(lux[i], 0.0) << mags[i];
    }
    // Same sky behind them (within a few per cent), so the ratios are those of the displayed
    // visibilities of their world visibilities.
    const double threshold = shader::pointSourceThresholdLux(b);
    auto shown = [&](int i) { return shader::displayedVisibility(stars[static_cast<std::size_t>(i)].illuminanceLux / threshold, k); };
    EXPECT_NEAR(lux[2] / lux[7], shown(2) / shown(7), 0.1 * shown(2) / shown(7));
    EXPECT_NEAR(lux[0] / lux[2], shown(0) / shown(2), 0.1 * shown(0) / shown(2));
  }
}

// A magnitude-6.5 star is not shown on a sky as bright as a suburban one (19 mag/arcsec^2,
// limiting magnitude 4.8) and is shown on one as dark as a dark site's (22 mag/arcsec^2,
// limiting magnitude 6.6). The skies are twilights found by the sun's altitude whose
// luminance behind the star equals those levels. The just-visible star is drawn at the
// display's threshold, its brightest pixel 4 codes over the displayed sky.
TEST_F(StarDisplay, FaintStarShowsOnADarkSkyNotOnASuburbanOne) {
  const ChannelConfig ch = channel(640, 480, Frustum{5.3, 5.3, 4, 4});
  const night::PointSource faint = source(180.0, 40.0, 6.5);
  auto skyAt = [&](double targetCdM2) {
    double lo = -20.0, hi = -8.0;  // sun altitudes bracketing the target
    for (int i = 0; i < 14; ++i) {
      const double mid = 0.5 * (lo + hi);
      (skyLuminance(sky(mid), ch, faint.direction) > targetCdM2 ? hi : lo) = mid;
    }
    return sky(0.5 * (lo + hi));
  };
  const double suburbanCdM2 = 34.08 * std::exp(20.7233 - 0.92104 * 19.0) * 1e-5 / M_PI;  // Schaefer 1990
  const double darkCdM2 = 34.08 * std::exp(20.7233 - 0.92104 * 22.0) * 1e-5 / M_PI;
  const SkyState suburban = skyAt(suburbanCdM2), dark = skyAt(darkCdM2);
  const double bSuburban = skyLuminance(suburban, ch, faint.direction), bDark = skyLuminance(dark, ch, faint.direction);
  std::printf("suburban %.3g cd/m^2 (limit %.2f), dark %.3g cd/m^2 (limit %.2f)\n", bSuburban,
              shader::limitingMagnitude(bSuburban), bDark, shader::limitingMagnitude(bDark));
  ASSERT_NEAR(bSuburban / suburbanCdM2, 1.0, 0.05);
  ASSERT_NEAR(bDark / darkCdM2, 1.0, 0.05);
  const Frame onSuburban = render(suburban, {faint}, ch);
  const Frame onDark = render(dark, {faint}, ch);
  EXPECT_EQ(displayedLux(onSuburban, faint.direction), 0.0);
  const double shown = displayedLux(onDark, faint.direction);
  std::printf("displayed on the dark sky: %.3g lux\n", shown);
  EXPECT_GT(shown, 0.0);
  // The display frames themselves: the star's pixels differ from the same frame without it on
  // the dark sky, not at all on the suburban one.
  auto codesChanged = [&](const SkyState& state, const Frame& with) {
    const Frame without = render(state, {}, ch);
    int sum = 0;
    for (std::size_t i = 0; i < without.display.rgba.size(); ++i)
      sum += std::abs(int{with.display.rgba[i]} - int{without.display.rgba[i]});
    return sum;
  };
  const int changedDark = codesChanged(dark, onDark);
  std::printf("codes changed by the star: %d on the dark sky\n", changedDark);
  EXPECT_GT(changedDark, 3);
  EXPECT_EQ(codesChanged(suburban, onSuburban), 0);
}

// The same stars on the same field of view at 640x512 and 1920x1200: their displayed
// visibility, the displayed illuminance sum(display luminance x pixel solid angle) over the
// display's threshold there, agrees within 10%. (The threshold itself is the frame's at both
// sizes: a brightest pixel 4 codes over the sky, which takes more light on the coarser pixels.)
TEST_F(StarDisplay, DisplayedIntensityIsTheSameAt640And1920) {
  const SkyState night = sky();
  std::vector<night::PointSource> stars;
  for (int i = 0; i < 4; ++i) stars.push_back(source(180.0 - 9.0 + 6.0 * i, 38.0 + 1.3 * i, -1.0 + 1.5 * i));
  const ChannelConfig smallChannel = channel(640, 512), largeChannel = channel(1920, 1200);
  const Frame small = render(night, stars, smallChannel), smallBare = render(night, {}, smallChannel);
  const Frame large = render(night, stars, largeChannel), largeBare = render(night, {}, largeChannel);
  for (const auto& s : stars) {
    const double a = displayedLux(small, s.direction) /
                     displayLaw(small, s.direction, displayedSky(smallBare, s.direction, smallChannel), smallChannel).thresholdLux;
    const double b = displayedLux(large, s.direction) /
                     displayLaw(large, s.direction, displayedSky(largeBare, s.direction, largeChannel), largeChannel).thresholdLux;
    std::printf("  displayed visibility %.3g at 640x512, %.3g at 1920x1200\n", a, b);
    EXPECT_GT(a, 0.0);
    EXPECT_NEAR(a / b, 1.0, 0.1);
  }
}

// Orion on a moonless January night from Innsbruck, the real catalogue, a 1280x1024 channel of
// 60 x 48 degrees: the displayed contrast of its seven bright stars (displayed visibility, the
// displayed illuminance over the threshold at the displayed sky around each) ranks as their
// visibility at the eye, and as their magnitude where they differ by more than 0.75 (the sky
// behind them differs a little), and Betelgeuse (B-V 1.85) is shown redder than Rigel (B-V -0.03). The frame is written to the
// build tree (night-test-output/orion_displayed.png), to be looked at.
TEST_F(StarDisplay, OrionRanksByMagnitudeOnTheDisplay) {
  SkyState night = sky();
  ObserverState o = night.observer;
  SkyConditions c = night.conditions;
  c.starCatalogue = std::make_shared<const night::StarCatalogue>(night_testing::catalogue(), o.utc);
  const SkyState probe = buildSkyState(o, c);
  const ephemeris::Star& rigelStar = *std::find_if(night_testing::catalogue().begin(), night_testing::catalogue().end(),
                                                   [](const ephemeris::Star& s) { return s.hr == 1713; });
  const ephemeris::BodyPosition rigel = ephemeris::starPosition(rigelStar, *probe.ephemeris);
  o.attitude = Attitude{rigel.azimuthRad / kDeg, 0.0, 0.0};
  ChannelConfig ch;
  ch.width = 1280;
  ch.height = 1024;
  ch.offset = Attitude{0.0, rigel.altitudeRefractedRad / kDeg + 8.0, 0.0};
  const SkyState s = buildSkyState(o, c);
  renderer_->draw(s, ch);
  const Frame f{renderer_->readPointSources(), renderer_->readDisplay(), ndcToWorld(eyeToEnu(o.attitude, ch.offset), ch.frustum)};
  SkyState bare = s;  // the same frame without the stars: the skies behind them
  bare.starField = nullptr;
  renderer_->draw(bare, ch);
  const Frame sky{renderer_->readHdr(), renderer_->readDisplay(), f.ndcToWorld};
  const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "night-test-output";
  std::filesystem::create_directories(dir);
  // Orion's seven (HR): Rigel, Betelgeuse, Bellatrix, Alnilam, Alnitak, Saiph, Mintaka.
  struct Shown {
    int hr;
    double worldLux, displayedLux;
    glm::dvec3 direction;
    double visibility, displayedVisibility;
  };
  std::vector<Shown> shown;
  for (int hr : {1713, 2061, 1790, 1903, 1948, 2004, 1852}) {
    const auto& all = s.starField->stars;
    const ephemeris::Star& cat = *std::find_if(night_testing::catalogue().begin(), night_testing::catalogue().end(),
                                               [hr](const ephemeris::Star& x) { return x.hr == hr; });
    const ephemeris::BodyPosition p = ephemeris::starPosition(cat, *s.ephemeris);
    const glm::dvec3 d = enuDirection(p.azimuthRad, p.altitudeRefractedRad);
    const auto it = std::max_element(all.begin(), all.end(), [&](const night::PointSource& a, const night::PointSource& b) {
      return glm::dot(a.direction, d) < glm::dot(b.direction, d);
    });
    const glm::dvec2 px = pixelOf(sky, it->direction);
    const float* hdr = sky.points.pixel(static_cast<int>(px.x), static_cast<int>(px.y));
    const double background = shader::rec709Luminance(glm::dvec3(hdr[0], hdr[1], hdr[2]));
    // Everything within 0.2 degrees, as measured on the display: Alnitak's companion (HR 1949,
    // 2.4 arcsec away) and the like.
    double worldLux = 0.0;
    for (const auto& other : all) worldLux += glm::dot(other.direction, it->direction) > std::cos(0.2 * kDeg) ? other.illuminanceLux : 0.0;
    const double displayed = displayedLux(f, it->direction, 0.2);
    const double displayedBackground = displayedSky(sky, it->direction, ch);
    shown.push_back({hr, worldLux, displayed, it->direction, worldLux / shader::pointSourceThresholdLux(background),
                     displayed / displayLaw(f, it->direction, displayedBackground, ch).thresholdLux});
    std::printf("  HR %d: %.3g lux at the eye on %.3g cd/m^2, V %.1f; displayed %.3g lux on %.3g cd/m^2, V_d %.1f\n", hr,
                worldLux, background, shown.back().visibility, displayed, displayedBackground,
                shown.back().displayedVisibility);
  }
  for (const Shown& a : shown)
    for (const Shown& b : shown) {
      if (a.visibility > 1.2 * b.visibility) {
        EXPECT_GT(a.displayedVisibility, b.displayedVisibility) << a.hr << " over " << b.hr;
      }
      if (a.worldLux > 2.0 * b.worldLux) {
        EXPECT_GT(a.displayedVisibility, b.displayedVisibility) << a.hr << " over " << b.hr;
      }
    }
  // Colour: the displayed light around each of the two, red over blue.
  auto redOverBlue = [&](const glm::dvec3& d) {
    const glm::dvec2 px = pixelOf(f, d);
    glm::dvec3 sum(0.0);
    for (int y = static_cast<int>(px.y) - 3; y <= static_cast<int>(px.y) + 3; ++y)
      for (int x = static_cast<int>(px.x) - 3; x <= static_cast<int>(px.x) + 3; ++x) {
        const float* p = f.points.pixel(x, y);
        sum += glm::dvec3(p[0], p[1], p[2]);
      }
    return sum.r / sum.b;
  };
  EXPECT_GT(redOverBlue(shown[1].direction), 2.0 * redOverBlue(shown[0].direction));
  writePng((dir / "orion_displayed.png").string(), f.display, ch.display.gamma);
}
