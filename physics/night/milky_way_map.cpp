#include "physics/night/milky_way_map.h"

#include "ephemeris/data_files.h"
#include "physics/night/diffuse_physics.h"
#include "physics/common/png_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace skyig::sky::night {

namespace {

// 8-bit RGB of a PNG (palette, grey and alpha expanded or stripped).
std::vector<std::uint8_t> readRgb(const std::string& path, int& width, int& height) {
  Rgb8Image image = readPngRgb8(path, "Milky Way map");
  width = image.width;
  height = image.height;
  return std::move(image.rgb);
}

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

double luminance(const glm::vec3& c) {
  const glm::dvec3 d(c);
  return 0.2126 * d.r + 0.7152 * d.g + 0.0722 * d.b;
}

// One pass of a separable minimum or maximum filter of half-width r: rows wrap (the map is
// periodic in RA), columns clamp. Each line is copied with its padding first, so the inner loop
// has no index arithmetic.
void extremumFilter(std::vector<glm::vec3>& image, int width, int height, int r, bool takeMax, bool alongRows) {
  const int lines = alongRows ? height : width, length = alongRows ? width : height;
  const std::size_t stride = alongRows ? 1 : static_cast<std::size_t>(width);
  std::vector<glm::vec3> padded(static_cast<std::size_t>(length + 2 * r));
  for (int l = 0; l < lines; ++l) {
    const std::size_t base = alongRows ? static_cast<std::size_t>(l) * static_cast<std::size_t>(width) : static_cast<std::size_t>(l);
    for (int i = -r; i < length + r; ++i) {
      const int j = alongRows ? (i + length) % length : std::clamp(i, 0, length - 1);
      padded[static_cast<std::size_t>(i + r)] = image[base + static_cast<std::size_t>(j) * stride];
    }
    for (int i = 0; i < length; ++i) {
      glm::vec3 e = padded[static_cast<std::size_t>(i)];
      for (int d = 1; d <= 2 * r; ++d) {
        const glm::vec3& v = padded[static_cast<std::size_t>(i + d)];
        e = takeMax ? glm::max(e, v) : glm::min(e, v);
      }
      image[base + static_cast<std::size_t>(i) * stride] = e;
    }
  }
}

// Grey opening (erosion then dilation) with a (2r+1)^2 square: removes bright features smaller
// than the square (the stars) and keeps wider ones (the Milky Way's clouds and lanes).
void opening(std::vector<glm::vec3>& image, int width, int height, int r) {
  extremumFilter(image, width, height, r, false, true);
  extremumFilter(image, width, height, r, false, false);
  extremumFilter(image, width, height, r, true, true);
  extremumFilter(image, width, height, r, true, false);
}

// One pass of a separable (2r+1)-texel box filter, with the edges of extremumFilter (rows wrap,
// columns clamp).
void boxFilter(std::vector<glm::vec3>& image, int width, int height, int r, bool alongRows) {
  const int lines = alongRows ? height : width, length = alongRows ? width : height;
  const std::size_t stride = alongRows ? 1 : static_cast<std::size_t>(width);
  std::vector<glm::dvec3> padded(static_cast<std::size_t>(length + 2 * r));
  for (int l = 0; l < lines; ++l) {
    const std::size_t base = alongRows ? static_cast<std::size_t>(l) * static_cast<std::size_t>(width) : static_cast<std::size_t>(l);
    for (int i = -r; i < length + r; ++i) {
      const int j = alongRows ? (i + length) % length : std::clamp(i, 0, length - 1);
      padded[static_cast<std::size_t>(i + r)] = glm::dvec3(image[base + static_cast<std::size_t>(j) * stride]);
    }
    glm::dvec3 sum(0.0);
    for (int d = 0; d < 2 * r; ++d) sum += padded[static_cast<std::size_t>(d)];
    for (int i = 0; i < length; ++i) {
      sum += padded[static_cast<std::size_t>(i + 2 * r)];
      image[base + static_cast<std::size_t>(i) * stride] = glm::vec3(sum / static_cast<double>(2 * r + 1));
      sum -= padded[static_cast<std::size_t>(i)];
    }
  }
}

// The opening leaves a mosaic: each local maximum of its erosion becomes a flat (2r+1)^2-texel
// plateau, with a step to the next (0.9 deg squares, wider in RA away from the equator, which a
// display with the eye's contrast shows as blocks). Two passes of a box of the same width (a
// 4r+1-texel triangle, 0.9 deg at half maximum, no finer than the opening already made the map)
// turn the steps into smooth ramps, with the map's mean kept.
void smoothPlateaus(std::vector<glm::vec3>& image, int width, int height, int r) {
  for (int pass = 0; pass < 2; ++pass) {
    boxFilter(image, width, height, r, true);
    boxFilter(image, width, height, r, false);
  }
}

}  // namespace

MilkyWayMap::MilkyWayMap(const std::string& pngPath) {
  const std::vector<std::uint8_t> rgb = readRgb(pngPath, width_, height_);
  if (width_ != 2 * height_ || height_ < 16)
    throw std::invalid_argument("Milky Way map " + pngPath + " is " + std::to_string(width_) + "x" +
                                std::to_string(height_) + ", expected an equirectangular 2:1 map");
  texels_.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  double lut[256];
  for (int i = 0; i < 256; ++i) lut[i] = srgbToLinear(i / 255.0);
  for (std::size_t i = 0; i < texels_.size(); ++i)
    texels_[i] = glm::vec3(glm::dvec3(lut[rgb[3 * i]], lut[rgb[3 * i + 1]], lut[rgb[3 * i + 2]]));
  // 2 pixels either side: 5 x 0.176 deg, wider than the catalogue stars' images in the map.
  opening(texels_, width_, height_, 2);
  smoothPlateaus(texels_, width_, height_, 2);

  // Calibration: the mean over |b| >= 60 deg (solid-angle weighted) and the 99th percentile
  // within |b| <= 10 deg of the linear luminance. sin b per pixel from per-row and per-column
  // tables (the map's directions, physics/night/milky_way.glsl), compared with sin 60 and sin 10.
  std::vector<double> sinRa(static_cast<std::size_t>(width_)), cosRa(sinRa.size()), sinDec(static_cast<std::size_t>(height_)),
      cosDec(sinDec.size());
  for (int x = 0; x < width_; ++x) {
    const glm::dvec3 d = shader::milkyWayDirection(glm::dvec2((x + 0.5) / width_, 0.5));
    cosRa[static_cast<std::size_t>(x)] = d.x;
    sinRa[static_cast<std::size_t>(x)] = d.y;
  }
  for (int y = 0; y < height_; ++y) {
    const double dec = (0.5 - (y + 0.5) / height_) * std::numbers::pi;
    sinDec[static_cast<std::size_t>(y)] = std::sin(dec);
    cosDec[static_cast<std::size_t>(y)] = std::cos(dec);
  }
  const double sin60 = std::sin(std::numbers::pi / 3.0), sin10 = std::sin(std::numbers::pi / 18.0);
  // Mean over the polar caps and the band's 99th percentile of the current texels.
  auto measure = [&](double& poleMean, double& bandP99) {
    double sum = 0.0, weightSum = 0.0;
    std::vector<double> band;
    for (int y = 0; y < height_; ++y) {
      const double weight = cosDec[static_cast<std::size_t>(y)];
      for (int x = 0; x < width_; ++x) {
        const glm::dvec3 dir(cosDec[static_cast<std::size_t>(y)] * cosRa[static_cast<std::size_t>(x)],
                             cosDec[static_cast<std::size_t>(y)] * sinRa[static_cast<std::size_t>(x)], sinDec[static_cast<std::size_t>(y)]);
        const double sinB = std::abs(shader::galacticSinLatitude(dir));
        const double y709 = luminance(texels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)]);
        if (sinB >= sin60) {
          sum += weight * y709;
          weightSum += weight;
        } else if (sinB <= sin10 && weight > 0.05) {
          band.push_back(y709);
        }
      }
    }
    poleMean = sum / weightSum;
    auto p99 = band.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(band.size()));
    std::nth_element(band.begin(), p99, band.end());
    bandP99 = *p99;
  };
  double pole = 0.0, bright = 0.0;
  measure(pole, bright);
  if (!(bright > pole)) throw std::invalid_argument("Milky Way map " + pngPath + " shows no galactic band");
  // S10 = scale (Y - offset): two equations, two unknowns.
  const double scale = (kBrightestS10 - kPoleS10) / (bright - pole);
  const double offset = pole - kPoleS10 / scale;
  for (glm::vec3& t : texels_) {
    const double y709 = luminance(t);
    const double s10 = std::max(scale * (y709 - offset), 0.0);
    // The affine map per channel, scale (t - offset grey): the photograph's black (its sky
    // background already removed) carries the floor, grey, since the faint starlight there has
    // no colour the photograph can tell, and only the light above it has the photograph's
    // colour; its luminance is s10. (Scaling each texel's own colour to s10 turned a texel whose
    // blue channel alone had left the black into pure blue at the floor's luminance: a
    // hard-edged blue patch along the band.) Where the offset is positive a dim coloured texel
    // can go below zero in a channel: it is desaturated towards grey at its luminance.
    glm::dvec3 c = scale * (glm::dvec3(t) - glm::dvec3(offset));
    const double least = std::min({c.r, c.g, c.b});
    if (s10 <= 0.0) {
      c = glm::dvec3(0.0);
    } else if (least < 0.0) {
      c = glm::dvec3(s10) + (c - glm::dvec3(s10)) * (s10 / (s10 - least));
    }
    t = glm::vec3(c);
  }
  // What the clip left of the anchors, for the record.
  measure(meanPole_, bright_);
}

glm::dvec3 MilkyWayMap::sampleS10(const glm::dvec2& uv) const {
  const double fx = uv.x * width_ - 0.5, fy = std::clamp(uv.y * height_ - 0.5, 0.0, height_ - 1.0);
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double ax = fx - x0, ay = fy - y0;
  auto at = [&](int x, int y) {
    x = ((x % width_) + width_) % width_;
    y = std::clamp(y, 0, height_ - 1);
    return glm::dvec3(texels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)]);
  };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), ax), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), ax), ay);
}

glm::dvec3 MilkyWayMap::s10(const glm::dvec3& directionJ2000) const {
  return sampleS10(shader::milkyWayTexCoord(glm::normalize(directionJ2000)));
}

std::string MilkyWayMap::standardPath() { return ephemeris::dataFilePath("milkyway.png"); }

std::shared_ptr<const MilkyWayMap> MilkyWayMap::standard() {
  static std::mutex mutex;
  static std::shared_ptr<const MilkyWayMap> map;
  std::lock_guard lock(mutex);
  if (!map) map = std::make_shared<const MilkyWayMap>(ephemeris::requireDataFile("milkyway.png"));
  return map;
}

}  // namespace skyig::sky::night
