#pragma once
// 8-bit RGB of a PNG file for the night sky's maps (the moon's albedo, the Milky Way): palette,
// grey and 16-bit images expanded or reduced, alpha dropped. No GL.
#include <cstdint>
#include <string>
#include <vector>

namespace skyig::sky {

struct Rgb8Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // rows top to bottom, 3 bytes a pixel
};

// Throws std::runtime_error "WHAT PATH: reason" (`what` names the map) when the file cannot be
// opened or decoded.
Rgb8Image readPngRgb8(const std::string& path, const std::string& what);

}  // namespace skyig::sky
