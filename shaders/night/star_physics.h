#pragma once
// The night point-source GLSL (shaders/night/star_psf.glsl, point_source_visibility.glsl) compiled as C++ in double precision,
// as shaders/physics.h does for the sky, so tests check the code the star pass runs.
#include "common/glsl_cpp_begin.h"
#include "night/star_psf.glsl"
#include "night/point_source_visibility.glsl"
#include "common/glsl_cpp_end.h"
