#pragma once
// The physically based atmosphere (Bruneton & Neyret 2008), written once in GLSL under
// shaders/atmosphere/ and compiled here as C++ in double precision, the same way as
// shaders/physics.h. GLSL's samplers become the CPU tables of atmosphere/cpu_texture.h, so
// the precomputation and the rendering functions run on the CPU for the reference path and
// the tests, and on the GPU with real samplers.
#include "atmosphere/cpu_texture.h"
#include "common/glsl_cpp.h"

// The parameter struct (and the constants beside it) lives outside the anonymous namespace of
// common/glsl_cpp_begin.h so C++ interfaces can pass it between translation units; identical
// in every one of them.
namespace skyig::shader::atmosphere_types {
using glsl_types::Float;
using glsl_types::vec4;
#include "atmosphere/parameters.glsl"
}  // namespace skyig::shader::atmosphere_types

#include "common/glsl_cpp_begin.h"
using namespace atmosphere_types;
using cpu_texture::sampler2D;
using cpu_texture::sampler3D;
using cpu_texture::texture;
// One line per physics file, in dependency order.
#include "atmosphere/geometry.glsl"
#include "atmosphere/medium.glsl"
#include "atmosphere/transmittance.glsl"
#include "atmosphere/scattering_texture.glsl"
#include "atmosphere/single_scattering.glsl"
#include "atmosphere/irradiance.glsl"
#include "atmosphere/multiple_scattering.glsl"
#include "atmosphere/rendering.glsl"
#include "atmosphere/rendering_rec709.glsl"
#include "atmosphere/aerial_perspective.glsl"
#include "common/glsl_cpp_end.h"
