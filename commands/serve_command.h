#pragma once
#include <CLI/CLI.hpp>

namespace skyig::services {

// `skyig serve`: the IG node. Windows (one per channel) or --headless; CIGI over UDP and/or
// CANaerospace over SocketCAN; Start of Frame every frame; clean stop on SIGINT/SIGTERM.
void registerServeCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
