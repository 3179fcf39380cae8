#pragma once
// The midpoint rule over the upper hemisphere in (cos theta, phi), where the solid angle element
// is d(cos theta) d(phi): every cell of an nMu x nPhi grid holds the same solid angle,
// 2 pi / (nMu nPhi), so a plain mean of f over the cells is its solid-angle mean.
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace skyig::sky {

// Calls f(direction) for the centre of each cell: ENU unit vectors (x east, y north, z up),
// azimuth from north through east.
template <typename F>
void forEachHemisphereDirection(int nMu, int nPhi, F&& f) {
  for (int i = 0; i < nMu; ++i) {
    const double mu = (i + 0.5) / nMu;
    const double sinTheta = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < nPhi; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / nPhi;
      f(glm::dvec3(sinTheta * std::sin(phi), sinTheta * std::cos(phi), mu));
    }
  }
}

}  // namespace skyig::sky
