#pragma once
// Every model of physics/common, analytic, eye and display, written once in GLSL and compiled here
// as C++ in double precision (docs/design.md, "One source for the physics"): one include for the
// sky state, the renderer's CPU side and the tests. A model's own code includes its folder's
// header (physics/eye/eye_physics.h, ...); the night's models have theirs
// (physics/moon/moon_physics.h, physics/stars/star_physics.h, physics/night/diffuse_physics.h),
// as have the atmosphere (physics/atmosphere/atmosphere_physics.h) and the goggle.
#include "physics/common/common_physics.h"
#include "physics/analytic/analytic_physics.h"
#include "physics/eye/eye_physics.h"
#include "physics/display/display_physics.h"
