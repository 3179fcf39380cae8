#include "node/host/host_script.h"

#include "node/common/config_error.h"

#include <algorithm>
#include <fstream>

namespace skyig::services {

std::string readHostScript(const std::string& path, const char* what) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot open the " + what);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void forEachScriptLine(const std::string& text, const std::function<void(std::istringstream& fields, int lineNumber)>& fn) {
  std::istringstream in(text);
  std::string line;
  int lineNumber = 0;
  bool data = false;
  while (std::getline(in, line)) {
    ++lineNumber;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r,") == std::string::npos) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    // A header: a line before any data line whose first field is not a number (a data line
    // starts with its time, and may name things later: "rain").
    if (!data) {
      std::istringstream first(line);
      double time = 0.0;
      if (!(first >> time)) continue;
    }
    data = true;
    std::istringstream fields(line);
    fn(fields, lineNumber);
  }
}

}  // namespace skyig::services
