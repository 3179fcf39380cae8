#pragma once
#include <string>

namespace skyig::services {

// `skyig --version [--caps]`: the build, and with caps the GL renderer and its limits and the
// host transports this machine supports — the first thing anyone asks for when a node misbehaves.
std::string versionText();
std::string capsText();

}  // namespace skyig::services
