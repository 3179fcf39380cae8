#pragma once
// `skyig precompute [--config FILE] [--cache DIR]`: builds (or finds) the physical sky's tables of
// a node configuration and of its visibility steps in the cache, what `serve` would otherwise
// build in the background after its first start; for a package's install step or an operator.
#include <CLI/CLI.hpp>

namespace skyig::services {

void registerPrecomputeCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
