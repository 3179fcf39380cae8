#pragma once
// What the pilot can see from where the state's observer is, as luminances over the whole
// view sphere: the sky above the horizon (sunlit, moonlit and the night's own light), the
// terrain below it (the ground model's luminance with its aerial perspective), and the sun's and
// moon's discs with their solid angles. The eye adapts to it and the display mapping is computed
// from it (sky/eye/tone_curve.h) once per state, for every channel alike.
#include "sky/eye/tone_curve.h"

#include <memory>
#include <vector>

namespace skyig::sky {

struct SkyState;

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
