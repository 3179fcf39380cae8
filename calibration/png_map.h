#pragma once
// The blend maps of MPCDI files are PNG images, 8 or 16 bits, grey or RGB: read into a FloatMap
// in [0, 1] of one channel (grey) or three (RGB, MPCDI's componentDepth 3: each colour of the
// projector blends with its own component; an alpha channel is dropped), and written as 16-bit
// grey by the MPCDI writer.
#include "calibration/projector.h"

#include <cstdint>
#include <string>
#include <vector>

namespace skyig::calibration {

// Throws CalibrationError naming `name` when the bytes are not a PNG libpng can decode, or when
// its header says it is wider than maxWidth or taller than maxHeight (checked before a pixel is
// decoded or allocated).
FloatMap readPngMap(const std::vector<std::uint8_t>& bytes, const std::string& name, int maxWidth, int maxHeight);

// Values clamped to [0, 1], 16-bit grey PNG bytes.
std::vector<std::uint8_t> writePngMap16(const FloatMap& map);

}  // namespace skyig::calibration
