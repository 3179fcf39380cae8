#ifndef SKYIG_COMMON_TONE_UNIFORMS_H
#define SKYIG_COMMON_TONE_UNIFORMS_H
// The tone block, shared by C++ and GLSL like render/glsl/uniforms.h (which includes it), in a file
// of its own so that the physical sky pass can map its pixels to the display itself when it is
// the frame's last full-screen pass (render/passes/sky/physical_sky.frag, SKYIG_FOLD_TONE).
#include "render/glsl/bindings.h"
#include "render/glsl/ubo.h"

// Tone reproduction of a channel (physics/eye/tone_reproduction.glsl).
SKYIG_UBO_BEGIN(ToneBlock, SKYIG_BINDING_TONE)
  SKYIG_VEC4 display;      // L_dmax, L_amb, gamma, L_a(d)
  SKYIG_VEC4 adaptation;   // x: world adaptation luminance (cd/m^2); y: dither amplitude in LSB;
                           // z: 0 the histogram curve below, 1 Tumblin-Rushmeier
  SKYIG_VEC4 curveRange;   // x, y: log10 world luminance of the curve's first and last point
  SKYIG_VEC4 curve[16];    // 64 display log10 luminances (physics/eye/tone_curve.h), 4 a vec4
  SKYIG_VEC4 glareDirection[2];  // the sources giving light, first (physics/eye/glare.h): xyz ENU unit vector; w: radius, deg
  SKYIG_VEC4 glareLux[2];        // rgb: linear Rec.709 illuminance at the eye, lux
  SKYIG_VEC4 glareCoefficients;  // the observer's veil equation (physics/eye/glare.glsl veilCoefficients)
SKYIG_UBO_END(ToneBlock)

#endif
