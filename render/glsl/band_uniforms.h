#ifndef SKYIG_COMMON_BAND_UNIFORMS_H
#define SKYIG_COMMON_BAND_UNIFORMS_H
// The band block, shared by C++ and GLSL like render/glsl/uniforms.h, in a file of its own: the
// physical sky's shaders read it but cannot include render/glsl/uniforms.h (its analytic-sky block's
// member names clash with the atmosphere's functions).
#include "render/glsl/bindings.h"
#include "render/glsl/ubo.h"
// The spectral band a channel's passes draw in (sky/nvis_weights.h, render/glsl/band.glsl): the eye's,
// or a goggle's NVIS radiance, each light's luminance times its weight.
SKYIG_UBO_BEGIN(BandBlock, SKYIG_BINDING_BAND)
  SKYIG_VEC4 band;          // x: 1 a goggle's band, 0 the eye's; y: the sun disc's weight over the sunlit sky's;
                            // z: the moonlit sky's over the sunlit sky's
  SKYIG_VEC4 lightWeights;  // W m^-2 sr^-1 per cd/m^2: x sunlit sky, y the moon's disc, z airglow, w zodiacal light
  SKYIG_VEC4 nightWeights;  // x the Milky Way and unresolved stars, y the terrain under the night's light
SKYIG_UBO_END(BandBlock)
#endif
