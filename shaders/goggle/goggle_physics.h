#pragma once
// The image intensifier's GLSL (shaders/goggle/intensifier.glsl) compiled as C++ in double
// precision, as shaders/physics.h does for the sky: the goggle pass's CPU side and the tests use
// the code the GPU runs.
#include "common/glsl_cpp_begin.h"
#include "common/constants.glsl"
#include "goggle/intensifier.glsl"
#include "common/glsl_cpp_end.h"
