#include "calibration/region_camera.h"

#include "sky/camera.h"

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

}  // namespace skyig::calibration
