#pragma once
// The night point-source GLSL (physics/stars/star_psf.glsl, point_source_visibility.glsl) compiled as C++ in double precision,
// as physics/physics.h does for the sky, so tests check the code the star pass runs.
#include "physics/common/glsl_cpp_begin.h"
#include "physics/stars/star_psf.glsl"
#include "physics/eye/point_source_visibility.glsl"
#include "physics/common/glsl_cpp_end.h"
