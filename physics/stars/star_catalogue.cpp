#include "physics/stars/star_catalogue.h"

#include "ephemeris/time_scales.h"
#include "physics/stars/star_colour.h"
#include "physics/stars/star_photometry.h"

namespace skyig::sky::night {

StarCatalogue::StarCatalogue(const std::vector<ephemeris::Star>& stars, const ephemeris::UtcTime& epoch) {
  const double jdTt = ephemeris::timeScales(epoch).jdTt;
  stars_.reserve(stars.size());
  for (const ephemeris::Star& s : stars) {
    const ephemeris::Vec3 u = ephemeris::starDirectionAt(s, jdTt);
    stars_.push_back({glm::dvec3(u.x, u.y, u.z), illuminanceFromVMagnitude(s.vmag), starRec709FromBv(s.bMinusV), s.hr,
                      starTemperatureFromBv(s.bMinusV)});
  }
}

std::shared_ptr<const StarCatalogue> loadStarCatalogue(const std::string& path, const ephemeris::UtcTime& epoch) {
  return std::make_shared<const StarCatalogue>(ephemeris::loadStarCatalogue(path), epoch);
}

}  // namespace skyig::sky::night
