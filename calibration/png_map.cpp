#include "calibration/png_map.h"

#include "calibration/calibration_error.h"

#include <png.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace skyig::calibration {

namespace {

struct Reader {
  const std::vector<std::uint8_t>* bytes;
  std::size_t at = 0;
};

void readBytes(png_structp png, png_bytep out, png_size_t count) {
  auto* r = static_cast<Reader*>(png_get_io_ptr(png));
  if (r->at + count > r->bytes->size()) png_error(png, "the PNG data ends early");
  std::memcpy(out, r->bytes->data() + r->at, count);
  r->at += count;
}

void fail(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void warn(png_structp, png_const_charp) {}

void writeBytes(png_structp png, png_bytep data, png_size_t count) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + count);
}

}  // namespace

FloatMap readPngMap(const std::vector<std::uint8_t>& bytes, const std::string& name, int maxWidth, int maxHeight) {
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) throw CalibrationError(name + ": not a PNG file");
  // The size in the header (the first chunk, IHDR: width and height big-endian at bytes 16 and
  // 20), before libpng allocates anything for it.
  if (bytes.size() >= 24 && std::memcmp(bytes.data() + 12, "IHDR", 4) == 0) {
    const auto be32 = [&](std::size_t at) {
      return std::uint64_t{bytes[at]} << 24 | std::uint64_t{bytes[at + 1]} << 16 | std::uint64_t{bytes[at + 2]} << 8 |
             std::uint64_t{bytes[at + 3]};
    };
    const std::uint64_t w = be32(16), h = be32(20);
    if (w > static_cast<std::uint64_t>(maxWidth) || h > static_cast<std::uint64_t>(maxHeight))
      throw CalibrationError(name + ": its header says " + std::to_string(w) + "x" + std::to_string(h) +
                             " pixels, larger than the " + std::to_string(maxWidth) + "x" + std::to_string(maxHeight) +
                             " it can cover (nothing decoded)");
  }
  std::string error;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, fail, warn);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    throw CalibrationError(name + ": cannot allocate a PNG decoder");
  }
  Reader reader{&bytes};
  FloatMap map;
  std::vector<std::uint16_t> pixels;
  std::vector<png_bytep> rows;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw CalibrationError(name + ": PNG: " + error);
  }
  png_set_read_fn(png, &reader, readBytes);
  // libpng refuses a larger header itself, and keeps what ancillary chunks may allocate small.
  png_set_user_limits(png, static_cast<png_uint_32>(std::max(maxWidth, 1)), static_cast<png_uint_32>(std::max(maxHeight, 1)));
  png_set_chunk_malloc_max(png, 8u << 20);
  png_read_info(png, info);
  png_set_expand(png);  // palette and low-bit grey to 8 bits
  png_set_strip_alpha(png);
  if (png_get_bit_depth(png, info) < 16) png_set_expand_16(png);
  if (std::endian::native == std::endian::little) png_set_swap(png);
  png_read_update_info(png, info);
  const int channels = png_get_channels(png, info);
  map.width = static_cast<int>(png_get_image_width(png, info));
  map.height = static_cast<int>(png_get_image_height(png, info));
  pixels.resize(static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height) * static_cast<std::size_t>(channels));
  rows.resize(static_cast<std::size_t>(map.height));
  for (int y = 0; y < map.height; ++y)
    rows[static_cast<std::size_t>(y)] = reinterpret_cast<png_bytep>(pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(map.width) * static_cast<std::size_t>(channels));
  png_read_image(png, rows.data());
  png_destroy_read_struct(&png, &info, nullptr);
  map.channels = channels;  // 1 (grey) or 3 (RGB: each colour blends with its own component)
  map.values.resize(pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) map.values[i] = static_cast<float>(pixels[i] / 65535.0);
  return map;
}

std::vector<std::uint8_t> writePngMap16(const FloatMap& map) {
  std::vector<std::uint8_t> out;
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, fail, warn);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw CalibrationError("cannot allocate a PNG encoder");
  }
  std::vector<std::uint8_t> row(static_cast<std::size_t>(map.width) * 2);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw CalibrationError("PNG: " + error);
  }
  png_set_write_fn(png, &out, writeBytes, nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(map.width), static_cast<png_uint_32>(map.height), 16, PNG_COLOR_TYPE_GRAY,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const float v = map.at(x, y, 0);
      const auto q = static_cast<std::uint16_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 65535.0f));
      row[static_cast<std::size_t>(x) * 2] = static_cast<std::uint8_t>(q >> 8);  // PNG is big-endian
      row[static_cast<std::size_t>(x) * 2 + 1] = static_cast<std::uint8_t>(q & 0xff);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace skyig::calibration
