#pragma once
// `skyig bench --ratios`: the sky pass and the whole frame as same-run ratios against the frozen
// reference of the sky pass (render/passes/sky/reference_sky_pass.h). On a shared, noisy machine an
// absolute time moves by 2x with the load; a ratio of two passes measured in the same rounds,
// interleaved, holds to a few per cent. The figure is process CPU time per pixel: every thread
// of llvmpipe counts in it, so it survives a busy 2-core machine.
#include "node/config/node_config.h"

#include <optional>
#include <string>

namespace skyig::services {

struct RatiosOptions {
  int width = 1280;
  int height = 1024;
  int rounds = 5;            // each measures every item once, in alternating order
  int framesPerRound = 3;    // frames per item and round
  // LP_NUM_THREADS for llvmpipe, set before the GL context is made; unset: 1 unless the
  // environment already sets it (one thread: no waiting between tiles in the figures).
  std::optional<int> llvmpipeThreads;
  bool json = false;
};

// Loads `config`'s tables and star catalogue, draws the scenes and prints the table (or JSON on
// stdout; progress on stderr). Returns the exit code.
int runRatiosBench(NodeConfig config, const RatiosOptions& options);

// What LP_NUM_THREADS the bench runs with, set in the environment before any GL context:
// `requested` when given (0: llvmpipe's own default, the variable removed), else the
// environment's value, else 1. Returns how it was chosen, for the output.
std::string pinLlvmpipeThreads(const std::optional<int>& requested);

}  // namespace skyig::services
