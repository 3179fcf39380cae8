#pragma once
// shaders/night/{units,milky_way,zodiacal,airglow}.glsl compiled as C++ in double precision (the
// pattern of shaders/physics.h), for the CPU side of the diffuse night sky and its tests.
#include "common/glsl_cpp.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
namespace skyig::shader {
namespace {
using namespace glm;
using namespace glsl_types;
using std::log;
using std::pow;
using std::sqrt;
#include "night/units.glsl"
#include "night/milky_way.glsl"
#include "night/zodiacal.glsl"
#include "night/airglow.glsl"
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
