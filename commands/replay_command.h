#pragma once
#include <CLI/CLI.hpp>

namespace skyig::services {

// `skyig record`: capture what the host sends, unchanged, with arrival times.
void registerRecordCommand(CLI::App& app, int& exitCode);
// `skyig replay FILE`: re-render a recording exactly, or re-transmit it to a live IG.
void registerReplayCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
