#include "render/passes/night/star_culling.h"

#include "physics/stars/star_physics.h"

#include <algorithm>
#include <cmath>

namespace skyig::render {

double starQuadReachPx(const glm::dmat3& ndcToWorld, int width, int height) {
  // A pinhole's pixels subtend least at the corners (|M (x, y, 1)| is convex: largest there).
  double smallestSr = 1e300;
  for (const double x : {-1.0, 1.0})
    for (const double y : {-1.0, 1.0})
      smallestSr = std::min(smallestSr, shader::pixelSolidAngle(ndcToWorld, glm::dvec2(x, y),
                                                                4.0 / (double(width) * double(height))));
  const double displayedSigmaPx =
      std::max(shader::kDisplayedPsfSigmaRad / std::sqrt(smallestSr), shader::kDisplayedPsfMinSigmaPx);
  return shader::starPsfQuadHalfSizePx(std::max(shader::kStarPsfSigmaPx, displayedSigmaPx)) + 1.0;
}

}  // namespace skyig::render
