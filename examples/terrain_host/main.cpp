// skyig_terrain_host: the example host (terrain_host.h) as a program. Renders one headless frame
// of a terrain under skyig's sky and writes it as an 8-bit sRGB PNG, tone-mapped by the host
// with skyig's adaptation.
//   skyig_terrain_host [--out terrain.png] [--utc 2026-06-21T17:30:00Z] [--config skyig.toml]
//                      [--model physical] [--tables medium] [--lat 47.26 --lon 11.34]
//                      [--yaw 180] [--pitch -2] [--size 640x400]
#include "examples/terrain_host/terrain_host.h"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

namespace {

void writePng(const std::string& path, int w, int h, const std::vector<unsigned char>& rgbBottomUp) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + path);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    throw std::runtime_error("libpng failed writing " + path);
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = h - 1; y >= 0; --y)  // GL's rows are bottom-up
    png_write_row(png, rgbBottomUp.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w) * 3);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

skyig::Utc parseUtc(const std::string& s) {
  skyig::Utc u;
  int hh = 0, mm = 0;
  double ss = 0.0;
  if (std::sscanf(s.c_str(), "%d-%d-%dT%d:%d:%lfZ", &u.year, &u.month, &u.day, &hh, &mm, &ss) != 6)
    throw std::runtime_error("--utc " + s + ": expected YYYY-MM-DDTHH:MM:SSZ");
  u.secondsOfDay = hh * 3600.0 + mm * 60.0 + ss;
  return u;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string out = "terrain.png";
    skyig::Settings settings;
    skyig::Observer observer;
    observer.utc = parseUtc("2026-06-21T17:30:00Z");
    terrain_host::Options options;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (i + 1 >= argc) throw std::runtime_error(a + ": expected a value");
      const std::string v = argv[++i];
      if (a == "--out") out = v;
      else if (a == "--utc") observer.utc = parseUtc(v);
      else if (a == "--config") settings.configFile = v;
      else if (a == "--model") settings.model = v;
      else if (a == "--tables") settings.tables = v;
      else if (a == "--lat") observer.latitudeDeg = std::stod(v);
      else if (a == "--lon") observer.longitudeDeg = std::stod(v);
      else if (a == "--yaw") options.yawDeg = std::stod(v);
      else if (a == "--pitch") options.pitchDeg = std::stod(v);
      else if (a == "--size" && std::sscanf(v.c_str(), "%dx%d", &options.width, &options.height) == 2) continue;
      else throw std::runtime_error("unknown option " + a + " " + v);
    }
    settings.temporalAdaptation = false;  // a still: the eye adapted to it
    skyig::Sky sky(settings);
    sky.update(observer, 0.0);
    terrain_host::HeadlessContext context;
    const terrain_host::Frame frame = terrain_host::drawFrame(sky, options, terrain_host::HeadlessContext::procAddress());
    writePng(out, frame.width, frame.height, terrain_host::toneMap(frame.final, sky.light().adaptationLuminance));
    std::printf("skyig %s: wrote %s (%dx%d), sun %.1f lux, sky ambient %.1f lux, adaptation %.3g cd/m^2\n",
                skyig::version(), out.c_str(), frame.width, frame.height, sky.light().sun.horizontalLux,
                sky.light().ambientHorizontalLux, sky.light().adaptationLuminance);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "skyig_terrain_host: %s\n", e.what());
    return 1;
  }
}
