#pragma once
// Sizes and contents of the precomputed tables of one group of four wavelengths (Bruneton &
// Neyret 2008, section 4 and 6): transmittance T(r, mu) 2D, sky irradiance E(r, mu_s) 2D,
// inscattered radiance S(r, mu, mu_s, nu) 4D stored in 3D, with the single Mie term apart.
#include <cstddef>
#include <cstdint>
#include <string>

#include "physics/common/cpu_texture.h"

namespace skyig::atmosphere {

struct TableSizes {
  int transmittanceMu = 256;  // Bruneton 2017 (the paper: 64x256 T, 16x64 E, 32x128x32x8 S)
  int transmittanceR = 64;
  int irradianceMuS = 64;
  int irradianceR = 16;
  int scatteringR = 32;
  int scatteringMu = 128;  // even
  int scatteringMuS = 32;
  int scatteringNu = 8;

  // Small tables for tests (the physics tests need luminance at 16 wavelengths quickly): seconds
  // to precompute on llvmpipe, but 15-22% off the default tables at sunset.
  static TableSizes small();
  // Half the default's radii and view angles: within 3% of the default tables up to 5 km
  // (docs/atmosphere.md), a quarter of their texels, ~28 s to precompute on llvmpipe.
  static TableSizes medium();
  // "small", "medium" or "default"; throws std::invalid_argument naming anything else.
  static TableSizes named(const std::string& name);
  // Texels of each 3D scattering table, and GPU bytes of one group at RGBA16F.
  std::size_t scatteringTexels() const;
  std::size_t bytesAtHalfFloat() const;
};

// Throws std::invalid_argument naming the bad size.
void validate(const TableSizes& sizes);

struct GroupTables {
  shader::cpu_texture::sampler2D transmittance;  // mu x r
  shader::cpu_texture::sampler2D irradiance;     // mu_s x r, indirect (sky) light only
  shader::cpu_texture::sampler3D scattering;     // (nu * mu_s) x mu x r: C*
  shader::cpu_texture::sampler3D singleMie;     // same layout: C_M
};

}  // namespace skyig::atmosphere
