#pragma once
// The moon's albedo map (physics/moon/data/moon.png: USGS Astrogeology + Clementine, public domain),
// equirectangular in selenographic longitude and latitude with longitude 0 at the centre, as
// relative albedo: scaled to a mean of 1 over the near side's disc, so the map changes the
// moon's look but not its mean brightness.
#include <string>
#include <vector>

namespace skyig::sky::night {

class MoonAlbedo {
 public:
  // Reads an 8-bit grey or RGB PNG; throws std::runtime_error naming the path if it cannot.
  static MoonAlbedo load(const std::string& path);
  // A featureless moon (albedo 1 everywhere), for checks of the reflectance law alone.
  static const MoonAlbedo& uniform();
  // The map at moonAlbedoPath(), read once per process; throws ephemeris::DataFileError when it
  // is missing.
  static const MoonAlbedo& standard();

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<float>& texels() const { return texels_; }  // row 0 = north, x fastest
  // Bilinear, as GL_LINEAR with GL_REPEAT in u and GL_CLAMP_TO_EDGE in v.
  double sample(double u, double v) const;

 private:
  MoonAlbedo(int width, int height, std::vector<float> texels);
  int width_;
  int height_;
  std::vector<float> texels_;
};

// moon.png in skyig's data directory (ephemeris/data_files.h), whether or not it is there.
std::string moonAlbedoPath();

}  // namespace skyig::sky::night
