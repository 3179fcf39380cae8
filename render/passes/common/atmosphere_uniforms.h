#pragma once
// The atmosphere's parameters as GLSL uniforms, for the sky pass and the GPU precompute alike.
#include "physics/atmosphere/precompute/precompute.h"

#include <glad/gl.h>

#include <string>

namespace skyig::render {

// Sets every member of a GLSL `uniform AtmosphereParameters` named `uniform` (e.g. "atm" or
// "atm[2]") in `program` (physics/atmosphere/parameters.glsl), as floats.
void setAtmosphereUniforms(GLuint program, const std::string& uniform, const atmosphere::AtmosphereParameters& a);

}  // namespace skyig::render
