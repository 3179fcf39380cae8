#include "calibration/pfm.h"

#include "calibration/calibration_error.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace skyig::calibration {

namespace {

// The header's whitespace-separated tokens: the format, width, height and scale, then exactly
// one whitespace byte before the data.
struct Header {
  std::string format;
  long width = 0, height = 0;
  double scale = 0.0;
  std::size_t dataOffset = 0;
};

Header parseHeader(const std::vector<std::uint8_t>& bytes, const std::string& name) {
  Header h;
  std::size_t at = 0;
  std::string tokens[4];
  for (auto& token : tokens) {
    while (at < bytes.size() && std::isspace(bytes[at])) ++at;
    while (at < bytes.size() && !std::isspace(bytes[at]) && token.size() < 32) token += static_cast<char>(bytes[at++]);
    if (token.empty()) throw CalibrationError(name + ": PFM header: the file ends before the header does");
  }
  if (at >= bytes.size()) throw CalibrationError(name + ": PFM header: no data after the header");
  h.dataOffset = at + 1;  // the single whitespace byte that ends the header
  h.format = tokens[0];
  if (h.format != "PF" && h.format != "Pf")
    throw CalibrationError(name + ": PFM header: expected \"PF\" or \"Pf\", got \"" + h.format + "\"");
  const auto integer = [&](const std::string& t, const char* what) {
    char* end = nullptr;
    const long v = std::strtol(t.c_str(), &end, 10);
    if (*end != '\0' || v <= 0 || v > 65536)
      throw CalibrationError(name + ": PFM header: " + what + " \"" + t + "\" is not a size from 1 to 65536");
    return v;
  };
  h.width = integer(tokens[1], "width");
  h.height = integer(tokens[2], "height");
  char* end = nullptr;
  h.scale = std::strtod(tokens[3].c_str(), &end);
  if (*end != '\0' || !std::isfinite(h.scale) || h.scale == 0.0)
    throw CalibrationError(name + ": PFM header: scale \"" + tokens[3] + "\" is not a finite non-zero number");
  return h;
}

}  // namespace

FloatMap readPfm(const std::vector<std::uint8_t>& bytes, const std::string& name) {
  const Header h = parseHeader(bytes, name);
  FloatMap map;
  map.width = static_cast<int>(h.width);
  map.height = static_cast<int>(h.height);
  map.channels = h.format == "PF" ? 3 : 1;
  const std::size_t count = static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height) *
                            static_cast<std::size_t>(map.channels);
  const std::size_t need = count * 4;
  const std::size_t have = bytes.size() - h.dataOffset;
  if (have < need)
    throw CalibrationError(name + ": PFM data: truncated, " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                           "x" + std::to_string(map.channels) + " floats need " + std::to_string(need) + " bytes, the file has " +
                           std::to_string(have));
  const bool little = h.scale < 0.0;
  const bool swap = little != (std::endian::native == std::endian::little);
  map.values.resize(count);
  const std::size_t rowFloats = static_cast<std::size_t>(h.width) * static_cast<std::size_t>(map.channels);
  for (std::size_t fileRow = 0; fileRow < static_cast<std::size_t>(h.height); ++fileRow) {
    const std::size_t row = static_cast<std::size_t>(h.height) - 1 - fileRow;  // bottom-up in the file
    for (std::size_t i = 0; i < rowFloats; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, bytes.data() + h.dataOffset + (fileRow * rowFloats + i) * 4, 4);
      if (swap) bits = __builtin_bswap32(bits);
      std::memcpy(&map.values[row * rowFloats + i], &bits, 4);
    }
  }
  return map;
}

FloatMap readPfmFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CalibrationError(path + ": cannot open the PFM file");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return readPfm(bytes, path);
}

std::vector<std::uint8_t> writePfm(const FloatMap& map, bool bigEndian) {
  if (map.channels != 1 && map.channels != 3) throw CalibrationError("PFM holds 1 or 3 channels, not " + std::to_string(map.channels));
  std::ostringstream header;
  header << (map.channels == 3 ? "PF" : "Pf") << '\n' << map.width << ' ' << map.height << '\n' << (bigEndian ? "1.0" : "-1.0") << '\n';
  const std::string text = header.str();
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  const bool swap = !bigEndian != (std::endian::native == std::endian::little);
  const std::size_t rowFloats = static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.channels);
  for (int fileRow = 0; fileRow < map.height; ++fileRow) {
    const std::size_t row = static_cast<std::size_t>(map.height - 1 - fileRow);
    for (std::size_t i = 0; i < rowFloats; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, &map.values[row * rowFloats + i], 4);
      if (swap) bits = __builtin_bswap32(bits);
      const auto* b = reinterpret_cast<const std::uint8_t*>(&bits);
      bytes.insert(bytes.end(), b, b + 4);
    }
  }
  return bytes;
}

}  // namespace skyig::calibration
