// The prologue of every header that compiles physics/*/*.glsl as C++ (physics/physics.h and the
// others): include it, then the GLSL files, then physics/common/glsl_cpp_end.h. No include guard, as it
// opens a scope each time. What it sets up, once for all of them:
// - GLSL's types and qualifiers (physics/common/glsl_cpp.h) and GLM's functions, with <cmath>'s for
//   scalars (not atan: GLSL's two-argument atan(y, x) is GLM's, std::atan takes one).
// - An anonymous namespace, so every translation unit gets its own copy of the functions: GLSL
//   has no `inline`, and this keeps the shader files free of C++-only words.
// - No warning for the functions and constants a translation unit does not use.
#include "physics/common/glsl_cpp.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
namespace skyig::shader {
namespace {
using namespace glm;
using namespace glsl_types;
using std::abs;
using std::asin;
using std::cos;
using std::exp;
using std::floor;
using std::log;
using std::pow;
using std::sin;
using std::sqrt;
using std::tan;
