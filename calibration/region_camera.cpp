#include "calibration/region_camera.h"

#include "calibration/calibration_error.h"
#include "physics/common/units.h"
#include "sky/camera.h"

#include <algorithm>
#include <cmath>

namespace skyig::calibration {

namespace {

const glm::dmat3& enuToBody() {
  static const glm::dmat3 m = glm::inverse(sky::bodyToEnu({}));
  return m;
}

}  // namespace

glm::dmat3 eyeToBody(const sky::Attitude& offset) { return enuToBody() * sky::eyeToEnu({}, offset); }

glm::dmat3 ndcToBody(const sky::Attitude& offset, const sky::Frustum& frustum) {
  return enuToBody() * sky::ndcToWorld(sky::eyeToEnu({}, offset), frustum);
}

glm::dvec3 directionOfUv(const RegionCamera& camera, const glm::dvec2& uv) {
  return glm::normalize(ndcToBody(camera.offset, camera.frustum) * glm::dvec3(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y, 1.0));
}

std::optional<glm::dvec2> uvOfDirection(const RegionCamera& camera, const glm::dvec3& bodyDirection) {
  const glm::dvec3 q = glm::inverse(ndcToBody(camera.offset, camera.frustum)) * bodyDirection;
  if (!(q.z > 0.0)) return std::nullopt;
  return glm::dvec2(0.5 * (q.x / q.z + 1.0), 0.5 * (1.0 - q.y / q.z));
}

// Looking along the mean direction, rolled like the projector; the half-angles are measured in
// the frame the sky's camera math builds from those angles.
RegionCamera cameraCovering(const std::vector<glm::dvec3>& directions, const glm::dvec3& rightHint, double marginDeg,
                            const std::string& name) {
  glm::dvec3 sum(0.0);
  for (const auto& d : directions) sum += d;
  if (directions.empty() || !(glm::length(sum) > 0.0))
    throw CalibrationError(name + ": no direction to cover (its points surround the eye, or there are none)");
  const glm::dvec3 forward = glm::normalize(sum);
  glm::dvec3 right = rightHint - glm::dot(rightHint, forward) * forward;
  if (!(glm::length(right) >= 1e-6)) right = glm::dvec3(0.0, 1.0, 0.0) - forward.y * forward;
  right = glm::normalize(right);
  const glm::dvec3 down = glm::cross(forward, right);
  // R = Rz(yaw) Ry(pitch) Rx(roll) (sky/camera.cpp), columns forward, right, down.
  RegionCamera camera;
  camera.offset.pitchDeg = std::asin(std::clamp(-forward.z, -1.0, 1.0)) / kDeg;
  camera.offset.yawDeg = std::atan2(forward.y, forward.x) / kDeg;
  camera.offset.rollDeg = std::atan2(right.z, down.z) / kDeg;
  const glm::dmat3 bodyToEye = glm::transpose(eyeToBody(camera.offset));
  double left = 0.0, rightDeg = 0.0, up = 0.0, downDeg = 0.0;
  for (const auto& d : directions) {
    const glm::dvec3 c = bodyToEye * d;
    if (c.x <= 0.0) throw CalibrationError(name + ": its footprint is wider than 180 degrees as seen from the eye");
    const double h = std::atan2(c.y, c.x) / kDeg, v = std::atan2(-c.z, c.x) / kDeg;
    left = std::max(left, -h);
    rightDeg = std::max(rightDeg, h);
    up = std::max(up, v);
    downDeg = std::max(downDeg, -v);
  }
  camera.frustum = {left + marginDeg, rightDeg + marginDeg, downDeg + marginDeg, up + marginDeg};
  for (double a : {camera.frustum.leftDeg, camera.frustum.rightDeg, camera.frustum.downDeg, camera.frustum.upDeg})
    if (!(a > 0.0 && a <= 89.0))
      throw CalibrationError(name + ": its footprint needs a frustum half-angle of " + std::to_string(a) +
                             " degrees as seen from the eye; a region camera covers at most 89");
  return camera;
}

}  // namespace skyig::calibration
