#pragma once
// Directions and a region camera's image: where a view direction falls in the image the
// channel renders for a region, and back. Directions are in the body frame (x forward, y right,
// z down; sky/camera.h), image coordinates (u, v) in [0, 1] from the image's top-left corner, v
// down -- the convention of ProjectorCalibration::warp. The sky's own camera math does the work
// (sky::eyeToEnu, sky::ndcToWorld), so a channel and its projector agree by construction.
#include "calibration/projector.h"

#include <glm/glm.hpp>

#include <optional>

namespace skyig::calibration {

// The unit body-frame direction through image point `uv` of `camera`.
glm::dvec3 directionOfUv(const RegionCamera& camera, const glm::dvec2& uv);

// Where `bodyDirection` falls in the image of `camera`; nullopt when it points behind the
// camera. A direction outside the frustum gives u or v outside [0, 1].
std::optional<glm::dvec2> uvOfDirection(const RegionCamera& camera, const glm::dvec3& bodyDirection);

}  // namespace skyig::calibration
