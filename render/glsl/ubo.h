#ifndef SKYIG_COMMON_UBO_H
#define SKYIG_COMMON_UBO_H
// The macros that let one uniform-block declaration be a C++ struct and a GLSL std140 block
// (render/glsl/uniforms.h, render/glsl/band_uniforms.h): vec4 and mat4 members only, so C++ needs no
// padding rules beyond sizeof(float[4]).
#ifdef __cplusplus
#include <glm/glm.hpp>
#define SKYIG_UBO_BEGIN(name, slot) struct name {
#define SKYIG_UBO_END(name) };
#define SKYIG_VEC4 glm::vec4
#define SKYIG_MAT4 glm::mat4
#else
#define SKYIG_UBO_BEGIN(name, slot) layout(std140, binding = slot) uniform name {
#define SKYIG_UBO_END(name) };
#define SKYIG_VEC4 vec4
#define SKYIG_MAT4 mat4
#endif
#endif
