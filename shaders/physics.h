#pragma once
// The physics of the sky, written once in GLSL under shaders/ and compiled here as C++ in
// double precision (docs/design.md, "One source for the physics"). The renderer embeds
// the same files; tests and the CPU side of skyig (adaptation, probe) call them from here.
//
// The functions land in an anonymous namespace so every translation unit gets its own
// copy: GLSL has no `inline`, and this keeps the shader files free of C++-only words.
#include "common/glsl_cpp.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
namespace skyig::shader {
namespace {
using namespace glm;
using namespace glsl_types;
using std::exp;
using std::log;
using std::pow;
using std::sqrt;
// Add one line per physics file, in dependency order.
#include "common/constants.glsl"
#include "common/color.glsl"
#include "sky/cie_general_sky.glsl"
#include "sky/preetham.glsl"
#include "sky/analytic_sky.glsl"
#include "tone/tumblin_rushmeier.glsl"
#include "tone/scotopic.glsl"
#include "tone/tone_reproduction.glsl"
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
