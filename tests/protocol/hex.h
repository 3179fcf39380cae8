#pragma once
// Test helper: bytes from readable hex ("01 18 03 07 ..."), and back for failure messages.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace skyig::protocol::test {

inline std::vector<std::uint8_t> hexBytes(std::string_view text) {
  std::vector<std::uint8_t> out;
  int nibbles = 0;
  unsigned acc = 0;
  for (char c : text) {
    unsigned v;
    if (c >= '0' && c <= '9')
      v = static_cast<unsigned>(c - '0');
    else if (c >= 'a' && c <= 'f')
      v = static_cast<unsigned>(c - 'a' + 10);
    else if (c >= 'A' && c <= 'F')
      v = static_cast<unsigned>(c - 'A' + 10);
    else if (c == ' ' || c == '\n' || c == '|')
      continue;
    else
      throw std::invalid_argument(std::string("bad hex character '") + c + "'");
    acc = (acc << 4) | v;
    if (++nibbles == 2) {
      out.push_back(static_cast<std::uint8_t>(acc));
      nibbles = 0;
      acc = 0;
    }
  }
  if (nibbles != 0) throw std::invalid_argument("odd number of hex digits");
  return out;
}

inline std::string toHex(const std::vector<std::uint8_t>& b) {
  static const char* d = "0123456789ABCDEF";
  std::string s;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (i != 0) s += (i % 8 == 0) ? " | " : " ";
    s += d[b[i] >> 4];
    s += d[b[i] & 15];
  }
  return s;
}

}  // namespace skyig::protocol::test
