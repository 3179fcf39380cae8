// Camera conventions (docs/design.md "Frames"): ENU world, CIGI body axes, yaw/pitch/roll.
#include "sky/camera.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig::sky;

namespace {
using skyig::kDeg;
constexpr int kW = 200, kH = 100;

glm::dvec3 centreRay(const Attitude& own, const Attitude& offset = {}, const Frustum& f = {}) {
  const glm::dmat3 m = ndcToWorld(eyeToEnu(own, offset), f);
  return glm::normalize(m * glm::dvec3(0.0, 0.0, 1.0));
}

double elevationDeg(const glm::dvec3& v) { return std::asin(v.z) / kDeg; }
double azimuthDeg(const glm::dvec3& v) {
  const double a = std::atan2(v.x, v.y) / kDeg;
  return a < 0 ? a + 360.0 : a;
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
}  // namespace

TEST(Camera, ZeroAttitudeLooksNorthLevel) { expectNear(centreRay({}), {0, 1, 0}); }

TEST(Camera, Yaw90LooksEast) { expectNear(centreRay({90, 0, 0}), {1, 0, 0}); }

TEST(Camera, PitchUpRaisesTheViewAndPutsTheHorizonBelowCentre) {
  const glm::dvec3 c = centreRay({0, 30, 0});
  EXPECT_NEAR(elevationDeg(c), 30.0, 1e-9);
  // The horizon (elevation 0) crosses the middle column below the centre row.
  const glm::dmat3 m = ndcToWorld(eyeToEnu({0, 30, 0}, {}), Frustum{30, 30, 40, 40});
  int horizonRow = -1;
  for (int row = 0; row < kH; ++row)
    if (pixelRay(m, kW / 2, row, kW, kH).z < 0.0) {
      horizonRow = row;
      break;
    }
  EXPECT_GT(horizonRow, kH / 2);
}

// Roll right wing down: the right of the picture looks below the horizon and the left above
// it, so on the screen the horizon runs higher on the right than on the left.
TEST(Camera, RollRightWingDownTiltsTheHorizon) {
  const glm::dmat3 m = ndcToWorld(eyeToEnu({0, 0, 20}, {}), Frustum{});
  const glm::dvec3 right = pixelRay(m, kW - 1, kH / 2, kW, kH);
  const glm::dvec3 left = pixelRay(m, 0, kH / 2, kW, kH);
  EXPECT_LT(right.z, 0.0);
  EXPECT_GT(left.z, 0.0);
  // The view axis itself stays level and north.
  expectNear(centreRay({0, 0, 20}), {0, 1, 0});
}

// A channel offset is a rotation in the body frame, composed after the ownship attitude.
TEST(Camera, ChannelOffsetsComposeWithAttitude) {
  // Heading east, a channel yawed 60 deg left looks north-east.
  EXPECT_NEAR(azimuthDeg(centreRay({90, 0, 0}, {-60, 0, 0})), 30.0, 1e-9);
  // A chin window (pitch -40) of a helicopter pitched 10 deg nose up looks 30 deg down.
  EXPECT_NEAR(elevationDeg(centreRay({0, 10, 0}, {0, -40, 0})), -30.0, 1e-9);
  // Rolled 90 deg right, a channel looking right (offset yaw 90) looks straight down.
  expectNear(centreRay({0, 0, 90}, {90, 0, 0}), {0, 0, -1}, 1e-12);
  // Rolled 90 deg right, a channel looking up in the body (offset pitch 90) looks east.
  expectNear(centreRay({0, 0, 90}, {0, 90, 0}), {1, 0, 0}, 1e-12);
}

TEST(Camera, AsymmetricFrustumEdgesAtTheirHalfAngles) {
  const Frustum f{10, 50, 5, 35};
  const glm::dmat3 m = ndcToWorld(eyeToEnu({}, {}), f);
  auto angleFromForward = [&](double x, double y, auto component) {
    const glm::dvec3 v = glm::normalize(m * glm::dvec3(x, y, 1.0));
    return std::atan2(component(v), v.y) / kDeg;
  };
  EXPECT_NEAR(angleFromForward(-1, 0, [](auto v) { return -v.x; }), 10.0, 1e-9);  // left edge
  EXPECT_NEAR(angleFromForward(1, 0, [](auto v) { return v.x; }), 50.0, 1e-9);    // right edge
  EXPECT_NEAR(angleFromForward(0, -1, [](auto v) { return -v.z; }), 5.0, 1e-9);   // bottom edge
  EXPECT_NEAR(angleFromForward(0, 1, [](auto v) { return v.z; }), 35.0, 1e-9);    // top edge
  // The middle of the screen looks right of and above the view axis.
  const glm::dvec3 c = glm::normalize(m * glm::dvec3(0, 0, 1));
  EXPECT_GT(c.x, 0.0);
  EXPECT_GT(c.z, 0.0);
}
