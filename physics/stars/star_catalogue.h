#pragma once
// The bright-star catalogue prepared once per run for the renderer: each star's J2000 direction
// with its proper motion applied at the run's epoch (starDirectionAt moves a star by at most
// 10" a year: once a run is exact enough for a flight), its illuminance above the atmosphere
// and its colour. Stars closer than the eye resolves (1 arcmin) are one source, their light
// summed (star_catalogue.cpp). Brightest first. Immutable, shared by every SkyState through
// SkyConditions::starCatalogue.
#include "ephemeris/bsc5.h"
#include "ephemeris/time.h"

#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

namespace skyig::sky::night {

struct CatalogueStar {
  glm::dvec3 directionJ2000{0.0, 0.0, 1.0};  // unit vector, proper motion applied
  double illuminanceLux = 0.0;               // above the atmosphere, from V
  glm::dvec3 rec709PerLux{1.0};              // colour, luminance 1
  int hr = 0;                                // Harvard Revised number (the scintillation seed)
  double temperatureK = 5800.0;              // the eq. 12 temperature of its colour (star_colour.h)
};

class StarCatalogue {
 public:
  // Throws std::invalid_argument for an epoch outside the ephemeris' 1900-2100.
  StarCatalogue(const std::vector<ephemeris::Star>& stars, const ephemeris::UtcTime& epoch);
  const std::vector<CatalogueStar>& stars() const { return stars_; }

 private:
  std::vector<CatalogueStar> stars_;
};

// Loads the CSV (ephemeris::loadStarCatalogue; throws std::runtime_error naming the file) and
// prepares it for `epoch`.
std::shared_ptr<const StarCatalogue> loadStarCatalogue(const std::string& path, const ephemeris::UtcTime& epoch);

}  // namespace skyig::sky::night
