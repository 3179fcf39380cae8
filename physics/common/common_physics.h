#pragma once
// The constants, colour spaces and refraction every model shares (physics/common/*.glsl), compiled
// as C++ in double precision (physics/README.md).
#include "physics/common/glsl_cpp_begin.h"
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"
#include "physics/common/refraction.glsl"
#include "physics/common/glsl_cpp_end.h"
