#pragma once
// Image files. EXR: float RGBA, linear Rec.709 primaries with whiteLuminance = 1 so values are
// cd/m^2, plus typed header attributes (strings, numbers as numbers, matrices). PNG: 8-bit, the
// tone-reproduced frame-buffer values as the projector receives them (gAMA records the display
// gamma). Files are encoded in memory and written by render/output_file.h: a regular file
// through a temporary name and a rename (a failure never leaves half a file), a FIFO, a device,
// "-" (stdout) or a link's target in place; they throw its OutputPathError or OutputWriteError.
#include "render/image.h"

#include <array>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>

namespace skyig::render {

class ImageIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A 4x4 matrix as OpenEXR's M44f holds it: m[row][column], applied to row vectors
// (p' = p M), so the last row is the translation.
struct Matrix44f {
  std::array<std::array<float, 4>, 4> m{};
  bool operator==(const Matrix44f&) const = default;
};

// One header attribute, stored as OpenEXR's string, int, float, double or m44f attribute.
// OpenEXR's standard attributes have fixed types (ImfStandardAttributes.h: latitude,
// longitude, altitude, utcOffset float; capDate, owner, comments string; worldToCamera m44f).
using AttributeValue = std::variant<std::string, int, float, double, Matrix44f>;
using ImageAttributes = std::map<std::string, AttributeValue>;

void writeExr(const std::string& path, const HdrImage& image, const ImageAttributes& attributes);
void writePng(const std::string& path, const DisplayImage& image, double displayGamma);

struct ExrFile {
  HdrImage image;
  ImageAttributes attributes;  // every string, int, float, double and m44f attribute of the header
  float whiteLuminance = 0.0f;
};
ExrFile readExr(const std::string& path);

// checkOutputPath (render/output_file.h): throws OutputPathError if `path` cannot be an output
// (checked before a render, so a bad output path fails fast and writes nothing).
void checkWritable(const std::string& path);

}  // namespace skyig::render
