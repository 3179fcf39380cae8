#include "physics/analytic/cie_sky_types.h"

#include <stdexcept>
#include <string>

namespace skyig::sky {

// Gradation groups I-VI (a, b) and indicatrix groups 1-6 (c, d, e) as tabulated in the
// standard (CIE S 011/E:2003 = ISO 15469:2004); cross-checked with Darula & Kittler 2002, "CIE
// general sky standard defining luminance distributions" (type 12 equals the classic CIE clear
// sky of Perez and Preetham).
const std::array<CieSkyType, 15>& cieSkyTypes() {
  static const std::array<CieSkyType, 15> kTypes = {{
      {1, 4.0, -0.70, 0, -1.0, 0.00, false, true, "standard overcast, steep gradation, azimuthal uniformity"},
      {2, 4.0, -0.70, 2, -1.5, 0.15, false, true, "overcast, steep gradation, slight brightening towards the sun"},
      {3, 1.1, -0.80, 0, -1.0, 0.00, false, true, "overcast, moderately graded, azimuthal uniformity"},
      {4, 1.1, -0.80, 2, -1.5, 0.15, false, true, "overcast, moderately graded, slight brightening towards the sun"},
      {5, 0.0, -1.00, 0, -1.0, 0.00, false, true, "uniform luminance"},
      {6, 0.0, -1.00, 2, -1.5, 0.15, false, true, "partly cloudy, no gradation, slight brightening towards the sun"},
      {7, 0.0, -1.00, 5, -2.5, 0.30, true, false, "partly cloudy, no gradation, brighter circumsolar region"},
      {8, 0.0, -1.00, 10, -3.0, 0.45, true, false, "partly cloudy, no gradation, distinct solar corona"},
      {9, -1.0, -0.55, 2, -1.5, 0.15, false, false, "partly cloudy, obscured sun"},
      {10, -1.0, -0.55, 5, -2.5, 0.30, true, false, "partly cloudy, brighter circumsolar region"},
      {11, -1.0, -0.55, 10, -3.0, 0.45, true, false, "white-blue sky with distinct solar corona"},
      {12, -1.0, -0.32, 10, -3.0, 0.45, true, false, "standard clear sky, low luminance turbidity"},
      {13, -1.0, -0.32, 16, -3.0, 0.30, true, false, "standard clear sky, polluted atmosphere"},
      {14, -1.0, -0.15, 16, -3.0, 0.30, true, false, "cloudless turbid sky with broad solar corona"},
      {15, -1.0, -0.15, 24, -2.8, 0.15, true, false, "white-blue turbid sky with broad solar corona"},
  }};
  return kTypes;
}

const CieSkyType& cieSkyType(int number) {
  if (number < 1 || number > 15)
    throw std::out_of_range("CIE sky type " + std::to_string(number) + " is outside 1..15");
  return cieSkyTypes()[static_cast<size_t>(number - 1)];
}

}  // namespace skyig::sky
