// The Bright Star Catalogue loader: the shipped file and corrupt ones.
#include "ephemeris/bsc5.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

using namespace skyig::ephemeris;

namespace {
std::string cataloguePath() { return std::string(SKYIG_SOURCE_DIR) + "/ephemeris/data/bsc5.csv"; }

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = std::string(SKYIG_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

constexpr const char* kHeader =
    "HR,RA_J2000_deg,Dec_J2000_deg,pmRA_arcsec_per_yr,pmDec_arcsec_per_yr,Vmag,B_V,name,parallax_arcsec,radvel_km_s\n";

void expectErrorMentions(const std::string& path, const std::string& what) {
  try {
    loadStarCatalogue(path);
    FAIL() << "no error for " << path;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(StarCatalogue, LoadsTheShippedCatalogue) {
  const std::vector<Star> stars = loadStarCatalogue(cataloguePath());
  EXPECT_EQ(stars.size(), 9096u);  // 9110 HR numbers less the 14 non-stellar entries
  const std::vector<Star> bright = brightestStars(stars, 3);
  // Sirius (HR 2491, V -1.46), Canopus (HR 2326, -0.72), then Arcturus (HR 5340, -0.04).
  EXPECT_EQ(bright[0].hr, 2491);
  EXPECT_NEAR(bright[0].vmag, -1.46, 1e-9);
  EXPECT_EQ(bright[1].hr, 2326);
  // Sirius: RA 6h45m08.9s, Dec -16 42' 58" (J2000), proper motion -0.553"/yr, -1.205"/yr.
  const Star& sirius = bright[0];
  EXPECT_NEAR(sirius.raRad / kDegToRad, (6 + 45 / 60.0 + 8.9 / 3600.0) * 15.0, 0.001);
  EXPECT_NEAR(sirius.decRad / kDegToRad, -(16 + 42 / 60.0 + 58 / 3600.0), 0.001);
  EXPECT_NEAR(sirius.pmDecRadPerYear / kArcsecToRad, -1.205, 0.01);
  EXPECT_NEAR(norm(sirius.directionJ2000), 1.0, 1e-15);
  ASSERT_TRUE(sirius.bMinusV.has_value());
  EXPECT_NEAR(*sirius.bMinusV, 0.0, 0.02);
}

TEST(StarCatalogue, ProperMotionOf61CygniA) {
  // 61 Cygni A (HR 8085) moves 5.2"/yr, among the fastest stars of the catalogue.
  const std::vector<Star> stars = loadStarCatalogue(cataloguePath());
  const Star* cyg = nullptr;
  for (const Star& s : stars)
    if (s.hr == 8085) cyg = &s;
  ASSERT_NE(cyg, nullptr);
  const double total = std::hypot(cyg->pmRaCosDecRadPerYear, cyg->pmDecRadPerYear);
  EXPECT_NEAR(total / kArcsecToRad, 5.2, 0.15);
  const double moved = angleBetween(starDirectionAt(*cyg, 2451545.0 + 100 * 365.25), cyg->directionJ2000);
  EXPECT_NEAR(moved / total, 100.0, 0.01);
}

TEST(StarCatalogue, ClearErrorsForBadFiles) {
  expectErrorMentions("/nonexistent/bsc5.csv", "/nonexistent/bsc5.csv");
  expectErrorMentions(writeTemp("stars_bad_header.csv", "# c\nHR,RA\n1,2\n"), "stars_bad_header.csv:2: unexpected header");
  expectErrorMentions(writeTemp("stars_bad_number.csv", std::string(kHeader) + "1,1.29,45.2,-0.012,-0.018,6.70,0.07,,,-18\n"
                                                        "2,abc,-0.5,0.045,-0.060,6.29,1.10,,,14\n"),
                      "stars_bad_number.csv:3: column RA_J2000_deg value 'abc' is not a number");
  expectErrorMentions(writeTemp("stars_bad_dec.csv", std::string(kHeader) + "1,1.29,95.2,-0.012,-0.018,6.70,0.07,,,-18\n"),
                      "stars_bad_dec.csv:2: column Dec_J2000_deg value 95.2 is outside");
  expectErrorMentions(writeTemp("stars_short.csv", std::string(kHeader) + "1,1.29,45.2\n"),
                      "stars_short.csv:2: expected 10 comma-separated fields, found 3");
  expectErrorMentions(writeTemp("stars_empty.csv", ""), "no header");
  expectErrorMentions(writeTemp("stars_dup.csv", std::string(kHeader) + "1,1.29,45.2,0,0,6.70,,,,\n1,1.29,45.2,0,0,6.70,,,,\n"),
                      "HR 1 appears twice");
}
