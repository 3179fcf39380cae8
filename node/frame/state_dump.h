#pragma once
// `--dump-state FILE.jsonl`: one JSON line per rendered frame — the IG frame, the last host
// frame, the host's values as last received, what the frame used (the state's observer, air,
// star field, atmosphere tables and adaptation; the frame's own attitude and channel views),
// and the sun and moon — for debugging, support and tests. `serve` and `replay` write the same
// lines, so a replay can be compared with the flight line by line; serve adds the frame's
// timing ("timing": the frame's milliseconds and each channel's GPU milliseconds).
#include "sky/sky_state.h"
#include "node/host/host_snapshot.h"
#include "node/host/node_stats.h"
#include "node/frame/sky_worker.h"

#include <cstdio>
#include <string>
#include <vector>

namespace skyig::services {

class StateDump {
 public:
  explicit StateDump(const std::string& path);  // throws std::runtime_error naming the path
  ~StateDump();
  StateDump(const StateDump&) = delete;
  StateDump& operator=(const StateDump&) = delete;
  // `channelGpuS` in pose.channels' order; `frameS` < 0: no timing (replay).
  void write(std::uint64_t igFrame, const HostSnapshot* host, const sky::SkyState& used, const FramePose& pose,
             double frameS = -1.0, const std::vector<double>& channelGpuS = {});

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
};

// Writes the counters as JSON through a temporary file, so a reader never sees half of it.
void writeStatsFile(const std::string& path, const NodeStats& stats);

}  // namespace skyig::services
