#include "physics/moon/moon_albedo.h"

#include "ephemeris/data_files.h"
#include "physics/moon/moon_physics.h"
#include "physics/common/png_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace skyig::sky::night {

namespace {

// Grey values of an 8-bit PNG. Taken as linear in albedo, not sRGB-decoded: read linearly the
// map's maria are about half as bright as its highlands, as measured normal albedos are (about
// 0.07 against 0.12-0.15); sRGB decoding would make them five times darker.
std::vector<float> readGrey(const std::string& path, int& width, int& height) {
  const Rgb8Image image = readPngRgb8(path, "moon albedo map");
  width = image.width;
  height = image.height;
  std::vector<float> grey(image.rgb.size() / 3);
  for (std::size_t i = 0; i < grey.size(); ++i)  // the map is grey: the mean of its channels
    grey[i] = (static_cast<float>(image.rgb[3 * i]) + static_cast<float>(image.rgb[3 * i + 1]) +
               static_cast<float>(image.rgb[3 * i + 2])) / 3.0f;
  return grey;
}

}  // namespace

MoonAlbedo::MoonAlbedo(int width, int height, std::vector<float> texels)
    : width_(width), height_(height), texels_(std::move(texels)) {
  // Scale to a mean of 1 over the near side as seen (weighted by projected area, the earthshine's
  // and full moon's weighting): a midpoint grid on the disc, near side facing +x, north +z.
  constexpr int kGrid = 128;
  double sum = 0.0;
  int count = 0;
  const glm::dvec3 toObserver(1, 0, 0), east(0, 1, 0), north(0, 0, 1);
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const glm::dvec3 q(0.0, 2.0 * (i + 0.5) / kGrid - 1.0, 2.0 * (j + 0.5) / kGrid - 1.0);
      if (glm::dot(q, q) >= 1.0) continue;
      const glm::dvec3 n = shader::moonSurfaceNormal(q, -toObserver);
      const glm::dvec2 uv = shader::selenographicUv(n, toObserver, north, east);
      sum += sample(uv.x, uv.y);
      ++count;
    }
  const double mean = sum / count;
  if (!(mean > 0.0)) throw std::runtime_error("moon albedo map is black on the near side");
  for (float& t : texels_) t = static_cast<float>(static_cast<double>(t) / mean);
}

MoonAlbedo MoonAlbedo::load(const std::string& path) {
  int width = 0, height = 0;
  std::vector<float> grey = readGrey(path, width, height);
  return MoonAlbedo(width, height, std::move(grey));
}

const MoonAlbedo& MoonAlbedo::uniform() {
  static const MoonAlbedo map(1, 1, {1.0f});
  return map;
}

const MoonAlbedo& MoonAlbedo::standard() {
  static const MoonAlbedo map = load(ephemeris::requireDataFile("moon.png"));
  return map;
}

double MoonAlbedo::sample(double u, double v) const {
  const double x = u * width_ - 0.5, y = std::clamp(v * height_ - 0.5, 0.0, height_ - 1.0);
  const double fx = std::floor(x), fy = std::floor(y);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const double tx = x - fx, ty = y - fy;
  auto at = [&](int xi, int yi) {
    xi = ((xi % width_) + width_) % width_;
    yi = std::clamp(yi, 0, height_ - 1);
    return static_cast<double>(texels_[static_cast<std::size_t>(yi) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(xi)]);
  };
  return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) + (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

std::string moonAlbedoPath() { return ephemeris::dataFilePath("moon.png"); }

}  // namespace skyig::sky::night
