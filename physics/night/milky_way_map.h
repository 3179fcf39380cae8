#pragma once
// The Milky Way and the unresolved stars: Mellinger's all-sky panorama (physics/night/data/milkyway.png,
// display-referred sRGB, J2000 equatorial) turned into surface brightness above the atmosphere
// (docs/night-sky-diffuse.md, "Milky Way"). At load time:
//  1. decode sRGB to linear;
//  2. remove the stars skyig draws from its catalogue (V <= 6.5) with a grey opening (a 5x5
//     minimum then maximum filter, 0.9 deg): a star's image is a few pixels wide, the Milky
//     Way's structure wider, so the opening keeps the band and drops the point sources; then
//     smooth the opening's flat 5x5 plateaus (two 5-texel box passes), which would otherwise
//     show as 1-2 deg blocks;
//  3. calibrate: an affine map of the map's luminance so that its mean over |b| >= 60 deg is
//     the integrated light of the stars fainter than the naked-eye limit at the galactic poles,
//     and its 99th percentile within |b| <= 10 deg that of the brightest Milky Way star clouds
//     (kPoleS10, kBrightestS10); what falls below zero is the photograph's sky background, and
//     the photograph's black takes the map's floor, grey.
// The result is linear Rec.709 in S10 per channel (luminance-weighted: Y in S10).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

namespace skyig::sky::night {

// Integrated light of stars fainter than the naked eye (V > 6) plus the diffuse galactic light,
// V band: from about 20 S10 towards the galactic poles to about 250 S10 in the brightest parts
// of the Milky Way (Roach & Gordon 1973, "The Light of the Night Sky", as summarised by Cinzano,
// lightpollution.it/cinzano/libro, on the visibility of the Milky Way).
inline constexpr double kPoleS10 = 20.0;
inline constexpr double kBrightestS10 = 250.0;

class MilkyWayMap {
 public:
  // From an 8-bit RGB(A) PNG equirectangular in J2000. Throws std::runtime_error naming the file
  // when it cannot be read, std::invalid_argument when it is not 2:1.
  explicit MilkyWayMap(const std::string& pngPath);

  int width() const { return width_; }
  int height() const { return height_; }
  // Linear Rec.709, S10 per channel, row 0 at the top (for the GL texture).
  const std::vector<glm::vec3>& texels() const { return texels_; }

  // Bilinear sample (GL_LINEAR, GL_REPEAT in u, clamp in v), S10 per channel, at a texture
  // coordinate of physics/night/milky_way.glsl.
  glm::dvec3 sampleS10(const glm::dvec2& uv) const;
  // The same for a J2000 unit vector.
  glm::dvec3 s10(const glm::dvec3& directionJ2000) const;

  // Calibration figures (for the docs and tests): the mean luminance over |b| >= 60 deg and the
  // luminance percentile the brightest anchor was put on, S10.
  double meanPoleS10() const { return meanPole_; }
  double brightS10() const { return bright_; }

  // The shipped map, milkyway.png in skyig's data directory (ephemeris/data_files.h); loaded
  // once per process (~0.5 s) and shared. Throws ephemeris::DataFileError when it is missing.
  static std::shared_ptr<const MilkyWayMap> standard();
  static std::string standardPath();

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<glm::vec3> texels_;
  double meanPole_ = 0.0;
  double bright_ = 0.0;
};

}  // namespace skyig::sky::night
