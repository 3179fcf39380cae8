// GPU precomputation, step 1 (Bruneton & Neyret 2008, algorithm 4.1): the optical depth
// tau(r, mu) to the top, from which T(r, mu) = exp(-tau). A pass
// (GLSL only); the physics is in transmittance.glsl. Host sequence: physics/atmosphere/
// precompute.cpp does the same steps on the CPU; render/glsl/bindings.h names the bindings.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/transmittance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform AtmosphereParameters atm;
layout(binding = SKYIG_IMAGE_TRANSMITTANCE, rgba32f) uniform writeonly image2D transmittance_out;
void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(transmittance_out)))) {
    return;
  }
  imageStore(transmittance_out, texel, computeOpticalDepthTexel(atm, vec2(texel) + vec2(0.5)));
}
