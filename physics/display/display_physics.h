#pragma once
// The display: a projector's blend in light (physics/display/projector_blend.glsl), compiled as
// C++ in double precision (physics/README.md).
#include "physics/common/glsl_cpp_begin.h"
#include "physics/display/projector_blend.glsl"
#include "physics/common/glsl_cpp_end.h"
