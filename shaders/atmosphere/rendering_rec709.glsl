// Sky radiance from tables already converted to linear Rec.709 (cd/m^2 per unit phase
// function): the sum over all wavelength groups of each group's C* and C_M times the 3 x 4
// block of the spectral-to-Rec.709 matrix (render/atmosphere/rec709_tables.h). Exact for the
// sky, because both phase functions are the same at every wavelength (paper eq. 2 and 4 with
// a grey g), so phase and colour conversion commute; one table pair for any number of
// wavelengths, which is what keeps the GPU tables within budget.
#ifndef SKYIG_ATMOSPHERE_RENDERING_REC709_GLSL
#define SKYIG_ATMOSPHERE_RENDERING_REC709_GLSL
#include "atmosphere/rendering.glsl"

// Linear Rec.709 (Y in cd/m^2) of the light scattered into the view ray; atm supplies the
// geometry and table sizes (the same for every group).
vec3 skyRec709(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_rec709,
               IN(sampler3D) single_mie_rec709, IN(vec3) camera_position, IN(vec3) view_ray,
               IN(vec3) sun_direction) {
  vec3 camera = camera_position;
  Float r;
  Float rmu;
  if (!enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    return vec3(0.0);
  }
  Float mu = atmClampCosine(rmu / r);
  Float mu_s = atmClampCosine(dot(camera, sun_direction) / r);
  Float nu = atmClampCosine(dot(view_ray, sun_direction));
  vec4 rgb = scatteredRadiance(atm, scattering_rec709, single_mie_rec709, r, mu, mu_s, nu,
                               rayIntersectsGround(atm, r, mu));
  return vec3(rgb.x, rgb.y, rgb.z);
}

#endif
