#pragma once
// The physically based atmosphere (Bruneton & Neyret 2008), written once in GLSL under
// shaders/atmosphere/ and compiled here as C++ in double precision, the same way as
// shaders/physics.h. GLSL's samplers become the CPU tables of atmosphere/cpu_texture.h, so
// the precomputation and the rendering functions run on the CPU for the reference path and
// the tests, and on the GPU with real samplers.
//
// The functions land in an anonymous namespace so every translation unit gets its own
// copy: GLSL has no `inline`, and this keeps the shader files free of C++-only words.
#include "atmosphere/cpu_texture.h"
#include "common/glsl_cpp.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
namespace skyig::shader {
// The parameter struct (and the constants beside it) lives outside the anonymous namespace so
// C++ interfaces can pass it between translation units; identical in every one of them.
namespace atmosphere_types {
using glsl_types::Float;
using glsl_types::vec4;
#include "atmosphere/parameters.glsl"
}  // namespace atmosphere_types
namespace {
using namespace atmosphere_types;
using namespace glm;
using namespace glsl_types;
using cpu_texture::sampler2D;
using cpu_texture::sampler3D;
using cpu_texture::texture;
using std::exp;
using std::floor;
using std::log;
using std::pow;
using std::sqrt;
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
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
