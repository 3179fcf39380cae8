#pragma once
#include <CLI/CLI.hpp>

namespace skyig::services {

// `skyig render`: one frame of one or all channels to OpenEXR (absolute) and PNG (displayed).
void registerRenderCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
