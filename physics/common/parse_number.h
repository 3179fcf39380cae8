#pragma once
// A number that is the whole of a word a user wrote ("300", "-1.5e3"), or none: the one reader of
// the command-line specs that pack numbers into a word (render --cloud, --projector).
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace skyig {

inline std::optional<double> parseWholeNumber(const std::string& word) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(word, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used == 0 || used != word.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace skyig
