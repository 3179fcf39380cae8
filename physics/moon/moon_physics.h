#pragma once
// physics/moon/moon.glsl compiled as C++ in double precision (the pattern of physics/physics.h),
// for the CPU side of the moon (physics/moon/moon_disc.h) and its tests.
#include "physics/common/glsl_cpp_begin.h"
#include "physics/moon/moon.glsl"
#include "physics/common/glsl_cpp_end.h"
