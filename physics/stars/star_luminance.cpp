#include "physics/stars/star_luminance.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::sky::night {

PointSourceLuminance starLuminance(const StarField& field, const glm::dvec3& direction, double coneRadiusRad) {
  const double length = glm::length(direction);
  if (!std::isfinite(length) || length <= 0.0)
    throw std::invalid_argument("star probe direction has length " + std::to_string(length));
  if (!(coneRadiusRad > 0.0 && coneRadiusRad <= std::numbers::pi / 2.0))
    throw std::invalid_argument("star probe cone radius " + std::to_string(coneRadiusRad) + " rad is outside (0, pi/2]");
  const glm::dvec3 d = direction / length;
  const double cosRadius = std::cos(coneRadiusRad);
  const double solidAngle = 2.0 * std::numbers::pi * (1.0 - cosRadius);
  PointSourceLuminance out;
  for (const auto* list : {&field.stars, &field.planets})
    for (const PointSource& p : *list)
      if (glm::dot(p.direction, d) >= cosRadius) {
        out.rec709 += p.rec709Lux / solidAngle;
        out.luminance += p.illuminanceLux / solidAngle;
        ++out.count;
      }
  return out;
}

}  // namespace skyig::sky::night
