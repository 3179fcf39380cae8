#include "render/image_io.h"

#include <ImfChromaticitiesAttribute.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfIntAttribute.h>
#include <ImfMatrixAttribute.h>
#include <ImfHeader.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#include "render/output_file.h"

namespace skyig::render {

namespace fs = std::filesystem;

namespace {

// libpng's output: appended to a byte vector (the file is written whole, render/output_file.h).
extern "C" void appendPngBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::byte>*>(png_get_io_ptr(png));
  const auto* bytes = reinterpret_cast<const std::byte*>(data);
  out->insert(out->end(), bytes, bytes + length);
}
extern "C" void flushPngBytes(png_structp) {}

void insertAttribute(Imf::Header& header, const std::string& name, const AttributeValue& value) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) header.insert(name, Imf::StringAttribute(v));
        else if constexpr (std::is_same_v<T, int>) header.insert(name, Imf::IntAttribute(v));
        else if constexpr (std::is_same_v<T, float>) header.insert(name, Imf::FloatAttribute(v));
        else if constexpr (std::is_same_v<T, double>) header.insert(name, Imf::DoubleAttribute(v));
        else {
          Imath::M44f m;
          for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m[r][c] = v.m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
          header.insert(name, Imf::M44fAttribute(m));
        }
      },
      value);
}

std::optional<AttributeValue> readAttribute(const Imf::Attribute& a) {
  if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) return AttributeValue(s->value());
  if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a)) return AttributeValue(i->value());
  if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a)) return AttributeValue(f->value());
  if (const auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&a)) return AttributeValue(d->value());
  if (const auto* m = dynamic_cast<const Imf::M44fAttribute*>(&a)) {
    Matrix44f out;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out.m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = m->value()[r][c];
    return AttributeValue(out);
  }
  return std::nullopt;
}

}  // namespace

void checkWritable(const std::string& path) { checkOutputPath(path); }

void writeExr(const std::string& path, const HdrImage& image, const ImageAttributes& attributes) {
  // Encoded in memory: OpenEXR seeks back to write its offset table, which a FIFO or standard
  // output cannot; the bytes then go out by the output rules (render/output_file.h).
  std::string bytes;
  try {
    Imf::Header header(image.width, image.height);
    Imf::addChromaticities(header, Imf::Chromaticities());  // Rec.709 primaries, D65 white
    Imf::addWhiteLuminance(header, 1.0f);                  // one unit = 1 cd/m^2
    for (const auto& [key, value] : attributes) insertAttribute(header, key, value);
    // 32-bit float: the sun's disc (1.6e9 cd/m^2) and a moonless sky (1e-4) both keep their
    // values; half float overflows at 65504 and turned the sun into +Inf.
    const char* names[] = {"R", "G", "B", "A"};
    Imf::FrameBuffer frame;
    const std::size_t pixelBytes = 4 * sizeof(float), rowBytes = pixelBytes * static_cast<std::size_t>(image.width);
    for (int c = 0; c < 4; ++c) {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      // OpenEXR's slices take a char* base even for writing.
      char* base = const_cast<char*>(reinterpret_cast<const char*>(image.rgba.data() + c));  // NOLINT
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, base, pixelBytes, rowBytes));
    }
    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frame);
      file.writePixels(image.height);
    }  // the file is complete when OutputFile is destroyed
    bytes = stream.str();
  } catch (const std::exception& e) {
    throw ImageIoError("cannot write " + path + ": " + e.what());
  }
  writeOutputFile(path, bytes);
}

ExrFile readExr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());  // half or float channels, read as float
    const Imath::Box2i dw = file.header().dataWindow();
    ExrFile out;
    out.image.width = dw.max.x - dw.min.x + 1;
    out.image.height = dw.max.y - dw.min.y + 1;
    out.image.rgba.assign(static_cast<std::size_t>(out.image.width) * static_cast<std::size_t>(out.image.height) * 4, 0.0f);
    const std::size_t pixelBytes = 4 * sizeof(float), rowBytes = pixelBytes * static_cast<std::size_t>(out.image.width);
    char* origin = reinterpret_cast<char*>(out.image.rgba.data()) -
                   static_cast<std::ptrdiff_t>(dw.min.x) * static_cast<std::ptrdiff_t>(pixelBytes) -
                   static_cast<std::ptrdiff_t>(dw.min.y) * static_cast<std::ptrdiff_t>(rowBytes);
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * static_cast<std::ptrdiff_t>(sizeof(float)), pixelBytes,
                                        rowBytes, 1, 1, c == 3 ? 1.0 : 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(dw.min.y, dw.max.y);
    if (Imf::hasWhiteLuminance(file.header())) out.whiteLuminance = Imf::whiteLuminance(file.header());
    for (auto it = file.header().begin(); it != file.header().end(); ++it)
      if (auto value = readAttribute(it.attribute())) out.attributes[it.name()] = std::move(*value);
    return out;
  } catch (const std::exception& e) {
    throw ImageIoError("cannot read " + path + ": " + e.what());
  }
}

void writePng(const std::string& path, const DisplayImage& image, double displayGamma) {
  std::vector<std::byte> bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  volatile bool ok = png && info;  // volatile: read after a longjmp
  if (ok && setjmp(png_jmpbuf(png))) ok = false;  // libpng reports errors by longjmp
  if (ok) {
    png_set_write_fn(png, &bytes, appendPngBytes, flushPngBytes);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
                 PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_gAMA(png, info, 1.0 / displayGamma);
    // zlib's fastest level and the Sub filter alone: a frame of sky is smooth along its rows, so
    // the left neighbour predicts it nearly as well as the best of the five filters libpng would
    // try on every row. At 1920 x 1200 the encoding takes 0.4 s instead of 1.25 s (llvmpipe
    // machine, 2 cores) for a file 26% larger (2.1 MB against 1.7): it was most of a rendered
    // frame's cost, and of a replay's.
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    for (int row = 0; row < image.height; ++row)
      png_write_row(png, &image.rgba[static_cast<size_t>(row) * static_cast<size_t>(image.width) * 4]);
    png_write_end(png, nullptr);
  }
  png_destroy_write_struct(png ? &png : nullptr, info ? &info : nullptr);
  if (!ok) throw ImageIoError("cannot write " + path + ": PNG encoding failed");
  writeOutputFile(path, bytes);
}

}  // namespace skyig::render
