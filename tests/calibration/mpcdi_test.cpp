// The readers against fixtures that encode one known warp (tests/data/calibration/
// make_fixtures.py): both PFM conventions, the zip and the folder form, 3D points in a
// surveyor's axes, and Paul Bourke's mesh all give the same image points, so the same sky
// directions, within one projector pixel.
#include "calibration/load.h"
#include "calibration/region_camera.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
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
