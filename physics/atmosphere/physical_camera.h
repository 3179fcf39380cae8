#pragma once

#include "physics/atmosphere/model.h"

#include <glm/glm.hpp>

namespace skyig::atmosphere {

// The camera of an observer at `heightM` above the model's ground, on the local vertical: where
// the sky pass and every CPU probe of the physical sky put the eye.
glm::dvec3 physicalCamera(const atmosphere::AtmosphereModel& model, double heightM);

}  // namespace skyig::atmosphere
