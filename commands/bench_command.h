#pragma once
#include <CLI/CLI.hpp>

namespace skyig::services {

// `skyig bench`: times the sky and tone passes of one channel, headless. On a GPU with GL
// timer queries; on llvmpipe (whose timer queries cover one tile only, see
// docs/performance.md) with glFinish and the wall clock.
void registerBenchCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
