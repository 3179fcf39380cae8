#include "physics/stars/star_catalogue.h"

#include "ephemeris/time_scales.h"
#include "physics/stars/star_colour.h"
#include "physics/stars/star_photometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace skyig::sky::night {

namespace {

// The eye resolves about one arcminute (Snellen's standard; Rayleigh's limit for a 2-3 mm night
// pupil is about as fine): a pair of catalogue stars closer than that is one point to the eye.
constexpr double kUnresolvedRad = 1.0 / 60.0 * 3.14159265358979323846 / 180.0;

// Each star absorbs the fainter ones within kUnresolvedRad, brightest first: their light adds,
// the colour is the light-weighted mean (each colour has luminance 1), the direction the
// light-weighted centroid; the brightest keeps its number (the scintillation seed) and its
// temperature. The display then ranks the pair by the light the eye gets from it, not each star
// by its own (two sources, each compressed, outranked brighter single stars: Alnitak's).
std::vector<CatalogueStar> mergeUnresolved(std::vector<CatalogueStar> stars) {
  std::sort(stars.begin(), stars.end(),
            [](const CatalogueStar& a, const CatalogueStar& b) { return a.directionJ2000.z < b.directionJ2000.z; });
  std::vector<std::size_t> brightest(stars.size());
  std::iota(brightest.begin(), brightest.end(), std::size_t{0});
  std::sort(brightest.begin(), brightest.end(),
            [&](std::size_t a, std::size_t b) { return stars[a].illuminanceLux > stars[b].illuminanceLux; });
  std::vector<bool> absorbed(stars.size(), false);
  const double cosLimit = std::cos(kUnresolvedRad);
  std::vector<CatalogueStar> out;
  out.reserve(stars.size());
  for (const std::size_t i : brightest) {
    if (absorbed[i]) continue;
    CatalogueStar merged = stars[i];
    glm::dvec3 centroid = stars[i].directionJ2000 * stars[i].illuminanceLux;
    glm::dvec3 colour = stars[i].rec709PerLux * stars[i].illuminanceLux;
    // Neighbours in z (sorted): |dz| <= the angle.
    const double z = stars[i].directionJ2000.z;
    auto lo = std::lower_bound(stars.begin(), stars.end(), z - kUnresolvedRad,
                               [](const CatalogueStar& a, double v) { return a.directionJ2000.z < v; });
    for (auto it = lo; it != stars.end() && it->directionJ2000.z <= z + kUnresolvedRad; ++it) {
      const std::size_t j = static_cast<std::size_t>(it - stars.begin());
      if (j == i || absorbed[j] || glm::dot(it->directionJ2000, stars[i].directionJ2000) < cosLimit) continue;
      if (it->illuminanceLux > stars[i].illuminanceLux) continue;  // it absorbs, not is absorbed
      absorbed[j] = true;
      merged.illuminanceLux += it->illuminanceLux;
      centroid += it->directionJ2000 * it->illuminanceLux;
      colour += it->rec709PerLux * it->illuminanceLux;
    }
    absorbed[i] = true;
    if (merged.illuminanceLux > stars[i].illuminanceLux) {
      merged.directionJ2000 = glm::normalize(centroid);
      merged.rec709PerLux = colour / merged.illuminanceLux;
    }
    out.push_back(merged);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const CatalogueStar& a, const CatalogueStar& b) { return a.illuminanceLux > b.illuminanceLux; });
  return out;
}

}  // namespace

StarCatalogue::StarCatalogue(const std::vector<ephemeris::Star>& stars, const ephemeris::UtcTime& epoch) {
  const double jdTt = ephemeris::timeScales(epoch).jdTt;
  std::vector<CatalogueStar> all;
  all.reserve(stars.size());
  for (const ephemeris::Star& s : stars) {
    const ephemeris::Vec3 u = ephemeris::starDirectionAt(s, jdTt);
    all.push_back({glm::dvec3(u.x, u.y, u.z), illuminanceFromVMagnitude(s.vmag), starRec709FromBv(s.bMinusV), s.hr,
                   starTemperatureFromBv(s.bMinusV)});
  }
  stars_ = mergeUnresolved(std::move(all));
}

std::shared_ptr<const StarCatalogue> loadStarCatalogue(const std::string& path, const ephemeris::UtcTime& epoch) {
  return std::make_shared<const StarCatalogue>(ephemeris::loadStarCatalogue(path), epoch);
}

}  // namespace skyig::sky::night
