#pragma once
// The 15 CIE standard general skies (CIE S 011/E:2003 = ISO 15469:2004, table 1).
#include <array>
#include <string_view>

namespace skyig::sky {

struct CieSkyType {
  int number;      // 1..15
  double a, b, c, d, e;
  bool sunVisible;  // whether the solar disc shows through (types 7-8 and 10-15)
  bool overcast;    // types 1-6: absolute level from the overcast zenith luminance
  std::string_view description;
};

const std::array<CieSkyType, 15>& cieSkyTypes();

// Throws std::out_of_range for a number outside 1..15.
const CieSkyType& cieSkyType(int number);

}  // namespace skyig::sky
