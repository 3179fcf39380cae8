#pragma once
// Portable Float Map (PFM), the float image MPCDI stores its geometry warps in: a text header
// "PF" (3 channels) or "Pf" (1 channel), "WIDTH HEIGHT", and a scale whose sign gives the byte
// order (negative: little-endian), then WIDTH x HEIGHT x channels 32-bit IEEE floats with the
// rows from the BOTTOM of the image up (Debevec's HDRShop definition of the format, which the
// MPCDI v2 standard (VESA 2015) names for its warp files). FloatMap rows are top-down: reading
// and writing turn the rows over.
#include "calibration/projector.h"

#include <cstdint>
#include <string>
#include <vector>

namespace skyig::calibration {

// `name` is the file's name for messages. Throws CalibrationError naming it: a bad header, a
// non-finite or zero scale, or fewer bytes than the header promises.
FloatMap readPfm(const std::vector<std::uint8_t>& bytes, const std::string& name);
FloatMap readPfmFile(const std::string& path);

// A 1- or 3-channel map as PFM bytes, little-endian (scale -1) unless `bigEndian`.
std::vector<std::uint8_t> writePfm(const FloatMap& map, bool bigEndian = false);

}  // namespace skyig::calibration
