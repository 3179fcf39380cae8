#include "node/frame/degradation.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace skyig::services {

DegradationPolicy::DegradationPolicy(DegradationSettings settings) : s_(std::move(settings)) {
  if (s_.enabled) s_.validate();
}

double DegradationPolicy::scaleAt(int level) const {
  return level == 0 ? 1.0 : s_.scales[static_cast<std::size_t>(level - 1)];
}

int DegradationPolicy::add(double workS, double periodS) {
  if (!s_.enabled || !std::isfinite(workS) || !(periodS > 0.0)) return 0;
  over_ = workS > periodS ? over_ + 1 : 0;
  if (level_ < static_cast<int>(s_.scales.size()) && over_ >= s_.overFrames) {
    ++level_;
    ++downs_;
    over_ = fitting_ = 0;
    reason_ = fmt::format("frame work {:.1f} ms over the {:.1f} ms period for {} frames: channels drawn at {:.2f} of their size",
                          1e3 * workS, 1e3 * periodS, s_.overFrames, scale());
    return +1;
  }
  if (level_ == 0) return 0;
  const double ratio = scaleAt(level_ - 1) / scale();
  const double aboveS = workS * ratio * ratio;
  fitting_ = aboveS < s_.releaseHeadroom * periodS ? fitting_ + 1 : 0;
  if (fitting_ < s_.releaseFrames) return 0;
  --level_;
  ++ups_;
  over_ = fitting_ = 0;
  reason_ = fmt::format("frame work {:.1f} ms would be {:.1f} ms at {:.2f}, under {:.0f}% of the {:.1f} ms period for {} "
                        "frames: channels drawn at {:.2f} of their size",
                        1e3 * workS, 1e3 * aboveS, scale(), 100.0 * s_.releaseHeadroom, 1e3 * periodS,
                        s_.releaseFrames, scale());
  return -1;
}

}  // namespace skyig::services
