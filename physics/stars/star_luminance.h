#pragma once
// The stars' and planets' share of the night probe (`skyig probe`): a point source has no
// luminance, so the probe reports the mean luminance of a small cone around the view
// direction, the summed illuminance of the sources inside it divided by its solid angle. A
// 0.5 degree radius is about the eye's field for a fixated point (and the moon's diameter):
// one bright star inside gives a finite, resolution-free figure (Sirius: 3e-2 cd/m^2).
#include "physics/stars/star_field.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <numbers>

namespace skyig::sky::night {

inline constexpr double kStarProbeConeRadiusRad = 0.5 * std::numbers::pi / 180.0;

struct PointSourceLuminance {
  glm::dvec3 rec709{0.0};   // linear Rec.709, cd/m^2
  double luminance = 0.0;   // Y, cd/m^2
  int count = 0;            // sources inside the cone
};

// Stars and planets of `field` within `coneRadiusRad` of the ENU direction `direction`
// (normalised here). Throws std::invalid_argument for a zero or non-finite direction or a
// radius outside (0, pi/2].
PointSourceLuminance starLuminance(const StarField& field, const glm::dvec3& direction,
                                   double coneRadiusRad = kStarProbeConeRadiusRad);

}  // namespace skyig::sky::night
