#include "node/config/degradation_settings.h"

#include <fmt/format.h>

#include <stdexcept>

namespace skyig::services {

void DegradationSettings::validate() const {
  if (overFrames < 1) throw std::invalid_argument(fmt::format("over_frames {} is not at least 1", overFrames));
  if (releaseFrames < 1) throw std::invalid_argument(fmt::format("release_frames {} is not at least 1", releaseFrames));
  if (!(releaseHeadroom > 0.0 && releaseHeadroom < 1.0))
    throw std::invalid_argument(fmt::format("release_headroom {} is not between 0 and 1", releaseHeadroom));
  if (scales.empty()) throw std::invalid_argument("scales is empty: give at least one, e.g. [0.75, 0.5]");
  double above = 1.0;
  for (double s : scales) {
    if (!(s >= 0.25 && s < above))
      throw std::invalid_argument(
          fmt::format("scales: {} is not from 0.25 up to and below the level above's {}", s, above));
    above = s;
  }
}

}  // namespace skyig::services
