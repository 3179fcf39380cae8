#ifndef SKYIG_COMMON_FRAME_UNIFORMS_H
#define SKYIG_COMMON_FRAME_UNIFORMS_H
// The frame block, shared by C++ and GLSL like render/glsl/uniforms.h (which includes it), in a file
// of its own so that the physical sky's shaders, which cannot include render/glsl/uniforms.h (its
// analytic-sky block's member names clash with the atmosphere's functions), can read it.
#include "render/glsl/bindings.h"
#include "render/glsl/ubo.h"

// Per channel and frame: how pixels map to view rays (Wang, Ji & Zhang 2011, eq. 22).
SKYIG_UBO_BEGIN(FrameBlock, SKYIG_BINDING_FRAME)
  SKYIG_MAT4 ndcToWorld;  // (x_ndc, y_ndc, 1) -> ENU view direction (unnormalised); mat3 in 4x4
  SKYIG_VEC4 viewport;    // width, height, 1/width, 1/height
SKYIG_UBO_END(FrameBlock)

#endif
