#pragma once
#include <CLI/CLI.hpp>

namespace skyig::services {

// `skyig probe`: the physical atmosphere's sky, sun and ground radiance in given view
// directions, as JSON, without an image (the CPU evaluation of the same shader code).
void registerProbeCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
