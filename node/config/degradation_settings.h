#pragma once
// [degrade] of the node's configuration: when and how far a node that cannot hold its frame rate
// lowers its channels' internal resolution (the policy: node/frame/degradation.h).
#include <vector>

namespace skyig::services {

struct DegradationSettings {
  bool enabled = false;             // off: always full resolution (render and replay never degrade)
  int overFrames = 30;              // frames over the period in a row before a level down
  std::vector<double> scales{0.75, 0.5};  // each level's scale of a side below full, descending
  double releaseHeadroom = 0.6;     // a level up when the level above would take under this share
  int releaseFrames = 120;          //   of the period, this many frames in a row

  // Throws std::invalid_argument naming the value when the settings cannot work.
  void validate() const;
};

}  // namespace skyig::services
