#pragma once
// The scattering tables of all wavelength groups folded into one pair in linear Rec.709
// (shaders/atmosphere/rendering_rec709.glsl): what the GPU sky pass needs, 2 x 8 MB at half
// float for the default size however many wavelengths were computed.
#include "render/atmosphere/model.h"

namespace skyig::atmosphere {

struct Rec709Tables {
  shader::cpu_texture::sampler3D scattering;  // rgb in x, y, z; w = 0
  shader::cpu_texture::sampler3D single_mie;
};

Rec709Tables combineToRec709(const AtmosphereModel& model);

// Sky radiance as linear Rec.709 (Y in cd/m^2) from the combined tables.
glm::dvec3 skyRec709(const AtmosphereModel& model, const Rec709Tables& tables,
                     const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun);

}  // namespace skyig::atmosphere
