#ifndef SKYIG_COMMON_GOGGLE_UNIFORMS_H
#define SKYIG_COMMON_GOGGLE_UNIFORMS_H
// The goggle's block, shared by C++ and GLSL like render/glsl/uniforms.h, in a file of its own that
// only the goggle's passes include: Mesa reports a std140 block of render/glsl/uniforms.h active in
// programs that never read it (this one was, in every pass), and each pass's bindings are
// checked against what it reads (tests/render/bindings_test.cpp).
#include "render/glsl/bindings.h"
#include "render/glsl/ubo.h"
// A goggle channel's image intensifier (passes/goggle*.frag, render/passes/goggle/goggle_pass.h,
// physics/goggle/intensifier.glsl).
SKYIG_UBO_BEGIN(GoggleBlock, SKYIG_BINDING_GOGGLE)
  SKYIG_VEC4 goggleTube;        // xy: the field's centre (pixels); z: its radius (pixels); w: the fraction of the channel inside it
  SKYIG_VEC4 goggleCathode;     // x: cathode lux per W m^-2 sr^-1 of NVIS radiance; y: photoelectrons per cathode lux in a pixel
                          // and a frame; z: the halo's Gaussian sigma (pixels); w: the coarse blocks' side (pixels: 1, 2, 4 or 8)
  SKYIG_VEC4 goggleGain;        // x: 1 automatic brightness control, 0 manual; y: the manual gain, of the maximum;
                          // z: 1 show the screen's cd/m^2 (tests, EXR), 0 display values
  SKYIG_VEC4 gogglePhosphor;    // rgb: the phosphor's linear Rec.709 colour of luminance 1
  SKYIG_VEC4 goggleMtf;         // x, y, z: 3x3 weights of the centre, the edges and the corners
SKYIG_UBO_END(GoggleBlock)
#endif
