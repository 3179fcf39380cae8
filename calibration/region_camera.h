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

// A camera of the body frame (a channel's, a region's or a projector lens's): the eye's axes in
// the body frame, and (x_ndc, y_ndc, 1) -> the body-frame ray through that image point. The
// sky's cameras work in ENU for an ownship's attitude; at zero attitude that is the body frame
// turned by bodyToEnu({}), which these take out.
glm::dmat3 eyeToBody(const skyig::sky::Attitude& offset);
glm::dmat3 ndcToBody(const skyig::sky::Attitude& offset, const skyig::sky::Frustum& frustum);

// The unit body-frame direction through image point `uv` of `camera`.
glm::dvec3 directionOfUv(const RegionCamera& camera, const glm::dvec2& uv);

// Where `bodyDirection` falls in the image of `camera`; nullopt when it points behind the
// camera. A direction outside the frustum gives u or v outside [0, 1].
std::optional<glm::dvec2> uvOfDirection(const RegionCamera& camera, const glm::dvec3& bodyDirection);

}  // namespace skyig::calibration
