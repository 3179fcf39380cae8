#pragma once
// shaders/night/{units,milky_way,zodiacal,airglow}.glsl compiled as C++ in double precision (the
// pattern of shaders/physics.h), for the CPU side of the diffuse night sky and its tests.
#include "common/glsl_cpp_begin.h"
#include "night/units.glsl"
#include "night/milky_way.glsl"
#include "night/zodiacal.glsl"
#include "night/airglow.glsl"
#include "common/glsl_cpp_end.h"
