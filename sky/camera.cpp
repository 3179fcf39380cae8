#include "sky/camera.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skyig::sky {

namespace {
using skyig::kDeg;
}

glm::dmat3 bodyToEnu(const Attitude& a) {
  const double cy = std::cos(a.yawDeg * kDeg), sy = std::sin(a.yawDeg * kDeg);
  const double cp = std::cos(a.pitchDeg * kDeg), sp = std::sin(a.pitchDeg * kDeg);
  const double cr = std::cos(a.rollDeg * kDeg), sr = std::sin(a.rollDeg * kDeg);
  // glm is column-major: each dvec3 below is one column.
  const glm::dmat3 yaw(glm::dvec3(cy, sy, 0), glm::dvec3(-sy, cy, 0), glm::dvec3(0, 0, 1));
  const glm::dmat3 pitch(glm::dvec3(cp, 0, -sp), glm::dvec3(0, 1, 0), glm::dvec3(sp, 0, cp));
  const glm::dmat3 roll(glm::dvec3(1, 0, 0), glm::dvec3(0, cr, sr), glm::dvec3(0, -sr, cr));
  // North-east-down to east-north-up: swap the horizontal axes and flip the vertical.
  const glm::dmat3 nedToEnu(glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1));
  return nedToEnu * yaw * pitch * roll;
}

glm::dmat3 eyeToEnu(const Attitude& ownship, const Attitude& channelOffset) {
  // The offset rotates the eye within the body frame (eye -> body), so it must not carry the
  // NED->ENU swap that bodyToEnu includes: take it out with the inverse of the zero attitude.
  return bodyToEnu(ownship) * glm::inverse(bodyToEnu({})) * bodyToEnu(channelOffset);
}

glm::dmat3 ndcToWorld(const glm::dmat3& eye, const Frustum& f) {
  const double l = -std::tan(f.leftDeg * kDeg), r = std::tan(f.rightDeg * kDeg);
  const double d = -std::tan(f.downDeg * kDeg), u = std::tan(f.upDeg * kDeg);
  // Eye-frame ray (x forward, y right, z down) for (x_ndc, y_ndc, 1): forward 1,
  // right mix(l, r), down -mix(d, u) — the inverse projection evaluated on the plane x = 1.
  const glm::dmat3 k(glm::dvec3(0.0, 0.5 * (r - l), 0.0),          // x_ndc column
                     glm::dvec3(0.0, 0.0, -0.5 * (u - d)),         // y_ndc column
                     glm::dvec3(1.0, 0.5 * (r + l), -0.5 * (u + d)));  // constant column
  return eye * k;
}

glm::dvec3 pixelRay(const glm::dmat3& m, int column, int row, int width, int height) {
  const double x = 2.0 * (column + 0.5) / width - 1.0;
  const double y = 1.0 - 2.0 * (row + 0.5) / height;
  return glm::normalize(m * glm::dvec3(x, y, 1.0));
}

double largestPixelAngleRad(const Frustum& f, int width, int height) {
  const double across = (std::tan(f.leftDeg * kDeg) + std::tan(f.rightDeg * kDeg)) / std::max(width, 1);
  const double down = (std::tan(f.upDeg * kDeg) + std::tan(f.downDeg * kDeg)) / std::max(height, 1);
  return std::max(across, down);
}

}  // namespace skyig::sky
