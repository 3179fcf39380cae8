#pragma once
// The image intensifier's GLSL (physics/goggle/intensifier.glsl) compiled as C++ in double
// precision, as physics/physics.h does for the sky: the goggle pass's CPU side and the tests use
// the code the GPU runs.
#include "physics/common/glsl_cpp_begin.h"
#include "physics/common/constants.glsl"
#include "physics/goggle/intensifier.glsl"
#include "physics/common/glsl_cpp_end.h"
