#ifndef SKYIG_COMMON_UNIFORMS_H
#define SKYIG_COMMON_UNIFORMS_H
// Uniform-block layouts shared by C++ and GLSL: the one place both sides read them from
// (docs/design.md); their binding points are in common/bindings.h. std140, vec4/mat4 members
// only, so C++ needs no padding rules beyond sizeof(float[4]).
#include "common/bindings.h"

#include "common/ubo.h"

// Per channel and frame: how pixels map to view rays (Wang, Ji & Zhang 2011, eq. 22).
SKYIG_UBO_BEGIN(FrameBlock, SKYIG_BINDING_FRAME)
  SKYIG_MAT4 ndcToWorld;  // (x_ndc, y_ndc, 1) -> ENU view direction (unnormalised); mat3 in 4x4
  SKYIG_VEC4 viewport;    // width, height, 1/width, 1/height
SKYIG_UBO_END(FrameBlock)

// The analytic sky of the state (shaders/sky/analytic_sky.glsl, field by field).
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

// Tone reproduction of a channel (shaders/tone/tone_reproduction.glsl).
SKYIG_UBO_BEGIN(ToneBlock, SKYIG_BINDING_TONE)
  SKYIG_VEC4 display;      // L_dmax, L_amb, gamma, L_a(d)
  SKYIG_VEC4 adaptation;   // x: world adaptation luminance (cd/m^2); y: dither amplitude in LSB;
                           // z: 0 the histogram curve below, 1 Tumblin-Rushmeier
  SKYIG_VEC4 curveRange;   // x, y: log10 world luminance of the curve's first and last point
  SKYIG_VEC4 curve[16];    // 64 display log10 luminances (sky/eye/tone_curve.h), 4 a vec4
  SKYIG_VEC4 glareDirection[2];  // the sources giving light, first (sky/eye/glare.h): xyz ENU unit vector; w: radius, deg
  SKYIG_VEC4 glareLux[2];        // rgb: linear Rec.709 illuminance at the eye, lux
  SKYIG_VEC4 glareCoefficients;  // the observer's veil equation (tone/glare.glsl veilCoefficients)
SKYIG_UBO_END(ToneBlock)

// The warp-and-blend pass of a projector (passes/warp_blend.frag, tone/projector_blend.glsl).
SKYIG_UBO_BEGIN(ProjectorBlock, SKYIG_BINDING_PROJECTOR)
  SKYIG_VEC4 projector;  // width, height (pixels), 1/width, 1/height
  SKYIG_VEC4 blend;      // x: the display's gamma; y: dither amplitude in LSB
SKYIG_UBO_END(ProjectorBlock)

#endif
