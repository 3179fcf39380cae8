// GPU precomputation, step 4b (per order n >= 2): the ground irradiance of order n-1 into
// delta_irradiance, added to the sky irradiance table. Each invocation owns its texel, so the
// accumulation is explicit and repeatable (no blending).
#include "render/glsl/bindings.h"
#include "physics/atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform AtmosphereParameters atm;
uniform int scattering_order;  // n: this pass integrates the radiance of order n - 1
layout(binding = SKYIG_UNIT_DELTA_RAYLEIGH) uniform sampler3D single_rayleigh_texture;
layout(binding = SKYIG_UNIT_DELTA_MIE) uniform sampler3D single_mie_texture;
layout(binding = SKYIG_UNIT_DELTA_MULTIPLE) uniform sampler3D multiple_texture;
layout(binding = SKYIG_IMAGE_DELTA_IRRADIANCE, rgba32f) uniform writeonly image2D delta_irradiance_out;
layout(binding = SKYIG_IMAGE_IRRADIANCE, rgba32f) uniform image2D irradiance_accumulated;
void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(delta_irradiance_out)))) {
    return;
  }
  vec4 delta = computeIndirectIrradianceTexel(atm, single_rayleigh_texture, single_mie_texture,
                                              multiple_texture, vec2(texel) + vec2(0.5),
                                              scattering_order - 1);
  imageStore(delta_irradiance_out, texel, delta);
  imageStore(irradiance_accumulated, texel, imageLoad(irradiance_accumulated, texel) + delta);
}
