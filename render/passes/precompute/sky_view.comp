// The sky, sun disc and ground of one group of four wavelengths for every pixel of an
// equirectangular view (azimuth across, zenith 0..180 deg down): spectral radiance, the
// sum of skyRadiance, sunDiscRadiance and the attenuated ground reflection. Used to time the
// per-pixel cost and to check a full panorama, horizon included, for NaN and Inf on the GPU.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/rendering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform AtmosphereParameters atm;
uniform vec3 camera;         // metres from the planet's centre
uniform vec3 sun_direction;  // unit
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
layout(binding = SKYIG_UNIT_SCATTERING) uniform sampler3D scattering_texture;
layout(binding = SKYIG_UNIT_SINGLE_MIE) uniform sampler3D single_mie_texture;
layout(binding = SKYIG_UNIT_IRRADIANCE) uniform sampler2D irradiance_texture;
layout(binding = SKYIG_IMAGE_SKY_VIEW, rgba32f) uniform writeonly image2D radiance_out;
void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(radiance_out);
  if (any(greaterThanEqual(pixel, size))) {
    return;
  }
  Float azimuth = (Float(pixel.x) + 0.5) / Float(size.x) * 2.0 * ATMOSPHERE_PI;
  Float zenith = (Float(pixel.y) + 0.5) / Float(size.y) * ATMOSPHERE_PI;
  vec3 view = vec3(sin(zenith) * cos(azimuth), sin(zenith) * sin(azimuth), cos(zenith));
  vec4 transmittance;
  vec4 radiance = skyRadiance(atm, transmittance_texture, scattering_texture, single_mie_texture,
                              camera, view, sun_direction, transmittance);
  radiance += sunDiscRadiance(atm, transmittance_texture, camera, view, sun_direction);
  Float r = length(camera);
  Float rmu = dot(camera, view);
  Float discriminant = rmu * rmu - r * r + atm.bottom_radius * atm.bottom_radius;
  if (rmu < 0.0 && discriminant >= 0.0) {
    vec3 ground_point = camera + view * (-rmu - sqrt(discriminant));
    vec4 sky_irradiance;
    vec4 sun_irradiance = sunAndSkyIrradiance(atm, transmittance_texture, irradiance_texture,
                                              ground_point, normalize(ground_point),
                                              sun_direction, sky_irradiance);
    vec4 ground_transmittance;
    skyRadianceToPoint(atm, transmittance_texture, scattering_texture, single_mie_texture, camera,
                       ground_point, sun_direction, ground_transmittance);
    radiance += atm.ground_albedo * (1.0 / ATMOSPHERE_PI) * (sun_irradiance + sky_irradiance) *
                ground_transmittance;
  }
  imageStore(radiance_out, pixel, radiance);
}
