#pragma once
// The physically based atmosphere (Bruneton & Neyret 2008), written once in GLSL under
// physics/atmosphere/ and compiled here as C++ in double precision, the same way as
// physics/physics.h. GLSL's samplers become the CPU tables of physics/common/cpu_texture.h, so
// the precomputation and the rendering functions run on the CPU for the reference path and
// the tests, and on the GPU with real samplers.
#include "physics/common/cpu_texture.h"
#include "physics/common/glsl_cpp.h"

// The parameter struct (and the constants beside it) lives outside the anonymous namespace of
// physics/common/glsl_cpp_begin.h so C++ interfaces can pass it between translation units; identical
// in every one of them.
namespace skyig::shader::atmosphere_types {
using glsl_types::Float;
using glsl_types::vec4;
#include "physics/atmosphere/parameters.glsl"
}  // namespace skyig::shader::atmosphere_types

#include "physics/common/glsl_cpp_begin.h"
using namespace atmosphere_types;
using cpu_texture::sampler2D;
using cpu_texture::sampler3D;
using cpu_texture::texture;
// One line per physics file, in dependency order.
#include "physics/atmosphere/geometry.glsl"
#include "physics/atmosphere/medium.glsl"
#include "physics/atmosphere/transmittance.glsl"
#include "physics/atmosphere/scattering_texture.glsl"
#include "physics/atmosphere/single_scattering.glsl"
#include "physics/atmosphere/irradiance.glsl"
#include "physics/atmosphere/multiple_scattering.glsl"
#include "physics/atmosphere/rendering.glsl"
#include "physics/atmosphere/rendering_rec709.glsl"
#include "physics/atmosphere/aerial_perspective.glsl"
#include "physics/common/glsl_cpp_end.h"
