#pragma once
// The night point-source GLSL (shaders/night/star_*.glsl) compiled as C++ in double precision,
// as shaders/physics.h does for the sky, so tests check the code the star pass runs.
#include "common/glsl_cpp.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
namespace skyig::shader {
namespace {
using namespace glm;
using namespace glsl_types;
using std::abs;
using std::exp;
#include "night/star_psf.glsl"
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
