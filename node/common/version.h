#pragma once
#include <string_view>

namespace skyig::services {
inline constexpr std::string_view kVersion = SKYIG_VERSION;
}
