// Twilight through the whole pipeline: the physical sky, the stars and the full tone
// reproduction on the real GL path. Colour drains from the frame as the sun goes down, and a
// magnitude-1 star appears against the darkening sky because of the sky's luminance and the
// eye's adaptation alone (docs/night-sky-stars.md, "Twilight").
#include "ephemeris/time.h"
#include "tables/table_cache.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "physics/night/night_diffuse.h"
#include "render/sky_renderer.h"
#include "tests/physics/night/star_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>
#include <memory>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using skyig::night_testing::kDeg;

namespace {

class Twilight : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    renderer_ = new SkyRenderer();
    atmosphere::ModelConfig config;
    config.sizes = atmosphere::TableSizes::small();  // shared with the render tests' cache
    model_ = new std::shared_ptr<const atmosphere::AtmosphereModel>(std::make_shared<const atmosphere::AtmosphereModel>(
        atmosphere::loadOrPrecompute(config, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache")));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete renderer_;
    delete context_;
  }

  static SkyConditions physical() {
    SkyConditions c;
    c.model = SkyModel::Physical;
    c.atmosphere = *model_;
    return c;
  }

  // Frames are also written as PNG to the build tree, to be looked at.
  static DisplayImage drawAndKeep(const SkyState& s, const ChannelConfig& c, const std::string& name) {
    renderer_->draw(s, c);
    DisplayImage im = renderer_->readDisplay();
    const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "night-test-output";
    std::filesystem::create_directories(dir);
    writePng((dir / (name + ".png")).string(), im, c.display.gamma);
    return im;
  }

  static inline GlContext* context_ = nullptr;
  static inline SkyRenderer* renderer_ = nullptr;
  static inline std::shared_ptr<const atmosphere::AtmosphereModel>* model_ = nullptr;
};

ObserverState dusk() {
  ObserverState o;
  o.attitude = Attitude{0.0, 0.0, 0.0};
  o.utc = {2026, 3, 20, 18 * 3600.0};
  return o;
}

// Mean over the frame of the 8-bit chroma max(R,G,B) - min(R,G,B), in [0, 1].
double meanChroma(const DisplayImage& im) {
  double sum = 0.0;
  const std::size_t n = im.rgba.size() / 4;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &im.rgba[i * 4];
    sum += (std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]})) / 255.0;
  }
  return sum / static_cast<double>(n);
}

// Display luminance (cd/m^2) of a pixel: eq. 17 of Wang, Ji & Zhang 2011 per channel, Rec.709
// weights.
double displayLuminance(const DisplayImage& im, int x, int y, const DisplayParams& d) {
  const std::uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * im.width + x) * 4];
  double l = 0.0;
  const double w[3] = {0.2126, 0.7152, 0.0722};
  for (int k = 0; k < 3; ++k) l += w[k] * (d.ambientLuminance + d.maxLuminance * std::pow(p[k] / 255.0, d.gamma));
  return l;
}

// CIE 1976 u'v' of a display pixel (decoded with the display gamma); nullopt for black.
std::optional<glm::dvec2> pixelUv(const std::uint8_t* p, double gamma) {
  const glm::dvec3 rgb(std::pow(p[0] / 255.0, gamma), std::pow(p[1] / 255.0, gamma), std::pow(p[2] / 255.0, gamma));
  const glm::dvec3 xyz(0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b, 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b,
                       0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b);
  const double den = xyz.x + 15.0 * xyz.y + 3.0 * xyz.z;
  if (den <= 0.0) return std::nullopt;
  return glm::dvec2(4.0 * xyz.x / den, 9.0 * xyz.y / den);
}

// The frame's colour spread: mean u'v' distance of its pixels from their mean chromaticity.
double chromaticSpread(const DisplayImage& im, double gamma) {
  std::vector<glm::dvec2> uv;
  for (std::size_t i = 0; i < im.rgba.size() / 4; ++i)
    if (auto c = pixelUv(&im.rgba[i * 4], gamma)) uv.push_back(*c);
  glm::dvec2 mean(0.0);
  for (const auto& c : uv) mean += c / static_cast<double>(uv.size());
  double spread = 0.0;
  for (const auto& c : uv) spread += glm::length(c - mean) / static_cast<double>(uv.size());
  return spread;
}

}  // namespace

// The frame (160x120, 80 x 60 degrees, looking west at the afterglow) loses its colour
// through nautical and astronomical twilight: the mean 8-bit chroma falls from sun -6 to -18
// degrees, and the spread of chromaticities over the frame (the red horizon against the blue
// sky) collapses as rod vision takes over (eq. 20-21). From -2 to -6 the chroma rises: the
// "blue hour", when ozone's Chappuis absorption leaves the sky its deepest blue (Hulburt 1953,
// JOSA 43, 113), which the physical sky reproduces.
TEST_F(Twilight, FramesLoseColourAsTheSunGoesDown) {
  ChannelConfig wide;
  wide.width = 160;
  wide.height = 120;
  wide.frustum = Frustum{40, 40, 30, 30};
  wide.offset = Attitude{-90.0, 25.0, 0.0};
  auto frame = [&](double sun) {
    return drawAndKeep(buildSkyState(dusk(), physical(), SunOverride{270.0, sun}), wide,
                       "twilight_west_sun" + std::to_string(static_cast<int>(sun)));
  };
  const DisplayImage civil = frame(-2.0);
  double last = 1.0;
  for (double sun : {-6.0, -10.0, -14.0, -18.0}) {
    const double chroma = meanChroma(frame(sun));
    EXPECT_LT(chroma, last) << "sun " << sun;
    last = chroma;
  }
  const DisplayImage night = frame(-18.0);
  EXPECT_LT(chromaticSpread(night, wide.display.gamma), 0.3 * chromaticSpread(civil, wide.display.gamma));
}

// A magnitude-1 star 30 degrees up in the east, on a channel of 2 arcmin pixels (a 1920-pixel
// channel 64 degrees wide): its peak pixel's display luminance against the mean of a ring
// 8-16 pixels around it. Weber contrast 0.1 is the threshold: Blackwell's (1946, JOSA 36, 624)
// 50% detection contrast for targets of a few arcminutes at 1-10 cd/m^2 is 0.03-0.1, and one
// 8-bit step of the +-1 LSB dither is 2% at mid-grey. The star does not stand out at sun -2
// and -4 degrees, does at -7 and -8: it appears near -6, as observers report, through the
// sky's luminance and the eye's adaptation alone.
TEST_F(Twilight, MagnitudeOneStarAppearsNearSunMinusSix) {
  ChannelConfig narrow;
  narrow.width = 160;
  narrow.height = 120;
  narrow.frustum = Frustum{2.667, 2.667, 2.0, 2.0};
  narrow.offset = Attitude{90.0, 30.0, 0.0};
  const ObserverState o = dusk();
  const ephemeris::SkyEphemeris e = buildSkyState(o, SkyConditions{}).ephemeris.value();
  SkyConditions c = physical();
  c.starCatalogue = std::make_shared<const night::StarCatalogue>(
      std::vector<ephemeris::Star>{night_testing::starAt(e, 90.0, 30.0, 1.0, 0.0)}, o.utc);
  auto weber = [&](double sun) {
    const DisplayImage im = drawAndKeep(buildSkyState(o, c, SunOverride{270.0, sun}), narrow,
                                        "twilight_star_sun" + std::to_string(static_cast<int>(sun)));
    double peak = 0.0, ring = 0.0;
    int n = 0;
    for (int y = 0; y < narrow.height; ++y)
      for (int x = 0; x < narrow.width; ++x) {
        const double r = std::hypot(x - 79.5, y - 59.5);  // the star is at the centre (refraction: 1 px)
        const double l = displayLuminance(im, x, y, narrow.display);
        if (r < 2.5) peak = std::max(peak, l);
        if (r > 8.0 && r < 16.0) ring += l, ++n;
      }
    ring /= n;
    return (peak - ring) / ring;
  };
  constexpr double kThreshold = 0.1;
  EXPECT_LT(weber(-2.0), kThreshold);
  EXPECT_LT(weber(-4.0), kThreshold);
  EXPECT_GT(weber(-7.0), kThreshold);
  EXPECT_GT(weber(-8.0), kThreshold);
}

namespace {

// The direction within 40 degrees of the zenith (on a 2-degree grid, from the CPU twin of the
// pass) whose Milky Way most exceeds that of its mirror image across the sun's vertical, and
// that mirror image as its reference: the twilight sky and the airglow are symmetric about
// that plane, so what differs between the two is the Milky Way (and the zodiacal light, faint
// this far from the sun). Yaw/pitch in degrees for a channel offset.
struct BandAndReference {
  Attitude band, reference;
  double bandMilkyWay = 0.0, referenceMilkyWay = 0.0;  // cd/m^2
};

BandAndReference milkyWayBand(const SkyState& s) {
  const auto sky = sky::nightDiffuseSky(s);
  auto milkyWay = [&](double yawDeg, double pitchDeg) {
    const glm::dvec3 v = enuDirection(yawDeg * kDeg, pitchDeg * kDeg);
    const glm::dvec3 c = night::nightDiffuseRadiance(*sky, v).milkyWay;
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  };
  const double sunYaw = s.sunAzimuth / kDeg;
  BandAndReference b;
  for (double pitch = 50.0; pitch <= 88.0; pitch += 2.0)
    for (double yaw = 0.0; yaw < 360.0; yaw += 2.0) {
      const double mirror = std::fmod(2.0 * sunYaw - yaw + 720.0, 360.0);
      const double band = milkyWay(yaw, pitch), reference = milkyWay(mirror, pitch);
      if (band - reference > b.bandMilkyWay - b.referenceMilkyWay) {
        b = {Attitude{yaw, pitch, 0.0}, Attitude{mirror, pitch, 0.0}, band, reference};
      }
    }
  return b;
}

// Mean display luminance of a frame without its brightest tenth of pixels (any star or planet
// in view), dithered 8-bit values decoded through the display model (eq. 17).
double trimmedMeanDisplayLuminance(const DisplayImage& im, const DisplayParams& d) {
  std::vector<double> l;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) l.push_back(displayLuminance(im, x, y, d));
  std::sort(l.begin(), l.end());
  l.resize(l.size() * 9 / 10);
  double sum = 0.0;
  for (double v : l) sum += v;
  return sum / static_cast<double>(l.size());
}

}  // namespace

// The Milky Way through the whole renderer on a summer evening over Innsbruck: a 6-degree patch
// on the band near the zenith against its mirror image across the sun's vertical, as display
// (Weber) contrast. Blackwell (1946, JOSA 36, 624) measured 50% detection contrasts of about
// 0.008-0.016 for targets of one to two degrees at 0.3-3 cd/m^2 (the night frame's display
// luminance here is 1.6-2 cd/m^2): ~0.01. Measured (small tables): 0.004 at sun -11.6 degrees,
// 0.012 at -15.5, 0.013 at -19, 0.038 at -24.5. The band is invisible in nautical twilight (under
// half the threshold), reaches the threshold near -15 and is plainly visible (twice it) in the
// dark sky: it appears as the sky darkens, through the sky's luminance and the adaptation alone
// (docs/night-sky.md, "When the night's sources appear": below about -15 degrees). The small
// tables make twilight 15-22% too bright (docs/atmosphere.md), so -15 to -19 are if anything
// pessimistic.
TEST_F(Twilight, MilkyWayAppearsAsTheSkyDarkens) {
  ChannelConfig patch;
  patch.width = 64;
  patch.height = 64;
  patch.frustum = Frustum{3.0, 3.0, 3.0, 3.0};
  ObserverState o;
  o.attitude = Attitude{0.0, 0.0, 0.0};
  auto contrastAt = [&](double utcHours) {
    o.utc = {2026, 8, 12, utcHours * 3600.0};
    const SkyState s = buildSkyState(o, physical());
    const BandAndReference b = milkyWayBand(s);
    EXPECT_LT(b.referenceMilkyWay, 0.5 * b.bandMilkyWay) << "the reference direction is in the band too";
    const std::string sun = std::to_string(static_cast<int>(std::lround(s.sunAltitude / kDeg)));
    patch.offset = b.band;
    const double band = trimmedMeanDisplayLuminance(drawAndKeep(s, patch, "milky_way_band_sun" + sun), patch.display);
    patch.offset = b.reference;
    const double reference = trimmedMeanDisplayLuminance(drawAndKeep(s, patch, "milky_way_reference_sun" + sun), patch.display);
    std::printf("sun %5.1f deg: Milky Way %.2e cd/m^2 against %.2e, display %.3f against %.3f cd/m^2, contrast %.4f\n",
                s.sunAltitude / kDeg, b.bandMilkyWay, b.referenceMilkyWay, band, reference, band / reference - 1.0);
    return band / reference - 1.0;
  };
  constexpr double kThreshold = 0.01;
  // Tumblin-Rushmeier compresses a dim scene's contrasts as the eye does (its gamma falls with
  // the adaptation): the band is invisible in nautical twilight and appears near -15 deg.
  patch.display.toneOperator = ToneOperator::TumblinRushmeier;
  const double nautical = contrastAt(19.75);  // sun -11.6
  const double minus15 = contrastAt(20.25);   // sun -15.5
  const double dark = contrastAt(21.75);      // sun -24.5
  EXPECT_LT(nautical, 0.5 * kThreshold);
  EXPECT_GT(minus15, nautical);
  // With the eye adapted to the whole view sphere (the darker terrain included) the band reaches
  // Blackwell's threshold a little after -15.5 deg (0.009 there, 0.038 in the dark sky).
  EXPECT_GT(minus15, 0.75 * kThreshold);
  EXPECT_GT(dark, 2.0 * kThreshold);
  // The histogram operator (the default) keeps a world contrast that fits the display as it is
  // (its linear ceiling): the band's 1.4% in nautical twilight is shown as 1.4%, just above the
  // display's threshold, where the dark-adapting eye at the world's few 1e-3 cd/m^2 would need
  // several per cent (docs/tone-reproduction.md, "Known limits"). It still rises with the
  // darkening sky and is plain in the dark one.
  patch.display.toneOperator = ToneOperator::Histogram;
  const double nauticalH = contrastAt(19.75), minus15H = contrastAt(20.25), darkH = contrastAt(21.75);
  EXPECT_LT(nauticalH, 2.0 * kThreshold);
  EXPECT_GT(minus15H, nauticalH);
  EXPECT_GT(darkH, minus15H);
  EXPECT_GT(darkH, 2.0 * kThreshold);
}

// The summer Milky Way at a dark site (Teide, 2390 m, 5 July 2027 23:00 UTC: the sun 30 degrees
// down, no moon, the galactic centre 14 degrees east of the meridian): the 6-degree patch where
// the band stands highest over the sky 20 degrees away at the same elevation (between 20 and 60
// degrees up), as display (Weber) contrast through the default operator. The eye sees the band
// there plainly; the threshold for targets of one to two degrees at the display's 0.3-3 cd/m^2 is
// about 0.01 (Blackwell 1946, JOSA 36, 624: 0.008-0.016), and the band must stand well above it
// (several times), while the frame does not show more contrast than the world has (the
// histogram operator's linear ceiling).
TEST_F(Twilight, TheSummerMilkyWayAtADarkSiteStandsWellAboveTheLargeTargetThreshold) {
  ObserverState o;
  o.latitudeDeg = 28.27;
  o.longitudeDeg = -16.64;
  o.heightM = 2390.0;
  o.attitude = Attitude{0.0, 0.0, 0.0};  // the patches' offsets are their view directions
  o.utc = *ephemeris::parseIso8601Utc("2027-07-05T23:00:00Z");
  const SkyState s = buildSkyState(o, physical());
  ASSERT_LT(s.sunAltitude, -25.0 * kDeg);
  ASSERT_LT(s.moonDirection.z, 0.0) << "a moonless sky";
  const auto sky = sky::nightDiffuseSky(s);
  auto milkyWay = [&](double yawDeg, double pitchDeg) {
    const glm::dvec3 c = night::nightDiffuseRadiance(*sky, enuDirection(yawDeg * kDeg, pitchDeg * kDeg)).milkyWay;
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  };
  BandAndReference b;
  for (double pitch = 20.0; pitch <= 60.0; pitch += 2.0) {
    // The azimuth step that puts two views at this elevation 20 degrees apart.
    const double se = std::sin(pitch * kDeg), ce = std::cos(pitch * kDeg);
    const double away = std::acos((std::cos(20.0 * kDeg) - se * se) / (ce * ce)) / kDeg;
    for (double yaw = 90.0; yaw <= 270.0; yaw += 2.0)
      for (double side : {-1.0, 1.0}) {
        const double other = std::fmod(yaw + side * away + 360.0, 360.0);
        const double band = milkyWay(yaw, pitch), reference = milkyWay(other, pitch);
        if (band - reference > b.bandMilkyWay - b.referenceMilkyWay)
          b = {Attitude{yaw, pitch, 0.0}, Attitude{other, pitch, 0.0}, band, reference};
      }
  }
  ChannelConfig patch;
  patch.width = 64;
  patch.height = 64;
  patch.frustum = Frustum{3.0, 3.0, 3.0, 3.0};
  patch.offset = b.band;
  const double band = trimmedMeanDisplayLuminance(drawAndKeep(s, patch, "milky_way_dark_site_band"), patch.display);
  const HdrImage bandHdr = renderer_->readHdr();
  patch.offset = b.reference;
  const double reference = trimmedMeanDisplayLuminance(drawAndKeep(s, patch, "milky_way_dark_site_reference"), patch.display);
  const HdrImage referenceHdr = renderer_->readHdr();
  auto meanLuminance = [](const HdrImage& im) {  // the scene's, its brightest tenth left out as above
    std::vector<double> l;
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) {
        const float* p = im.pixel(x, y);
        l.push_back(0.2126 * double(p[0]) + 0.7152 * double(p[1]) + 0.0722 * double(p[2]));
      }
    std::sort(l.begin(), l.end());
    l.resize(l.size() * 9 / 10);
    double sum = 0.0;
    for (double v : l) sum += v;
    return sum / static_cast<double>(l.size());
  };
  const double world = meanLuminance(bandHdr) / meanLuminance(referenceHdr) - 1.0;
  const double shown = band / reference - 1.0;
  std::printf("dark site: the band at azimuth %.0f, %.0f deg up, against azimuth %.0f: Milky Way %.2e against %.2e cd/m^2; "
              "the world's contrast %.3f, the display's %.3f (%.3f against %.3f cd/m^2); threshold 0.01\n",
              b.band.yawDeg, b.band.pitchDeg, b.reference.yawDeg, b.bandMilkyWay, b.referenceMilkyWay, world, shown, band,
              reference);
  constexpr double kThreshold = 0.01;
  EXPECT_GT(reference, 0.3);  // the threshold's luminance range
  EXPECT_LT(band, 3.0);
  EXPECT_GT(shown, 5.0 * kThreshold);
  EXPECT_LT(shown, 1.05 * world + 0.01);  // no more than the world's (the dither's code aside)
}
