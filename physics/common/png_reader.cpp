#include "physics/common/png_reader.h"

#include <png.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace skyig::sky {

namespace {

struct PngError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// libpng reports errors through this callback; throwing out of it unwinds past libpng's frames,
// which it allows in C++ builds instead of longjmp.
[[noreturn]] void pngError(png_structp, png_const_charp message) { throw PngError(message); }

}  // namespace

Rgb8Image readPngRgb8(const std::string& path, const std::string& what) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw std::runtime_error(what + " " + path + " cannot be opened");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, pngError, nullptr);
  png_infop info = png_create_info_struct(png);
  Rgb8Image image;
  try {
    png_init_io(png, file.get());
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    image.width = static_cast<int>(png_get_image_width(png, info));
    image.height = static_cast<int>(png_get_image_height(png, info));
    if (png_get_channels(png, info) != 3 || png_get_bit_depth(png, info) != 8) throw PngError("unexpected pixel format");
    const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 3;
    image.rgb.resize(rowBytes * static_cast<std::size_t>(image.height));
    std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = &image.rgb[y * rowBytes];
    png_read_image(png, rows.data());
  } catch (const PngError& e) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(what + " " + path + ": " + e.what());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

}  // namespace skyig::sky
