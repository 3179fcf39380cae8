#include "physics/atmosphere/precompute/orders_tail.h"

#include <algorithm>
#include <stdexcept>

namespace skyig::atmosphere {

using shader::cpu_texture::sampler2D;
using shader::cpu_texture::sampler3D;

glm::dvec4 ordersRatio(const sampler3D& before, const sampler3D& last) {
  if (before.texels.size() != last.texels.size()) throw std::invalid_argument("orders tail: tables of different sizes");
  glm::dvec4 a(0.0), b(0.0);
  for (std::size_t i = 0; i < last.texels.size(); ++i) {
    a += last.texels[i];
    b += before.texels[i];
  }
  glm::dvec4 q(0.0);
  for (glm::length_t c = 0; c < 4; ++c) q[c] = b[c] > 0.0 ? a[c] / b[c] : 0.0;
  // Not yet shrinking geometrically at any wavelength: no tail at all (one decision for the
  // four, so the colour does not jump).
  for (glm::length_t c = 0; c < 4; ++c)
    if (q[c] > kOrdersTailMaxRatio) return glm::dvec4(0.0);
  return q;
}

void addOrdersTail(const AtmosphereParameters& atm, const sampler3D& before, const sampler3D& last,
                   const sampler2D& lastIrradiance, GroupTables& tables) {
  const glm::dvec4 q = ordersRatio(before, last);
  const glm::dvec4 k = q / (glm::dvec4(1.0) - q);
  sampler3D& s = tables.scattering;
  for (int z = 0; z < s.depth; ++z)
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x) {
        double r = 0.0, mu = 0.0, mu_s = 0.0, nu = 0.0;
        bool ground = false;
        shader::rMuMuSNuFromScatteringFragCoord(atm, glm::dvec3(x + 0.5, y + 0.5, z + 0.5), r, mu, mu_s, nu, ground);
        s.at(x, y, z) += last.at(x, y, z) * k / shader::rayleighPhaseFunction(nu);
      }
  for (std::size_t i = 0; i < tables.irradiance.texels.size(); ++i) tables.irradiance.texels[i] += lastIrradiance.texels[i] * k;
}

}  // namespace skyig::atmosphere
