#include "physics/night/zodiacal_light.h"

#include "physics/spectrum/spectral_data.h"
#include "physics/spectrum/spectrum.h"
#include "physics/night/diffuse_physics.h"

#include <algorithm>
#include <cmath>

namespace skyig::sky::night {

namespace {

// Leinert et al. (1998) table 17: zodiacal light at 500 nm, 1e-8 W m^-2 sr^-1 um^-1; rows
// lambda - lambda_sun = 0, 5, ..., 45, 60, 75, ..., 180 deg; columns beta = 0, 5, ..., 30, 45,
// 60, 75, 90 deg. 0 marks the cells the table leaves empty (near the sun).
constexpr float kTable17[kZodiacalRows][kZodiacalColumns] = {
    {0, 0, 0, 3140, 1610, 985, 640, 275, 150, 100, 77},
    {0, 0, 0, 2940, 1540, 945, 625, 271, 150, 100, 77},
    {0, 0, 4740, 2470, 1370, 865, 590, 264, 148, 100, 77},
    {11500, 6780, 3440, 1860, 1110, 755, 525, 251, 146, 100, 77},
    {6400, 4480, 2410, 1410, 910, 635, 454, 237, 141, 99, 77},
    {3840, 2830, 1730, 1100, 749, 545, 410, 223, 136, 97, 77},
    {2480, 1870, 1220, 845, 615, 467, 365, 207, 131, 95, 77},
    {1650, 1270, 910, 680, 510, 397, 320, 193, 125, 93, 77},
    {1180, 940, 700, 530, 416, 338, 282, 179, 120, 92, 77},
    {910, 730, 555, 442, 356, 292, 250, 166, 116, 90, 77},
    {505, 442, 352, 292, 243, 209, 183, 134, 104, 86, 77},
    {338, 317, 269, 227, 196, 172, 151, 116, 93, 82, 77},
    {259, 251, 225, 193, 166, 147, 132, 104, 86, 79, 77},
    {212, 210, 197, 170, 150, 133, 119, 96, 82, 77, 77},
    {188, 186, 177, 154, 138, 125, 113, 90, 77, 74, 77},
    {179, 178, 166, 147, 134, 122, 110, 90, 77, 73, 77},
    {179, 178, 165, 148, 137, 127, 116, 96, 79, 72, 77},
    {196, 192, 179, 165, 151, 141, 131, 104, 82, 72, 77},
    {230, 212, 195, 178, 163, 148, 134, 105, 83, 72, 77},
};

std::array<float, kZodiacalRows * kZodiacalColumns> makeTable() {
  std::array<float, kZodiacalRows * kZodiacalColumns> t{};
  for (int r = 0; r < kZodiacalRows; ++r) {
    int firstDefined = 0;
    while (kTable17[r][firstDefined] == 0.0f) ++firstDefined;
    for (int c = 0; c < kZodiacalColumns; ++c) {
      const float v = kTable17[r][std::max(c, firstDefined)];
      t[static_cast<std::size_t>(r * kZodiacalColumns + c)] = static_cast<float>(shader::leinertToS10(v));
    }
  }
  return t;
}

}  // namespace

const std::array<float, kZodiacalRows * kZodiacalColumns>& zodiacalTableS10() {
  static const auto table = makeTable();
  return table;
}

double zodiacalS10(double helioLongitudeDeg, double eclipticLatitudeDeg) {
  const glm::dvec2 index = shader::zodiacalTableIndex(glm::dvec2(helioLongitudeDeg, eclipticLatitudeDeg));
  const int r0 = std::min(static_cast<int>(index.x), kZodiacalRows - 2);
  const int c0 = std::min(static_cast<int>(index.y), kZodiacalColumns - 2);
  const double ar = index.x - r0, ac = index.y - c0;
  const auto& t = zodiacalTableS10();
  auto at = [&](int r, int c) { return static_cast<double>(t[static_cast<std::size_t>(r * kZodiacalColumns + c)]); };
  return (1.0 - ar) * ((1.0 - ac) * at(r0, c0) + ac * at(r0, c0 + 1)) + ar * ((1.0 - ac) * at(r0 + 1, c0) + ac * at(r0 + 1, c0 + 1));
}

const glm::dvec3& sunlightRec709() {
  static const glm::dvec3 colour = [] {
    glm::dvec3 xyz(0.0);
    for (double w = 380.0; w <= 780.0; w += 1.0) xyz += atmosphere::solarIrradiance(w) * atmosphere::cie1931ColourMatching(w);
    const glm::dvec3 rgb = atmosphere::xyzToRec709(xyz);
    return rgb / xyz.y;
  }();
  return colour;
}

glm::dvec3 zodiacalRadiance(const glm::dvec3& viewJ2000, const glm::dvec3& sunJ2000) {
  const glm::dvec2 lonLat = shader::helioEclipticCoordinates(viewJ2000, sunJ2000);
  return shader::s10ToCdM2(zodiacalS10(lonLat.x, lonLat.y)) * sunlightRec709();
}

}  // namespace skyig::sky::night
