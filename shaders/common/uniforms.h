#ifndef SKYIG_COMMON_UNIFORMS_H
#define SKYIG_COMMON_UNIFORMS_H
// Uniform-block layouts and binding points shared by C++ and GLSL: the one place both sides
// read them from (docs/design.md). std140, vec4/mat4 members only, so C++ needs no
// padding rules beyond sizeof(float[4]).
#ifdef __cplusplus
#include <glm/glm.hpp>
#define SKYIG_UBO_BEGIN(name, slot) struct name {
#define SKYIG_UBO_END(name) };
#define SKYIG_VEC4 glm::vec4
#define SKYIG_MAT4 glm::mat4
#define SKYIG_CONST constexpr int
#else
#define SKYIG_UBO_BEGIN(name, slot) layout(std140, binding = slot) uniform name {
#define SKYIG_UBO_END(name) };
#define SKYIG_VEC4 vec4
#define SKYIG_MAT4 mat4
#define SKYIG_CONST const int
#endif

SKYIG_CONST SKYIG_BINDING_FRAME = 0;
SKYIG_CONST SKYIG_BINDING_SKY = 1;
SKYIG_CONST SKYIG_BINDING_TONE = 2;
SKYIG_CONST SKYIG_UNIT_HDR_IMAGE = 0;

// Per channel and frame: how pixels map to view rays (Wang, Ji & Zhang 2011, eq. 22).
SKYIG_UBO_BEGIN(FrameBlock, 0)
  SKYIG_MAT4 ndcToWorld;  // (x_ndc, y_ndc, 1) -> ENU view direction (unnormalised); mat3 in 4x4
  SKYIG_VEC4 viewport;    // width, height, 1/width, 1/height
SKYIG_UBO_END(FrameBlock)

// The analytic sky of the state (shaders/sky/analytic_sky.glsl, field by field).
SKYIG_UBO_BEGIN(AnalyticSkyBlock, 1)
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
SKYIG_UBO_BEGIN(ToneBlock, 2)
  SKYIG_VEC4 display;      // L_dmax, L_amb, gamma, L_a(d)
  SKYIG_VEC4 adaptation;   // x: world adaptation luminance (cd/m^2); y: dither amplitude in LSB
SKYIG_UBO_END(ToneBlock)

#endif
