// skyig's ephemeris against two independent implementations packaged by Debian:
//  - Swiss Ephemeris (libswe-dev + swe-basic-data: JPL DE431 compressed, 1800-2400) for the sun,
//    moon and planets, topocentric apparent places, magnitudes and moon phase;
//  - ERFA (liberfa-dev, the SOFA algorithms) for sidereal time and the stars' observed places.
// Both share skyig's TT and UT1 for each instant (swe_set_delta_t_userdef, ERFA's UTC with the
// same leap seconds), so the differences are those of the models. Skips, saying why, where the
// libraries or the ephemeris files are absent. Prints max and RMS errors (docs/ephemeris.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "ephemeris/ephemeris.h"

#if SKYIG_HAVE_REFERENCE_LIBS
#include <erfa.h>
#include <swephexp.h>
#include <sys/stat.h>
#endif

using namespace skyig::ephemeris;

namespace {
struct Stat {
  double max = 0.0, sumSq = 0.0;
  int n = 0;
  void add(double v) {
    max = std::max(max, std::fabs(v));
    sumSq += v * v;
    ++n;
  }
  double rms() const { return n ? std::sqrt(sumSq / n) : 0.0; }
};

[[maybe_unused]] Vec3 unit(double ra, double dec) {
  return {std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec)};
}
}  // namespace

#if SKYIG_HAVE_REFERENCE_LIBS
namespace {
constexpr const char* kEphePath = "/usr/share/libswe/ephe";

bool ephemerisFilesPresent() {
  struct stat st {};
  return stat((std::string(kEphePath) + "/sepl_18.se1").c_str(), &st) == 0 &&
         stat((std::string(kEphePath) + "/semo_18.se1").c_str(), &st) == 0;
}

UtcTime randomInstant(std::mt19937_64& rng, int firstYear, int lastYear) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  UtcTime t;
  t.year = firstYear + static_cast<int>(u(rng) * (lastYear - firstYear + 1));
  t.month = 1 + static_cast<int>(u(rng) * 12.0);
  t.day = 1 + static_cast<int>(u(rng) * 28.0);
  t.secondsOfDay = u(rng) * 86399.0;
  return t;
}

Observer randomObserver(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Observer o;
  o.latitudeRad = (u(rng) * 170.0 - 85.0) * kDegToRad;
  o.longitudeRad = (u(rng) * 360.0 - 180.0) * kDegToRad;
  o.heightM = u(rng) * 4000.0;
  return o;
}
}  // namespace

TEST(ReferenceComparison, SunMoonPlanetsAgainstSwissEphemeris) {
  if (!ephemerisFilesPresent())
    GTEST_SKIP() << "Swiss Ephemeris files not found in " << kEphePath << " (apt-get install swe-basic-data)";
  swe_set_ephe_path(const_cast<char*>(kEphePath));
  std::mt19937_64 rng(20260101);
  constexpr int kBodies = 7;
  const int sweBody[kBodies] = {SE_SUN, SE_MOON, SE_MERCURY, SE_VENUS, SE_MARS, SE_JUPITER, SE_SATURN};
  const char* names[kBodies] = {"sun", "moon", "Mercury", "Venus", "Mars", "Jupiter", "Saturn"};
  const double limitArcsec[kBodies] = {1.0, 5.0, 5.0, 5.0, 5.0, 5.0, 5.0};  // docs/ephemeris.md's targets
  Stat pos[kBodies], azalt[kBodies], mag[5], phase, sweSidereal;
  for (int k = 0; k < 300; ++k) {
    const UtcTime t = randomInstant(rng, 1950, 2100);
    const Observer o = randomObserver(rng);
    const SkyEphemeris s = computeEphemeris(t, o);
    swe_set_delta_t_userdef(s.time.jdTt - s.time.jdUt1);
    const double lonDeg = o.longitudeRad / kDegToRad, latDeg = o.latitudeRad / kDegToRad;
    swe_set_topo(lonDeg, latDeg, o.heightM);
    double geopos[3] = {lonDeg, latDeg, o.heightM};
    const BodyPosition* mine[kBodies] = {&s.sun, &s.moon, &s.planets[0], &s.planets[1],
                                         &s.planets[2], &s.planets[3], &s.planets[4]};
    for (int b = 0; b < kBodies; ++b) {
      double xx[6] = {};
      char err[AS_MAXCH] = {};
      const int flags = SEFLG_SWIEPH | SEFLG_TOPOCTR | SEFLG_EQUATORIAL;
      ASSERT_GE(swe_calc(s.time.jdTt, sweBody[b], flags, xx, err), 0) << err;
      const double e = angleBetween(unit(mine[b]->rightAscensionRad, mine[b]->declinationRad),
                                    unit(xx[0] * kDegToRad, xx[1] * kDegToRad)) / kArcsecToRad;
      pos[b].add(e);
      EXPECT_LT(e, limitArcsec[b]) << names[b] << " at " << formatIso8601Utc(t);
      // Horizontal reference: Swiss' place with ERFA's sidereal time (swe_azalt's own sidereal
      // time differs from SOFA's by up to 0.19 s, see docs/ephemeris.md).
      double az = 0.0, el = 0.0;
      const double last = eraGst06a(s.time.jdUt1, 0.0, s.time.jdTt, 0.0) + o.longitudeRad;
      eraHd2ae(last - xx[0] * kDegToRad, xx[1] * kDegToRad, o.latitudeRad, &az, &el);
      const Vec3 theirs{std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
      azalt[b].add(angleBetween(mine[b]->enu, theirs) / kArcsecToRad);
      double hor[3] = {};
      swe_azalt(s.time.jdUt1, SE_EQU2HOR, geopos, 0.0, 0.0, xx, hor);
      sweSidereal.add(std::remainder(swe_sidtime(s.time.jdUt1) * 3600.0 -
                                         (last - o.longitudeRad) / kTwoPi * 86400.0, 86400.0));
      if (b >= 1) {
        double attr[20] = {};
        ASSERT_GE(swe_pheno(s.time.jdTt, sweBody[b], SEFLG_SWIEPH | SEFLG_TOPOCTR, attr, err), 0) << err;
        if (b == 1) {
          phase.add(s.moon.phaseAngleRad / kDegToRad - attr[0]);
        } else {
          // Mallama & Hilton (2018) in both; Swiss adds Mars' orbital/rotational terms.
          mag[b - 2].add(s.planets[static_cast<std::size_t>(b - 2)].magnitude - attr[4]);
        }
      }
    }
  }
  std::printf("\n%-8s %28s %28s\n", "body", "RA/Dec vs Swiss: max, RMS", "az/alt vs Swiss+ERFA: max, RMS");
  for (int b = 0; b < kBodies; ++b)
    std::printf("%-8s %12.3f\" %12.3f\"  %12.3f\" %12.3f\"\n", names[b], pos[b].max, pos[b].rms(), azalt[b].max,
                azalt[b].rms());
  std::printf("(swe_sidtime - eraGst06a: max %.4f s, RMS %.4f s)\n", sweSidereal.max, sweSidereal.rms());
  std::printf("moon phase angle vs Swiss: max %.4f deg, RMS %.4f deg\n", phase.max, phase.rms());
  for (int p = 0; p < 5; ++p) std::printf("%-8s magnitude vs Swiss: max %.3f, RMS %.3f\n", names[p + 2], mag[p].max, mag[p].rms());
  for (int b = 0; b < kBodies; ++b) EXPECT_LT(azalt[b].max, limitArcsec[b] + 0.5) << names[b];
  EXPECT_LT(phase.max, 0.01);
  for (int p = 0; p < 5; ++p) EXPECT_LT(mag[p].max, p == 2 ? 0.2 : 0.05) << names[p + 2];
}

TEST(ReferenceComparison, SiderealTimeAndStarsAgainstErfa) {
  std::mt19937_64 rng(4242);
  const std::vector<Star> stars = brightestStars(loadStarCatalogue(std::string(SKYIG_SOURCE_DIR) + "/ephemeris/data/bsc5.csv"), 300);
  Stat gast, star, starGpu;
  for (int k = 0; k < 200; ++k) {
    // ERFA's UTC uses the same leap-second table from 1972 on; before that it models the
    // rubber-second UTC of 1961-1971, so the comparison starts in 1973.
    const UtcTime t = randomInstant(rng, 1973, 2100);
    Observer o = randomObserver(rng);
    const double dut1 = std::uniform_real_distribution<double>(-0.9, 0.9)(rng);
    EphemerisOptions opt;
    opt.dut1S = dut1;
    const SkyEphemeris s = computeEphemeris(t, o, opt);
    const double g = eraGst06a(s.time.jdUt1, 0.0, s.time.jdTt, 0.0);
    gast.add(std::remainder(s.gastRad - g, kTwoPi) / kTwoPi * 86400.0);
    double utc1 = 0.0, utc2 = 0.0;
    ASSERT_GE(eraDtf2d("UTC", t.year, t.month, t.day, 0, 0, 0.0, &utc1, &utc2), 0);
    utc2 += t.secondsOfDay / 86400.0;
    for (std::size_t i = k % 10; i < stars.size(); i += 10) {
      const Star& st = stars[i];
      double aob = 0, zob = 0, hob = 0, dob = 0, rob = 0, eo = 0;
      const int j = eraAtco13(st.raRad, st.decRad, st.pmRaCosDecRadPerYear / std::cos(st.decRad), st.pmDecRadPerYear,
                              0.0, 0.0, utc1, utc2, dut1, o.longitudeRad, o.latitudeRad, o.heightM, 0.0, 0.0,
                              0.0, 0.0, 0.0, 0.55, &aob, &zob, &hob, &dob, &rob, &eo);
      ASSERT_GE(j, 0);
      const Vec3 theirs{std::sin(zob) * std::sin(aob), std::sin(zob) * std::cos(aob), std::cos(zob)};
      const BodyPosition mine = starPosition(st, s);
      star.add(angleBetween(mine.enu, theirs) / kArcsecToRad);
      // The renderer's recipe (matrix and aberration, no light deflection), away from the sun.
      const Vec3 gpu = s.j2000ToEnu * normalized(starDirectionAt(st, s.time.jdTt) + s.aberrationJ2000);
      if (angleBetween(gpu, s.sun.enu) > kDegToRad) starGpu.add(angleBetween(gpu, theirs) / kArcsecToRad);
    }
  }
  std::printf("\nGAST vs eraGst06a: max %.6f s, RMS %.6f s (%d instants)\n", gast.max, gast.rms(), gast.n);
  std::printf("bright stars vs eraAtco13 (airless): max %.3f\", RMS %.3f\" (%d star places)\n", star.max, star.rms(), star.n);
  std::printf("bright stars, renderer recipe (J2000->ENU matrix + aberration vector), more than 1 deg "
              "from the sun: max %.3f\", RMS %.3f\"\n", starGpu.max, starGpu.rms());
  EXPECT_LT(gast.max, 0.01);
  EXPECT_LT(star.max, 1.0);
  EXPECT_LT(starGpu.max, 1.0);
}
#else
TEST(ReferenceComparison, Skipped) {
  GTEST_SKIP() << "Swiss Ephemeris (libswe-dev, swe-basic-data) or ERFA (liberfa-dev) was not found when "
                  "configuring: the comparison with independent ephemerides is skipped";
}
#endif
