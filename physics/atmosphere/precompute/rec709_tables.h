#pragma once
// The scattering tables of all wavelength groups folded into one pair in linear Rec.709
// (physics/atmosphere/rendering_rec709.glsl): what the GPU sky pass needs, however many
// wavelengths were computed. Folding is exact for the sky radiance (both phase functions are
// grey); light that crosses the air (sun disc, ground, aerial perspective) is attenuated by a
// sun-weighted XYZ transmittance instead of the spectral one (docs/atmosphere.md bounds the
// error).
#include "physics/atmosphere/model.h"

#include <cstdint>
#include <vector>

namespace skyig::atmosphere {

struct Rec709Tables {
  shader::cpu_texture::sampler3D scattering;  // rgb in x, y, z; w = 0
  shader::cpu_texture::sampler3D singleMie;
};

Rec709Tables combineToRec709(const AtmosphereModel& model);

// Sky radiance as linear Rec.709 (Y in cd/m^2) from the combined tables.
glm::dvec3 skyRec709(const AtmosphereModel& model, const Rec709Tables& tables,
                     const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun);

// The moonlit sky (Jensen et al. 2001, "A Physically-Based Night Sky Model", section 5): the
// same scattering lit from the moon's direction, its spectrum taken as the sun's times a
// Rec.709 scale (the moon's irradiance relative to the sun's, per channel).
glm::dvec3 moonlitSkyRec709(const AtmosphereModel& model, const glm::dvec3& camera,
                            const glm::dvec3& view, const glm::dvec3& moonDirection,
                            const glm::dvec3& moonlightScale);

// What the renderer uploads: the tables of physics/atmosphere/rendering_rec709.glsl ("packed
// tables"), with the scattering pair rounded to half floats as on the GPU.
//   scattering:    C*.rgb, C_M.b in w   (Rec.709 x REC709_TABLE_SCALE, RGBA16F on the GPU)
//   singleMieRg:   C_M.rg in x, y       (RG16F)
//   transmittanceXyz, irradianceXyz: the optical depth of the sun-weighted XYZ transmittance
//   (w = 0), sky irradiance in XYZ (RGBA32F: a foggy horizon's depth needs float's digits)
struct PackedRec709Tables {
  shader::cpu_texture::sampler2D transmittanceXyz;
  shader::cpu_texture::sampler2D irradianceXyz;
  shader::cpu_texture::sampler3D scattering;
  shader::cpu_texture::sampler3D singleMieRg;
  glm::dvec3 solarIrradianceXyz{0.0};  // at the top of the atmosphere (Y in lux)
  glm::dvec3 limbDarkeningXyz{0.0};    // sun-weighted mean exponent per XYZ channel
  double groundAlbedo = 0.0;
};

// Makes the packed tables of a model, one scattering slice (one radius, z) at a time so a
// renderer can spread the work over frames.
class Rec709Packer {
 public:
  explicit Rec709Packer(const AtmosphereModel& model);

  int slices() const;  // depth of the scattering tables (their radii)
  // Every part of the packed tables except the scattering pair (small).
  PackedRec709Tables packSmallTables() const;
  // Half floats of slice z: scattering as RGBA (4 per texel) and single Mie as RG (2).
  void packSlice(int z, std::vector<std::uint16_t>& scattering, std::vector<std::uint16_t>& singleMieRg) const;

 private:
  const AtmosphereModel& model_;
  std::vector<glm::dvec3> rgb_;   // Rec.709 per unit spectral radiance, per wavelength
  std::vector<glm::dvec3> xyzSun_;  // XYZ of the solar irradiance at each wavelength
};

// All of it at once, the half floats read back as doubles: the CPU image of the GPU tables.
PackedRec709Tables packRec709(const AtmosphereModel& model);

// The alpha and rg of the packed pair rejoined: C* and C_M, Rec.709 (unscaled).
glm::dvec3 packedSkyRec709(const AtmosphereModel& model, const PackedRec709Tables& tables,
                           const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& light);
// Sky + sun disc + ground (with its attenuation), what the sky pass draws for the sun alone.
glm::dvec3 packedRadianceRec709(const AtmosphereModel& model, const PackedRec709Tables& tables,
                                const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun);

}  // namespace skyig::atmosphere
