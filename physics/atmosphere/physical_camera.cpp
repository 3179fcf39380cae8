#include "physics/atmosphere/physical_camera.h"

#include <algorithm>

namespace skyig::atmosphere {

glm::dvec3 physicalCamera(const atmosphere::AtmosphereModel& model, double heightM) {
  // At least a metre above the ground: the tables' parameterisation is singular on it.
  return {0.0, 0.0, model.parameters(0).bottom_radius + std::max(heightM, 1.0)};
}

}  // namespace skyig::atmosphere
