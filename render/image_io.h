#pragma once
// Image files. EXR: half RGBA, linear Rec.709 primaries with whiteLuminance = 1 so values are
// cd/m^2, plus skyig's string attributes. PNG: 8-bit, the tone-reproduced frame-buffer values
// as the projector receives them (gAMA records the display gamma). Files are encoded in memory
// and written by render/output_file.h: a regular file through a temporary name and a rename
// (a failure never leaves half a file), a FIFO, a device, "-" (stdout) or a link's target in
// place; they throw its OutputPathError or OutputWriteError.
#include "render/image.h"

#include <map>
#include <stdexcept>
#include <string>

namespace skyig::render {

class ImageIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using ImageAttributes = std::map<std::string, std::string>;

void writeExr(const std::string& path, const HdrImage& image, const ImageAttributes& attributes);
void writePng(const std::string& path, const DisplayImage& image, double displayGamma);

struct ExrFile {
  HdrImage image;
  ImageAttributes attributes;  // skyig's string attributes
  float whiteLuminance = 0.0f;
};
ExrFile readExr(const std::string& path);

// checkOutputPath (render/output_file.h): throws OutputPathError if `path` cannot be an output
// (checked before a render, so a bad output path fails fast and writes nothing).
void checkWritable(const std::string& path);

}  // namespace skyig::render
