#pragma once
#include <CLI/CLI.hpp>

namespace skyig::services {

// `skyig host`: a host emulator flying a scripted path and sending CIGI over UDP at a rate,
// with the date and time advancing (optionally time-lapsed); it can drop and reorder
// datagrams to exercise an IG.
void registerHostCommand(CLI::App& app, int& exitCode);

}  // namespace skyig::services
