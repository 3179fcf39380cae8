#pragma once
// The text of the host emulator's scripts (host_path.h's flight, host_weather.h's weather): CSV
// with '#' comments, blank lines and an optional header line before the first data line; commas
// and blanks separate the fields.
#include <functional>
#include <sstream>
#include <string>

namespace skyig::services {

// The file's text; throws ConfigError "<path>: cannot open the <what>".
std::string readHostScript(const std::string& path, const char* what);

// Calls fn(fields, lineNumber) for each data line, its commas made blanks; '#' starts a comment,
// and lines before the first data line whose first field is not a number are a header.
void forEachScriptLine(const std::string& text, const std::function<void(std::istringstream& fields, int lineNumber)>& fn);

}  // namespace skyig::services
