// The readers against fixtures that encode one known warp (tests/data/calibration/
// make_fixtures.py): both PFM conventions, the zip and the folder form, 3D points in a
// surveyor's axes, and Paul Bourke's mesh all give the same image points, so the same sky
// directions, within one projector pixel.
#include "calibration/load.h"
#include "calibration/region_camera.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace {

using namespace skyig::calibration;

const std::string kData = std::string(SKYIG_SOURCE_DIR) + "/tests/data/calibration/";
constexpr int kGridW = 9, kGridH = 6;
using skyig::kDeg;

// make_fixtures.py's warp and blend.
glm::dvec2 fixtureUv(double s, double t) {
  return {0.05 + 0.9 * s + 0.03 * std::sin(std::numbers::pi * t), 0.1 + 0.8 * t + 0.02 * s * s};
}
double fixtureAlpha(double s) { return s < 0.7 ? 1.0 : std::max(0.0, 1.0 - (s - 0.7) / 0.3); }

RegionCamera fixtureCamera() {
  RegionCamera c;
  c.offset = {10.0, -5.0, 2.0};
  c.frustum = {30.0, 25.0, 15.0, 20.0};
  return c;
}

// The angle one projector pixel spans at the fixture's scale: the camera's horizontal field
// over the projector's 64 columns.
double onePixelRad() { return (55.0 * kDeg) / 64.0; }

void expectFixtureWarp(const ProjectorCalibration& p, double uvTolerance) {
  ASSERT_EQ(p.warp.width, kGridW);
  ASSERT_EQ(p.warp.height, kGridH);
  ASSERT_EQ(p.warp.channels, 2);
  const RegionCamera camera = fixtureCamera();
  for (int j = 0; j < kGridH; ++j)
    for (int i = 0; i < kGridW; ++i) {
      const glm::dvec2 want = fixtureUv(i / double(kGridW - 1), j / double(kGridH - 1));
      const glm::dvec2 got(p.warp.at(i, j, 0), p.warp.at(i, j, 1));
      EXPECT_NEAR(got.x, want.x, uvTolerance) << "node " << i << "," << j;
      EXPECT_NEAR(got.y, want.y, uvTolerance) << "node " << i << "," << j;
      // The direction that projector pixel shows, against the one the fixture was made from.
      const double angle = std::acos(std::min(1.0, glm::dot(directionOfUv(camera, got), directionOfUv(camera, want))));
      EXPECT_LT(angle, onePixelRad()) << "node " << i << "," << j;
    }
}

TEST(Mpcdi, AbsoluteWarpValuesAreTheImagePoints) {
  const ProjectorCalibration p = loadProjector(mpcdiSource(kData + "warp_absolute.mpcdi", "p1", WarpValues::Absolute));
  EXPECT_EQ(p.width, 64);
  EXPECT_EQ(p.height, 40);
  ASSERT_TRUE(p.cameraGiven);
  EXPECT_DOUBLE_EQ(p.camera.offset.yawDeg, 10.0);
  EXPECT_DOUBLE_EQ(p.camera.offset.pitchDeg, -5.0);
  EXPECT_DOUBLE_EQ(p.camera.offset.rollDeg, 2.0);
  EXPECT_DOUBLE_EQ(p.camera.frustum.leftDeg, 30.0);  // leftAngle -30 is 30 degrees to the left
  EXPECT_DOUBLE_EQ(p.camera.frustum.rightDeg, 25.0);
  EXPECT_DOUBLE_EQ(p.camera.frustum.downDeg, 15.0);
  EXPECT_DOUBLE_EQ(p.camera.frustum.upDeg, 20.0);
  expectFixtureWarp(p, 1e-6);
}

TEST(Mpcdi, OffsetWarpValuesInAFolderGiveTheSameDirections) {
  const ProjectorCalibration p = loadProjector(mpcdiSource(kData + "warp_offset", "p1", WarpValues::Offset));
  expectFixtureWarp(p, 1e-6);
  // Read as absolute, the same file is wrong by the grid: the convention matters.
  const ProjectorCalibration wrong = loadProjector(mpcdiSource(kData + "warp_offset", "p1", WarpValues::Absolute));
  EXPECT_GT(std::abs(wrong.warp.at(kGridW - 1, 0, 0) - p.warp.at(kGridW - 1, 0, 0)), 0.9);
}

TEST(Mpcdi, PointsOfAnAdvancedProfileAreSeenFromItsEye) {
  const ProjectorCalibration p = loadProjector(mpcdiSource(kData + "points_a3.mpcdi", "p1", WarpValues::Absolute));
  expectFixtureWarp(p, 1e-5);  // float points 3 m away: ~1e-7 rad
}

// The reference library's a3 example has no <frustum>: the region's camera is then made to cover
// its points (as skyig dome makes its regions'), and every node shows the same direction it
// shows through points_a3's own frustum (the same points), within the image (1 degree of margin).
// The fixture is in the SDK's conventions (tests/data/calibration/make_fixtures.py), its
// gammaEmbedded 0 read as not given, with a warning.
TEST(Mpcdi, AnA3RegionWithoutAFrustumGetsACameraCoveringItsPoints) {
  const ProjectorCalibration given = loadProjector(mpcdiSource(kData + "points_a3.mpcdi", "p1", WarpValues::Absolute));
  const ProjectorCalibration made = loadProjector(mpcdiSource(kData + "sdk_a3.mpcdi", "r1", WarpValues::Absolute));
  EXPECT_TRUE(made.cameraGiven);  // the renderer draws the region through the camera its warp was mapped with
  ASSERT_EQ(made.warnings.size(), 2u);
  EXPECT_NE(made.warnings[0].find("no <frustum>: its camera is made to cover the region's points"), std::string::npos);
  EXPECT_NE(made.warnings[1].find("<gammaEmbedded> 0 read as not given"), std::string::npos);
  ASSERT_EQ(made.warp.width, given.warp.width);
  ASSERT_EQ(made.warp.height, given.warp.height);
  double worst = 0.0, lowest = 1.0, highest = 0.0;
  for (int y = 0; y < made.warp.height; ++y)
    for (int x = 0; x < made.warp.width; ++x) {
      const glm::dvec2 a(given.warp.at(x, y, 0), given.warp.at(x, y, 1)), b(made.warp.at(x, y, 0), made.warp.at(x, y, 1));
      if (std::isnan(a.x)) continue;
      ASSERT_FALSE(std::isnan(b.x)) << x << "," << y;
      const glm::dvec3 da = directionOfUv(given.camera, a), db = directionOfUv(made.camera, b);
      worst = std::max(worst, std::acos(std::clamp(glm::dot(da, db), -1.0, 1.0)));
      lowest = std::min({lowest, b.x, b.y});
      highest = std::max({highest, b.x, b.y});
    }
  EXPECT_LT(worst, 1e-5);  // radians
  EXPECT_GT(lowest, 0.0);
  EXPECT_LT(highest, 1.0);
  std::printf("a3 without a frustum: camera yaw %.2f pitch %.2f roll %.2f, half-angles %.2f %.2f %.2f %.2f deg; "
              "nodes within u, v [%.3f, %.3f]\n", made.camera.offset.yawDeg, made.camera.offset.pitchDeg,
              made.camera.offset.rollDeg, made.camera.frustum.leftDeg, made.camera.frustum.rightDeg,
              made.camera.frustum.downDeg, made.camera.frustum.upDeg, lowest, highest);
}

// Each profile as VESA's reference library writes it (tests/data/calibration/make_fixtures.py:
// Xresolution, files at the zip's root, the SDK's frustum order and PFM header): 2d without a
// camera, 3d and sl with the file's frustum as the region's camera, three sl regions each with
// its own, and every warp the fixtures' uv().
TEST(Mpcdi, EveryProfileAsTheReferenceLibraryWritesItLoads) {
  const ProjectorCalibration flat = loadProjector(mpcdiSource(kData + "sdk_2d.mpcdi", "r1", WarpValues::Absolute));
  EXPECT_FALSE(flat.cameraGiven);
  EXPECT_EQ(flat.width, 64);
  expectFixtureWarp(flat, 1e-6);
  auto expectFrustum = [](const ProjectorCalibration& p, double yawDeg) {
    ASSERT_TRUE(p.cameraGiven) << p.source;
    EXPECT_DOUBLE_EQ(p.camera.offset.yawDeg, yawDeg) << p.source;
    EXPECT_DOUBLE_EQ(p.camera.offset.pitchDeg, -5.0);
    EXPECT_DOUBLE_EQ(p.camera.offset.rollDeg, 2.0);
    EXPECT_DOUBLE_EQ(p.camera.frustum.leftDeg, 30.0);
    EXPECT_DOUBLE_EQ(p.camera.frustum.rightDeg, 25.0);
    EXPECT_DOUBLE_EQ(p.camera.frustum.downDeg, 15.0);
    EXPECT_DOUBLE_EQ(p.camera.frustum.upDeg, 20.0);
  };
  const ProjectorCalibration simulation = loadProjector(mpcdiSource(kData + "sdk_3d.mpcdi", "r1", WarpValues::Absolute));
  expectFrustum(simulation, 10.0);
  expectFixtureWarp(simulation, 1e-6);
  const ProjectorCalibration lamp = loadProjector(mpcdiSource(kData + "sdk_sl.mpcdi", "r1", WarpValues::Absolute));
  expectFrustum(lamp, 10.0);
  expectFixtureWarp(lamp, 1e-5);
  for (const auto& [region, yaw] : {std::pair{"r1", -40.0}, std::pair{"r2", 10.0}, std::pair{"r3", 60.0}}) {
    const ProjectorCalibration p = loadProjector(mpcdiSource(kData + "sdk_sl_three.mpcdi", region, WarpValues::Absolute));
    expectFrustum(p, yaw);
    expectFixtureWarp(p, 1e-5);
  }
}

// The 3d fixture's alpha map holds three components (componentDepth 3): each colour keeps its
// own weight, green and blue 0.8 and 0.6 of red in light, the embedded gamma taken out of each.
TEST(Mpcdi, AThreeComponentAlphaMapKeepsEachColoursWeight) {
  const ProjectorCalibration p = loadProjector(mpcdiSource(kData + "sdk_3d.mpcdi", "r1", WarpValues::Absolute));
  ASSERT_EQ(p.alpha.channels, 3);
  ASSERT_EQ(p.alpha.width, 16);
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(p.alpha.at(i, 3, 0), fixtureAlpha(i / 15.0), 2e-4) << i;
    EXPECT_NEAR(p.alpha.at(i, 3, 1), 0.8 * fixtureAlpha(i / 15.0), 2e-4) << i;
    EXPECT_NEAR(p.alpha.at(i, 3, 2), 0.6 * fixtureAlpha(i / 15.0), 2e-4) << i;
  }
}

TEST(Mpcdi, TheAlphaMapsEmbeddedGammaIsTakenOut) {
  const ProjectorCalibration p = loadProjector(mpcdiSource(kData + "warp_absolute.mpcdi", "p1", WarpValues::Absolute));
  ASSERT_EQ(p.alpha.width, 16);
  ASSERT_EQ(p.alpha.height, 10);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(p.alpha.at(i, 3), fixtureAlpha(i / 15.0), 2e-4) << i;  // 16-bit steps
  ASSERT_EQ(p.beta.width, 16);
  EXPECT_NEAR(p.beta.at(15, 0), 0.001, 2e-5);
  EXPECT_NEAR(p.beta.at(0, 0), 0.0, 2e-5);
}

TEST(BourkeMesh, AMeshShowsTheSamePointsWithItsVFlipped) {
  const ProjectorCalibration p = loadProjector(bourkeSource(kData + "mesh_bourke.txt", 64, 40));
  EXPECT_FALSE(p.cameraGiven);  // the channel's own camera
  EXPECT_EQ(p.width, 64);
  expectFixtureWarp(p, 2e-6);  // six decimals in the text
  for (int i = 0; i < kGridW; ++i) EXPECT_NEAR(p.alpha.at(i, 2), fixtureAlpha(i / double(kGridW - 1)), 1e-5);
}

TEST(RegionCamera, ImagePointsAndDirectionsAreInverse) {
  const RegionCamera c = fixtureCamera();
  for (const glm::dvec2 uv : {glm::dvec2(0.5, 0.5), glm::dvec2(0.0, 0.0), glm::dvec2(1.0, 0.25), glm::dvec2(0.3, 0.9)}) {
    const auto back = uvOfDirection(c, directionOfUv(c, uv));
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, uv.x, 1e-12);
    EXPECT_NEAR(back->y, uv.y, 1e-12);
  }
  // The image's top-left corner is left of and above its centre (v grows downwards).
  const glm::dvec3 centre = directionOfUv(c, {0.5, 0.5}), corner = directionOfUv(c, {0.0, 0.0});
  EXPECT_LT(corner.z, centre.z);  // z down: the corner is higher
  EXPECT_FALSE(uvOfDirection(c, -centre));  // behind the camera
}

}  // namespace
