#pragma once
// shaders/night/moon.glsl compiled as C++ in double precision (the pattern of shaders/physics.h),
// for the CPU side of the moon (sky/night/moon_disc.h) and its tests.
#include "common/glsl_cpp_begin.h"
#include "night/moon.glsl"
#include "common/glsl_cpp_end.h"
