#pragma once
// From radiance sampled at a few wavelengths to CIE XYZ, luminance (cd/m^2) and linear
// Rec.709. The sampled spectrum is taken as piecewise linear between samples (flat beyond the
// first and last), except for the sun's fine structure: the weights fold in the ASTM G-173
// spectrum relative to its sampled value, so a spectrum proportional to the sun's is
// converted exactly. X = 683 lm/W * int L(lambda) xbar(lambda) dlambda (CIE 015:2004).
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace skyig::atmosphere {

// Maximum luminous efficacy of photopic vision, lm/W (CIE; the SI definition of the candela).
inline constexpr double kMaxLuminousEfficacy = 683.0;

// XYZ -> linear Rec.709 / sRGB primaries, D65 white (IEC 61966-2-1), row-major as printed.
glm::dvec3 xyzToRec709(const glm::dvec3& xyz);

class SpectralConverter {
 public:
  // Wavelengths in nm, strictly increasing, inside [360, 830]; throws otherwise.
  explicit SpectralConverter(std::vector<double> wavelengthsNm);

  const std::vector<double>& wavelengths() const { return wavelengths_; }
  // Spectral radiance (W m^-2 sr^-1 nm^-1) or irradiance (W m^-2 nm^-1) at the wavelengths to
  // XYZ in cd/m^2 or lux; throws if the size differs.
  glm::dvec3 toXyz(const std::vector<double>& spectrum) const;
  double luminance(const std::vector<double>& spectrum) const { return toXyz(spectrum).y; }
  glm::dvec3 toRec709(const std::vector<double>& spectrum) const {
    return xyzToRec709(toXyz(spectrum));
  }
  // XYZ (cd/m^2) contributed by one unit of spectral radiance at sample i.
  const glm::dvec3& weight(std::size_t i) const { return weights_.at(i); }
  // Linear interpolation of the sampled spectrum at one wavelength (nm).
  double at(const std::vector<double>& spectrum, double wavelengthNm) const;

 private:
  std::vector<double> wavelengths_;
  std::vector<glm::dvec3> weights_;  // per sample: XYZ per unit spectral value
};

}  // namespace skyig::atmosphere
