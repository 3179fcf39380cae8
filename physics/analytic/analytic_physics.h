#pragma once
// The analytic skies (CIE general sky, Preetham's Perez sky, their sun disc) compiled as C++ in
// double precision (physics/README.md), for physics/analytic/analytic_sky.h and the tests.
#include "physics/common/glsl_cpp_begin.h"
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"
#include "physics/analytic/cie_general_sky.glsl"
#include "physics/analytic/preetham.glsl"
#include "physics/analytic/analytic_sky.glsl"
#include "physics/common/glsl_cpp_end.h"
