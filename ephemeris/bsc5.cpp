#include "ephemeris/bsc5.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace skyig::ephemeris {

namespace {
constexpr std::string_view kHeader =
    "HR,RA_J2000_deg,Dec_J2000_deg,pmRA_arcsec_per_yr,pmDec_arcsec_per_yr,Vmag,B_V,name,parallax_arcsec,radvel_km_s";

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw std::runtime_error(path + ":" + std::to_string(line) + ": " + what);
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  for (char ch : line) {
    if (ch == ',') {
      fields.push_back(field);
      field.clear();
    } else if (ch != '\r') {
      field.push_back(ch);
    }
  }
  fields.push_back(field);
  return fields;
}

double parseNumber(const std::string& path, int line, const std::string& column, const std::string& text,
                   double lo, double hi) {
  if (text.empty()) fail(path, line, "column " + column + " is empty");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v))
    fail(path, line, "column " + column + " value '" + text + "' is not a number");
  if (v < lo || v > hi)
    fail(path, line, "column " + column + " value " + text + " is outside [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "]");
  return v;
}
}  // namespace

std::vector<Star> loadStarCatalogue(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the star catalogue");
  std::vector<Star> stars;
  std::string text;
  int lineNo = 0;
  bool headerSeen = false;
  using skyig::kDeg;
  constexpr double kArcsec = kDeg / 3600.0;
  while (std::getline(in, text)) {
    ++lineNo;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.empty() || text[0] == '#') continue;
    if (!headerSeen) {
      if (text != kHeader) fail(path, lineNo, "unexpected header '" + text + "', expected '" + std::string(kHeader) + "'");
      headerSeen = true;
      continue;
    }
    const std::vector<std::string> f = splitCsv(text);
    if (f.size() != 10) fail(path, lineNo, "expected 10 comma-separated fields, found " + std::to_string(f.size()));
    Star s;
    s.hr = static_cast<int>(parseNumber(path, lineNo, "HR", f[0], 1, 9110));
    if (std::to_string(s.hr) != f[0]) fail(path, lineNo, "column HR value '" + f[0] + "' is not an integer");
    s.raRad = parseNumber(path, lineNo, "RA_J2000_deg", f[1], 0.0, 360.0) * kDeg;
    s.decRad = parseNumber(path, lineNo, "Dec_J2000_deg", f[2], -90.0, 90.0) * kDeg;
    s.pmRaCosDecRadPerYear = parseNumber(path, lineNo, "pmRA_arcsec_per_yr", f[3], -15.0, 15.0) * kArcsec;
    s.pmDecRadPerYear = parseNumber(path, lineNo, "pmDec_arcsec_per_yr", f[4], -15.0, 15.0) * kArcsec;
    s.vmag = parseNumber(path, lineNo, "Vmag", f[5], -2.0, 9.0);
    if (!f[6].empty()) s.bMinusV = parseNumber(path, lineNo, "B_V", f[6], -0.5, 6.0);
    s.name = f[7];
    s.directionJ2000 = {std::cos(s.decRad) * std::cos(s.raRad), std::cos(s.decRad) * std::sin(s.raRad),
                        std::sin(s.decRad)};
    stars.push_back(std::move(s));
  }
  if (!headerSeen) throw std::runtime_error(path + ": no header line and no stars: not a star catalogue");
  if (stars.empty()) throw std::runtime_error(path + ": the catalogue holds no stars");
  std::sort(stars.begin(), stars.end(), [](const Star& a, const Star& b) { return a.hr < b.hr; });
  for (std::size_t i = 1; i < stars.size(); ++i)
    if (stars[i].hr == stars[i - 1].hr)
      throw std::runtime_error(path + ": HR " + std::to_string(stars[i].hr) + " appears twice");
  return stars;
}

Vec3 starDirectionAt(const Star& star, double jdTt) {
  const double years = (jdTt - 2451545.0) / 365.25;
  const double sa = std::sin(star.raRad), ca = std::cos(star.raRad);
  const double sd = std::sin(star.decRad), cd = std::cos(star.decRad);
  const Vec3 east{-sa, ca, 0.0};              // direction of increasing RA
  const Vec3 north{-sd * ca, -sd * sa, cd};   // direction of increasing Dec
  return normalized(star.directionJ2000 + (years * star.pmRaCosDecRadPerYear) * east +
                    (years * star.pmDecRadPerYear) * north);
}

std::vector<Star> brightestStars(const std::vector<Star>& stars, std::size_t n) {
  std::vector<Star> sorted = stars;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Star& a, const Star& b) { return a.vmag < b.vmag; });
  if (sorted.size() > n) sorted.resize(n);
  return sorted;
}

}  // namespace skyig::ephemeris
