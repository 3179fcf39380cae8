#pragma once
// The pilot's eye (scotopic vision, thresholds, tone reproduction, glare, the tone curve)
// compiled as C++ in double precision (physics/README.md), for physics/eye and the tests.
#include "physics/common/glsl_cpp_begin.h"
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"
#include "physics/eye/tumblin_rushmeier.glsl"
#include "physics/eye/scotopic.glsl"
#include "physics/eye/threshold.glsl"
#include "physics/eye/tone_reproduction.glsl"
#include "physics/eye/glare.glsl"
#include "physics/eye/tone_curve.glsl"
#include "physics/common/glsl_cpp_end.h"
