#pragma once
// Directions and a region camera's image: where a view direction falls in the image the
// channel renders for a region, and back. Directions are in the body frame (x forward, y right,
// z down; sky/camera.h), image coordinates (u, v) in [0, 1] from the image's top-left corner, v
// down -- the convention of ProjectorCalibration::warp. The sky's own camera math does the work
// (sky::eyeToEnu, sky::ndcToWorld), so a channel and its projector agree by construction.
#include "calibration/projector.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

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

// The camera that covers body-frame `directions` (a projector's footprint on the screen, seen
// from the eye): looking along their mean, rolled so that its right is `rightHint` (the
// projector's raster's right), its half-angles their extremes plus marginDeg. Throws
// CalibrationError naming `name` when they span 180 degrees or more, or a half-angle over 89.
RegionCamera cameraCovering(const std::vector<glm::dvec3>& directions, const glm::dvec3& rightHint, double marginDeg,
                            const std::string& name);

}  // namespace skyig::calibration
