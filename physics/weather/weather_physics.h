#pragma once
// The weather's layers (fog, mist, precipitation, cloud decks, their table and the clouds' field) written once in GLSL and
// compiled here as C++ in double precision (physics/README.md), for physics/weather, the sky state
// and the tests.
#include "physics/common/glsl_cpp.h"

// The layer's struct outside the anonymous namespace of glsl_cpp_begin.h, so C++ interfaces can
// pass it between translation units (as physics/atmosphere/atmosphere_physics.h does).
namespace skyig::shader::weather_types {
using glsl_types::Float;
using glsl_types::vec3;
#include "physics/weather/fog_layer_parameters.glsl"
}  // namespace skyig::shader::weather_types

#include "physics/common/glsl_cpp_begin.h"
using namespace weather_types;
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"
#include "physics/weather/fog_layer.glsl"
#include "physics/weather/fog_table.glsl"
#include "physics/weather/cloud_cover.glsl"
#include "physics/weather/cloud_sunlight.glsl"
#include "physics/common/glsl_cpp_end.h"
