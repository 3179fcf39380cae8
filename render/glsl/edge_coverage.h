#pragma once
// render/glsl/edge_coverage.glsl compiled as C++ in double precision (as physics/physics.h does for
// the sky), so tests check the coverage the passes compute.
#include "physics/common/glsl_cpp_begin.h"
#include "render/glsl/edge_coverage.glsl"
#include "physics/common/glsl_cpp_end.h"
