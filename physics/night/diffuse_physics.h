#pragma once
// physics/night/{units,milky_way,zodiacal,airglow}.glsl compiled as C++ in double precision (the
// pattern of physics/physics.h), for the CPU side of the diffuse night sky and its tests.
#include "physics/common/glsl_cpp_begin.h"
#include "physics/night/units.glsl"
#include "physics/night/milky_way.glsl"
#include "physics/night/zodiacal.glsl"
#include "physics/night/airglow.glsl"
#include "physics/common/glsl_cpp_end.h"
