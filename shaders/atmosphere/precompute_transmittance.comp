// GPU precomputation, step 1 (Bruneton & Neyret 2008, algorithm 4.1): T(r, mu). A pass
// (GLSL only); the physics is in transmittance.glsl. Host sequence: sky/atmosphere/
// precompute.cpp does the same steps on the CPU; common/bindings.h names the bindings.
#include "common/bindings.h"
#include "atmosphere/transmittance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform AtmosphereParameters atm;
layout(binding = SKYIG_IMAGE_TRANSMITTANCE, rgba32f) uniform writeonly image2D transmittance_out;
void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(transmittance_out)))) {
    return;
  }
  imageStore(transmittance_out, texel, computeTransmittanceTexel(atm, vec2(texel) + vec2(0.5)));
}
