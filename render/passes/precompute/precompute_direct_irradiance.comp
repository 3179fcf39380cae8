// GPU precomputation, step 2: the direct irradiance (order 0 on the ground) into
// delta_irradiance, and the accumulated sky irradiance cleared.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/irradiance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform AtmosphereParameters atm;
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
layout(binding = SKYIG_IMAGE_DELTA_IRRADIANCE, rgba32f) uniform writeonly image2D delta_irradiance_out;
layout(binding = SKYIG_IMAGE_IRRADIANCE, rgba32f) uniform writeonly image2D irradiance_out;
void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(delta_irradiance_out)))) {
    return;
  }
  imageStore(delta_irradiance_out, texel,
             computeDirectIrradianceTexel(atm, transmittance_texture, vec2(texel) + vec2(0.5)));
  imageStore(irradiance_out, texel, vec4(0.0));
}
