#include "calibration/region_camera.h"

#include "sky/camera.h"

namespace skyig::calibration {

namespace {

// The image's normalised device coordinates (x right, y up, 1) -> the body frame, for an
// ownship at zero attitude (the body frame is then north-east-down in ENU).
glm::dmat3 ndcToBody(const RegionCamera& camera) {
  const glm::dmat3 enuToBody = glm::inverse(sky::bodyToEnu({}));
  return enuToBody * sky::ndcToWorld(sky::eyeToEnu({}, camera.offset), camera.frustum);
}

}  // namespace

glm::dvec3 directionOfUv(const RegionCamera& camera, const glm::dvec2& uv) {
  return glm::normalize(ndcToBody(camera) * glm::dvec3(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y, 1.0));
}

std::optional<glm::dvec2> uvOfDirection(const RegionCamera& camera, const glm::dvec3& bodyDirection) {
  const glm::dvec3 q = glm::inverse(ndcToBody(camera)) * bodyDirection;
  if (!(q.z > 0.0)) return std::nullopt;
  return glm::dvec2(0.5 * (q.x / q.z + 1.0), 0.5 * (1.0 - q.y / q.z));
}

}  // namespace skyig::calibration
