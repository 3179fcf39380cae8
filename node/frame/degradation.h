#pragma once
// What a node does when it cannot hold its frame rate (`skyig serve`, `[degrade]`): after
// `overFrames` frames in a row whose work took longer than the target period, every channel of
// the node is drawn at the next lower internal resolution (each side times the level's scale;
// the frustum and the window stay, the image is stretched to them); once `releaseFrames` frames
// in a row would have fitted under `releaseHeadroom` of the period at the level above, it goes
// back up one level. A frame's cost is taken as proportional to its pixels: a frame of work w at
// scale s would take w (s_up / s)^2 at scale s_up. Pure: no clock, no GL; the frame loop feeds it.
//
// One decision for the whole node, so no seam between its channels (they are drawn at one
// scale); the sky drawn at a lower resolution keeps its colours (the eye's adaptation and the
// display mapping come from the sky state, not from the frame's pixels). Nodes decide each on
// their own timing: a dome's nodes with the same work and budget decide alike.
#include "node/config/degradation_settings.h"

#include <cstdint>
#include <string>

namespace skyig::services {

class DegradationPolicy {
 public:
  explicit DegradationPolicy(DegradationSettings settings);

  // One frame: its work (seconds) against the target period. Returns the change of level that
  // takes effect from the next frame: +1 one level down (lower resolution), -1 one up, 0 none.
  int add(double workS, double periodS);

  int level() const { return level_; }  // 0: full resolution
  double scale() const { return scaleAt(level_); }
  std::uint64_t levelsDown() const { return downs_; }
  std::uint64_t levelsUp() const { return ups_; }
  // "frame work 21.3 ms over the 16.7 ms period for 30 frames: channels drawn at 0.75 of their
  // size" and the like, for the log line of the last change.
  const std::string& lastReason() const { return reason_; }

 private:
  double scaleAt(int level) const;

  DegradationSettings s_;
  int level_ = 0;
  int over_ = 0;     // frames over the period in a row
  int fitting_ = 0;  // frames in a row that the level above would have fitted
  std::uint64_t downs_ = 0, ups_ = 0;
  std::string reason_;
};

}  // namespace skyig::services
