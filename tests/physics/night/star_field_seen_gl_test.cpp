// The star field as a pilot sees it on the display, counted the way an observer would count it
// on the 8-bit frame: a catalogue star is shown when the brightest pixel at its place stands 3
// codes over the mean of a ring 9-21 pixels around it. The whole renderer on the real GL path
// (llvmpipe where there is no GPU), the real catalogue, the default display and operator.
//
// The eye's side is Schaefer's (1990) point-source threshold against the sky behind each star
// (physics/eye/point_source_visibility.glsl); the display's side is the display threshold the
// displayed-star pass maps a just-visible star to (docs/night-sky-stars.md, "The display's
// threshold"). What a channel shows must not depend on its pixel scale.
#include "render/image_io.h"
#include "render/sky_renderer.h"
#include "physics/analytic/analytic_sky.h"
#include "physics/stars/star_physics.h"
#include "tests/physics/night/night_gl_fixture.h"
#include "tests/physics/night/star_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <tuple>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using skyig::night_testing::kDeg;

namespace {

class StarFieldSeen : public night_testing::NightGlTest {
 protected:
  static SkyConditions conditions(const ObserverState& o) {
    SkyConditions c;
    c.model = SkyModel::Physical;
    c.atmosphere = *model_;
    c.starCatalogue = std::make_shared<const night::StarCatalogue>(night_testing::catalogue(), o.utc);
    return c;
  }

  // A dark site: Teide observatory (2390 m) on a moonless January night, looking south-east.
  static ObserverState darkSite() {
    ObserverState o;
    o.latitudeDeg = 28.3003;
    o.longitudeDeg = -16.5122;
    o.heightM = 2390.0;
    o.utc = {2027, 1, 8, 22.5 * 3600.0};
    o.attitude = Attitude{135.0, 0.0, 0.0};
    return o;
  }

  // A 60 x 40 degree channel, its middle 35 degrees up (or `pitchDeg`).
  static ChannelConfig channel(int width, int height, double pitchDeg = 35.0) {
    ChannelConfig ch;
    ch.width = width;
    ch.height = height;
    ch.frustum = Frustum{30.0, 30.0, 20.0, 20.0};
    ch.offset = Attitude{0.0, pitchDeg, 0.0};
    return ch;
  }

  struct Count {
    int shown = 0, of = 0;
    double fraction() const { return of > 0 ? static_cast<double>(shown) / of : 0.0; }
  };
  struct Seen {
    Count toFive, fiveToSix, toThreeHalf;  // catalogue V <= 5, 5 < V <= 6, V <= 3.5
    int fainterThanLimitShown = 0;         // stars fainter than the eye's limit there, shown
    int peaks = 0, strayPeaks = 0;         // displayed peaks, and those with no source V <= 7 near
    double meanSkyCdM2 = 0.0;              // the sky behind the counted stars (HDR, no stars)
  };

  // The frame's luma in codes.
  static std::vector<double> luma(const DisplayImage& d) {
    std::vector<double> l(static_cast<std::size_t>(d.width) * d.height);
    for (std::size_t i = 0; i < l.size(); ++i)
      l[i] = 0.2126 * d.rgba[i * 4] + 0.7152 * d.rgba[i * 4 + 1] + 0.0722 * d.rgba[i * 4 + 2];
    return l;
  }

  static double ringMean(const std::vector<double>& l, int w, int cx, int cy) {
    double sum = 0.0;
    int n = 0;
    for (int dy = -21; dy <= 21; ++dy)
      for (int dx = -21; dx <= 21; ++dx) {
        const int r2 = dx * dx + dy * dy;
        if (r2 < 81 || r2 > 441) continue;
        sum += l[static_cast<std::size_t>(cy + dy) * w + cx + dx];
        ++n;
      }
    return sum / n;
  }

  // How far the place's brightest pixel (within 2 pixels) stands over its ring, in codes.
  static double standOut(const std::vector<double>& l, int w, double px, double py) {
    const int cx = static_cast<int>(px), cy = static_cast<int>(py);
    double peak = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) peak = std::max(peak, l[static_cast<std::size_t>(cy + dy) * w + cx + dx]);
    return peak - ringMean(l, w, cx, cy);
  }

  static Seen look(const ObserverState& o, const ChannelConfig& ch, const char* png = nullptr) {
    const SkyConditions c = conditions(o);
    const SkyState s = buildSkyState(o, c);
    renderer_->draw(s, ch);
    const DisplayImage frame = renderer_->readDisplay();
    SkyState bare = s;
    bare.starField = nullptr;
    renderer_->draw(bare, ch);
    const HdrImage sky = renderer_->readHdr();
    if (png) {
      const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "night-test-output";
      std::filesystem::create_directories(dir);
      writePng((dir / png).string(), frame, ch.display.gamma);
    }
    const glm::dmat3 toNdc = glm::inverse(ndcToWorld(eyeToEnu(o.attitude, ch.offset), ch.frustum));
    const int w = frame.width, h = frame.height;
    auto pixelOf = [&](const glm::dvec3& d, glm::dvec2& px) {
      const glm::dvec3 p = toNdc * d;
      if (p.z <= 0.0) return false;
      px = {(p.x / p.z * 0.5 + 0.5) * w, (0.5 - p.y / p.z * 0.5) * h};
      return px.x >= 22 && px.y >= 22 && px.x < w - 22 && px.y < h - 22;
    };
    const std::vector<double> l = luma(frame);
    Seen seen;
    std::vector<glm::dvec2> sources;  // every catalogue star V <= 7 and planet in the frame
    double skySum = 0.0;
    int skyN = 0;
    for (const ephemeris::Star& star : night_testing::catalogue()) {
      const ephemeris::BodyPosition p = ephemeris::starPosition(star, *s.ephemeris);
      glm::dvec2 px;
      if (p.altitudeRefractedRad < 5.0 * kDeg || !pixelOf(enuDirection(p.azimuthRad, p.altitudeRefractedRad), px)) continue;
      if (star.vmag <= 7.0) sources.push_back(px);
      const float* b = sky.pixel(static_cast<int>(px.x), static_cast<int>(px.y));
      const double background = shader::rec709Luminance(glm::dvec3(b[0], b[1], b[2]));
      const bool shown = standOut(l, w, px.x, px.y) >= 3.0;
      if (star.vmag <= 6.0) {
        skySum += background;
        ++skyN;
      }
      if (star.vmag <= 5.0) {
        ++seen.toFive.of;
        seen.toFive.shown += shown;
      } else if (star.vmag <= 6.0) {
        ++seen.fiveToSix.of;
        seen.fiveToSix.shown += shown;
      }
      if (star.vmag <= 3.5) {
        ++seen.toThreeHalf.of;
        seen.toThreeHalf.shown += shown;
      }
      // Shown though fainter than the eye sees there (its own light, above the atmosphere: the
      // extinction only makes it fainter still), and no brighter star near it.
      if (shown && star.vmag > shader::limitingMagnitude(background) + 0.2) {
        bool alone = true;
        for (const ephemeris::Star& other : night_testing::catalogue())
          if (other.vmag < star.vmag && glm::dot(glm::dvec3(other.directionJ2000.x, other.directionJ2000.y, other.directionJ2000.z),
                                                 glm::dvec3(star.directionJ2000.x, star.directionJ2000.y, star.directionJ2000.z)) >
                                            std::cos(0.4 * kDeg))
            alone = false;
        seen.fainterThanLimitShown += alone;
      }
    }
    for (const night::PointSource& src : s.starField->stars) {  // the planets among them too
      glm::dvec2 px;
      if (shader::magnitudeOfIlluminance(src.illuminanceLux) < 3.0 && pixelOf(src.direction, px)) sources.push_back(px);
    }
    seen.meanSkyCdM2 = skyN > 0 ? skySum / skyN : 0.0;
    // Every displayed peak: a pixel no lower than any within 2 pixels, 3 codes over its ring;
    // peaks closer than 4 pixels are one.
    std::vector<glm::dvec2> peaks;
    for (int y = 22; y < h - 22; ++y)
      for (int x = 22; x < w - 22; ++x) {
        const double v = l[static_cast<std::size_t>(y) * w + x];
        bool top = true;
        for (int dy = -2; dy <= 2 && top; ++dy)
          for (int dx = -2; dx <= 2 && top; ++dx) top = l[static_cast<std::size_t>(y + dy) * w + x + dx] <= v;
        if (!top || v - ringMean(l, w, x, y) < 3.0) continue;
        bool near = false;
        for (const glm::dvec2& q : peaks) near = near || glm::length(q - glm::dvec2(x, y)) < 4.0;
        if (!near) peaks.emplace_back(x, y);
      }
    seen.peaks = static_cast<int>(peaks.size());
    for (const glm::dvec2& q : peaks) {
      bool explained = false;
      for (const glm::dvec2& src : sources) explained = explained || glm::length(src - q - glm::dvec2(0.5)) < 4.0;
      seen.strayPeaks += !explained;
    }
    return seen;
  }

  // Sky brightness in V mag/arcsec^2 from cd/m^2: Schaefer (1990), B (nL) = 34.08 exp(20.7233 -
  // 0.92104 m), 1 nL = 1e-5 / pi cd/m^2.
  static double skyMagnitude(double cdM2) { return (20.7233 - std::log(cdM2 * M_PI * 1e5 / 34.08)) / 0.92104; }

  static void print(const char* what, const Seen& s) {
    std::printf("%s: V<=5 %d/%d (%.0f%%), 5<V<=6 %d/%d (%.0f%%), V<=3.5 %d/%d; fainter than the limit shown %d; "
                "peaks %d, stray %d; sky %.3g cd/m^2, %.2f mag/arcsec^2 (limit %.2f)\n",
                what, s.toFive.shown, s.toFive.of, 100.0 * s.toFive.fraction(), s.fiveToSix.shown, s.fiveToSix.of,
                100.0 * s.fiveToSix.fraction(), s.toThreeHalf.shown, s.toThreeHalf.of, s.fainterThanLimitShown, s.peaks,
                s.strayPeaks, s.meanSkyCdM2, skyMagnitude(s.meanSkyCdM2), shader::limitingMagnitude(s.meanSkyCdM2));
  }

};

}  // namespace

// A moonless dark site (about 21.9 mag/arcsec^2, the eye's limit near V 6.5): the stars the eye
// sees are shown at 1.9, 3.8 and 5.6 arcmin a pixel alike, and nearly nothing else.
TEST_F(StarFieldSeen, AtADarkSiteTheEyesStarsShowAtEveryPixelScale) {
  const ObserverState o = darkSite();
  std::vector<Seen> sizes;
  for (const auto& [w, h, png] : {std::tuple{1920, 1280, "dark_site_1920.png"}, std::tuple{960, 640, "dark_site_960.png"},
                                  std::tuple{640, 427, "dark_site_640.png"}}) {
    sizes.push_back(look(o, channel(w, h), png));
    char what[32];
    std::snprintf(what, sizeof what, "%dx%d", w, h);
    print(what, sizes.back());
  }
  for (const Seen& s : sizes) {
    ASSERT_GT(s.toFive.of, 40);
    ASSERT_GT(s.fiveToSix.of, 60);
    EXPECT_GE(s.toFive.fraction(), 0.90);
    EXPECT_GE(s.fiveToSix.fraction(), 0.50);
    EXPECT_LT(s.strayPeaks, 0.08 * s.peaks);
    EXPECT_EQ(s.fainterThanLimitShown, 0);
  }
  for (const Seen& s : sizes) {
    EXPECT_NEAR(static_cast<double>(s.toFive.shown + s.fiveToSix.shown) / (sizes[0].toFive.shown + sizes[0].fiveToSix.shown),
                1.0, 0.15);
  }
}

// A full moon 58 degrees up over Innsbruck (2027-01-22 23:00 UTC), the channel 90 degrees away
// from it: the sky is 18.5-19.5 mag/arcsec^2, where the eye's limit is near V 4.5-5. The bright
// stars stay; none fainter than the limit is shown.
TEST_F(StarFieldSeen, UnderAFullMoonTheBrightStarsStay) {
  ObserverState o;
  o.utc = {2027, 1, 22, 23.0 * 3600.0};
  const SkyState probe = buildSkyState(o, conditions(o));
  const ephemeris::BodyPosition moon = probe.ephemeris->moon;
  ASSERT_NEAR(moon.altitudeRad / kDeg, 58.0, 3.0);
  // The opposite azimuth, at the altitude 90 degrees from the moon: 180 - 90 - moon's altitude.
  o.attitude = Attitude{std::fmod(moon.azimuthRad / kDeg + 180.0, 360.0), 0.0, 0.0};
  const Seen s = look(o, channel(1920, 1280, 90.0 - moon.altitudeRad / kDeg), "full_moon_away.png");
  print("full moon, 90 degrees away", s);
  EXPECT_GT(skyMagnitude(s.meanSkyCdM2), 18.3);
  EXPECT_LT(skyMagnitude(s.meanSkyCdM2), 19.7);
  ASSERT_GE(s.toThreeHalf.of, 3);
  EXPECT_GE(s.toThreeHalf.fraction(), 0.80);
  EXPECT_EQ(s.fainterThanLimitShown, 0);
}

// The Milky Way at the dark site (the band crosses the channel's right side): its colour in the
// HDR frame (no stars, so no point decides) changes by less than 2% (CIE xy distance 0.02 of the
// chromaticity's own scale, as |dxy| / |xy| < 0.02) between neighbouring pixels, at 5.6 arcmin a
// pixel where a step of the map would show most. (The map's near-black texels scaled to the
// calibration's floor in their own colour made a hard-edged blue patch: 0.099 per pixel; now 0.0025.)
TEST_F(StarFieldSeen, TheMilkyWaysColourHasNoSteps) {
  const ObserverState o = darkSite();
  const SkyConditions c = conditions(o);
  SkyState s = buildSkyState(o, c);
  s.starField = nullptr;
  const ChannelConfig ch = channel(640, 427);
  renderer_->draw(s, ch);
  const HdrImage hdr = renderer_->readHdr();
  auto xy = [&](int x, int y) {
    const float* p = hdr.pixel(x, y);
    const glm::dvec3 rgb(p[0], p[1], p[2]);
    const glm::dvec3 xyz(0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b, 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b,
                         0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b);
    return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z);
  };
  double largest = 0.0;
  for (int y = 0; y + 1 < hdr.height; ++y)
    for (int x = 0; x + 1 < hdr.width; ++x) {
      const glm::dvec2 here = xy(x, y);
      const double step = std::max(glm::length(xy(x + 1, y) - here), glm::length(xy(x, y + 1) - here)) / glm::length(here);
      largest = std::max(largest, step);
    }
  std::printf("largest relative chromaticity step between neighbouring pixels: %.4f\n", largest);
  EXPECT_LT(largest, 0.02);
}
