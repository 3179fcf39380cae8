#pragma once
// The physics of the sky, written once in GLSL under shaders/ and compiled here as C++ in
// double precision (docs/design.md, "One source for the physics"). The renderer embeds
// the same files; tests and the CPU side of skyig (adaptation, probe) call them from here.
#include "common/glsl_cpp_begin.h"
// Add one line per physics file, in dependency order.
#include "common/constants.glsl"
#include "common/color.glsl"
#include "sky/cie_general_sky.glsl"
#include "sky/preetham.glsl"
#include "sky/analytic_sky.glsl"
#include "tone/tumblin_rushmeier.glsl"
#include "tone/scotopic.glsl"
#include "tone/threshold.glsl"
#include "tone/tone_reproduction.glsl"
#include "tone/glare.glsl"
#include "tone/projector_blend.glsl"
#include "common/glsl_cpp_end.h"
