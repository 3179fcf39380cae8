#ifndef SKYIG_COMMON_UNIFORMS_H
#define SKYIG_COMMON_UNIFORMS_H
// Uniform-block layouts shared by C++ and GLSL: the one place both sides read them from
// (docs/design.md); their binding points are in render/glsl/bindings.h. std140, vec4/mat4 members
// only, so C++ needs no padding rules beyond sizeof(float[4]).
#include "render/glsl/bindings.h"

#include "render/glsl/ubo.h"

#include "render/glsl/frame_uniforms.h"
#include "render/glsl/tone_uniforms.h"

// The analytic sky of the state (physics/analytic/analytic_sky.glsl, field by field).
SKYIG_UBO_BEGIN(AnalyticSkyBlock, SKYIG_BINDING_SKY)
  SKYIG_VEC4 perezA;
  SKYIG_VEC4 perezB;
  SKYIG_VEC4 perezC;
  SKYIG_VEC4 perezD;
  SKYIG_VEC4 perezE;
  SKYIG_VEC4 perezK;
  SKYIG_VEC4 zenith;            // xyz: (Y, x, y)
  SKYIG_VEC4 skySunDirection;   // xyz; w: luminance scale
  SKYIG_VEC4 sunDirection;      // xyz; w: cos of the disc radius
  SKYIG_VEC4 sunRadiance;       // rgb
  SKYIG_VEC4 groundRadiance;    // rgb
SKYIG_UBO_END(AnalyticSkyBlock)

// The warp-and-blend pass of a projector (render/passes/projector/warp_blend.frag, physics/display/projector_blend.glsl).
SKYIG_UBO_BEGIN(ProjectorBlock, SKYIG_BINDING_PROJECTOR)
  SKYIG_VEC4 projector;  // width, height (pixels), 1/width, 1/height
  SKYIG_VEC4 blend;      // x: the display's gamma; y: dither amplitude in LSB
SKYIG_UBO_END(ProjectorBlock)

#endif
