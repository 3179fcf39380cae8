#pragma once
// What the pilot can see from where the state's observer is, as luminances over the whole
// view sphere: the sky above the horizon (sunlit, moonlit and the night's own light), the
// terrain below it (the ground model's luminance with its aerial perspective), and the sun's and
// moon's discs with their solid angles. The eye adapts to it and the display mapping is computed
// from it (physics/eye/tone_curve.h) once per state, for every channel alike.
#include "physics/eye/tone_curve.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace skyig::sky {

struct SkyState;

// The sphere cut into cells of equal solid angle: `bands` equal steps in cos(zenith) from the
// nadir up (Archimedes' hat-box theorem: equal steps in height cut equal areas) times `sectors`
// in azimuth from north through east. Calls f(view, solidAngle) at each cell's centre (an ENU
// unit vector, x east, y north, z up), band by band. The view sphere and the host's light
// (sky/client_light.h) integrate over it.
template <class F>
void forEachEqualAreaCell(int bands, int sectors, F&& f) {
  const double solidAngle = 4.0 * std::numbers::pi / (bands * sectors);
  for (int i = 0; i < bands; ++i) {
    const double mu = -1.0 + 2.0 * (i + 0.5) / bands;
    const double sinTheta = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / sectors;
      f(glm::dvec3(sinTheta * std::sin(phi), sinTheta * std::cos(phi), mu), solidAngle);
    }
  }
}

// One cell's light by source (luminance, cd/m^2): the sun's (sky or terrain, with the analytic
// model all of it), the moon's (the moonlit sky or terrain) and the night's own (airglow,
// zodiacal light, starlight; on the terrain the light they give it). Their sum is what the
// histogram holds for the cell.
struct ViewCellLight {
  float sunlit = 0.0f;
  float moonlit = 0.0f;
  float night = 0.0f;
};

struct ViewSphere {
  eye::LuminanceHistogram histogram;  // every cell and the discs
  double meanLuminance = 0.0;         // cd/m^2: the solid-angle mean without the discs
  std::shared_ptr<const std::vector<ViewCellLight>> cells;  // by source, every cell
};

// Equal-area cells (16 in cos(zenith) over the sphere x 32 in azimuth): ~2 ms per state on the
// worker for the physical model.
ViewSphere viewSphere(const SkyState& state);

}  // namespace skyig::sky
