#pragma once
// The Yale Bright Star Catalogue, 5th revised ed. (Hoffleit & Warren 1991, CDS V/50), as the
// CSV in ephemeris/data/bsc5.csv (provenance and credit in ephemeris/data/README.md).
#include <optional>
#include <string>
#include <vector>

#include "ephemeris/vec3.h"

namespace skyig::ephemeris {

struct Star {
  int hr = 0;                        // Harvard Revised number
  double raRad = 0.0, decRad = 0.0;  // J2000/FK5, epoch J2000
  double pmRaCosDecRadPerYear = 0.0; // proper motion in RA times cos(Dec)
  double pmDecRadPerYear = 0.0;
  double vmag = 0.0;                 // Johnson V
  std::optional<double> bMinusV;     // Johnson B-V (absent for 310 stars)
  std::string name;                  // Bayer/Flamsteed designation, may be empty
  Vec3 directionJ2000;               // unit vector at epoch J2000
};

// Reads the catalogue CSV (lines starting with '#' are comments, the first other line is the
// header). Throws std::runtime_error naming the file and line for a missing file, a wrong
// header, a malformed or out-of-range field. Returns the stars sorted by HR number.
std::vector<Star> loadStarCatalogue(const std::string& path);

// Unit vector of a star at TT Julian date jdTt with its proper motion applied (J2000 axes,
// linear space motion; radial velocity and parallax neglected: < 0.01 arcsec within 1900-2100 for
// all but a handful of nearby stars).
Vec3 starDirectionAt(const Star& star, double jdTt);

// The n brightest stars (smallest V), brightest first.
std::vector<Star> brightestStars(const std::vector<Star>& stars, std::size_t n);

}  // namespace skyig::ephemeris
