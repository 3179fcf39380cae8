#pragma once
// Lets the physics in physics/*/*.glsl compile as C++ against GLM, in double precision, so the
// tests check the very code the GPU runs (the pattern of Bruneton's 2017 reference code,
// which uses IN/OUT the same way). Included by physics/common/glsl_cpp_begin.h, the prologue of the
// headers that do so (and by physics/atmosphere/atmosphere_physics.h for its parameter struct).
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

// For the rare line that differs between the two compilers (a GPU's hardware against the CPU's
// double precision); each use says why.
#define SKYIG_GLSL_AS_CPP 1

namespace skyig::shader::glsl_types {
using Float = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using mat3 = glm::dmat3;
using mat4 = glm::dmat4;
}  // namespace skyig::shader::glsl_types

// Parameter qualifiers: GLSL's `in`/`out`/`inout` become references in C++.
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
