#pragma once
// shaders/night/moon.glsl compiled as C++ in double precision (the pattern of shaders/physics.h),
// for the CPU side of the moon (sky/night/moon_disc.h) and its tests.
#include "common/glsl_cpp.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
namespace skyig::shader {
namespace {
using namespace glm;
using namespace glsl_types;
using std::asin;
using std::cos;
using std::sin;
using std::sqrt;
using std::tan;
#include "night/moon.glsl"
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
