// Compiles every atmosphere physics function as real GLSL 4.50 (glslangValidator), with
// samplers where the C++ side has CPU tables: the GPU half of "written once".
#include "physics/atmosphere/rendering.glsl"
#include "physics/atmosphere/rendering_rec709.glsl"
#include "physics/atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D transmittance_texture;
layout(binding = 1) uniform sampler3D scattering_texture;
layout(binding = 2) uniform sampler3D single_mie_texture;
layout(binding = 3) uniform sampler2D irradiance_texture;
layout(binding = 4, rgba32f) uniform writeonly image2D result;
uniform AtmosphereParameters atm;
void main() {
  vec4 t;
  vec3 cam = vec3(0.0, 0.0, atm.bottom_radius + 1000.0);
  vec4 l = skyRadiance(atm, transmittance_texture, scattering_texture, single_mie_texture, cam, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), t);
  vec4 sky;
  l += sunAndSkyIrradiance(atm, transmittance_texture, irradiance_texture, cam, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), sky);
  l += groundRadiance(atm, transmittance_texture, scattering_texture, single_mie_texture, irradiance_texture, cam, vec3(0.0, 0.0, atm.bottom_radius), atm.ground_albedo, vec3(0.0, 0.0, 1.0), t);
  l += sunDiscRadiance(atm, transmittance_texture, cam, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0));
  l += computeOpticalDepthTexel(atm, vec2(gl_GlobalInvocationID.xy));
  l += computeDirectIrradianceTexel(atm, transmittance_texture, vec2(gl_GlobalInvocationID.xy));
  vec4 r; vec4 m;
  computeSingleScatteringTexel(atm, transmittance_texture, vec3(gl_GlobalInvocationID), r, m);
  l += computeScatteringDensityTexel(atm, transmittance_texture, scattering_texture, single_mie_texture, scattering_texture, irradiance_texture, vec3(gl_GlobalInvocationID), 2);
  l += computeIndirectIrradianceTexel(atm, scattering_texture, single_mie_texture, scattering_texture, vec2(gl_GlobalInvocationID.xy), 2);
  float nu;
  l += computeMultipleScatteringTexel(atm, transmittance_texture, scattering_texture, vec3(gl_GlobalInvocationID), nu);
  l += vec4(skyRec709(atm, scattering_texture, single_mie_texture, cam, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0)), 0.0);
  imageStore(result, ivec2(gl_GlobalInvocationID.xy), l + r + m);
}
