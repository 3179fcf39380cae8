#pragma once
// Channel cameras. Frames: ENU world (x east, y north, z up); CIGI body axes (x forward,
// y right, z down); attitude as yaw (true heading, clockwise from north), pitch (nose up),
// roll (right wing down), applied in that order. Angles in degrees at this interface.
#include <glm/glm.hpp>

namespace skyig::sky {

struct Attitude {
  double yawDeg = 0.0;
  double pitchDeg = 0.0;
  double rollDeg = 0.0;
};

// Half-angles of a possibly asymmetric frustum, degrees, each in (0, 89].
struct Frustum {
  double leftDeg = 30.0;
  double rightDeg = 30.0;
  double downDeg = 24.0;
  double upDeg = 24.0;
};

// Columns: the body x, y, z axes expressed in ENU (R = P_ned->enu Rz(yaw) Ry(pitch) Rx(roll)).
glm::dmat3 bodyToEnu(const Attitude& attitude);

// A channel's eye frame: the ownship attitude composed with the channel's eyepoint rotation,
// which is itself a yaw/pitch/roll in the body frame.
glm::dmat3 eyeToEnu(const Attitude& ownship, const Attitude& channelOffset);

// Wang, Ji & Zhang 2011, eq. 22 (the view ray from the inverse projection) as a matrix:
// (x_ndc, y_ndc, 1) -> the (unnormalised) ENU direction of the view ray through that point of
// the far plane. x_ndc grows to the right, y_ndc upwards.
glm::dmat3 ndcToWorld(const glm::dmat3& eyeToEnu, const Frustum& frustum);

// The unit ENU view ray through the centre of pixel (column, row), row 0 at the top.
glm::dvec3 pixelRay(const glm::dmat3& ndcToWorld, int column, int row, int width, int height);

// The largest angle (rad) a pixel of a width x height channel spans along either axis: the
// pixel's pitch on the image plane at unit distance, since a step dt there turns the ray by
// cos^2(theta) dt <= dt (largest at the projection's centre, tan theta = t).
double largestPixelAngleRad(const Frustum& frustum, int width, int height);

}  // namespace skyig::sky
