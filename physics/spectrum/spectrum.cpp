#include "physics/spectrum/spectrum.h"

#include <sstream>
#include <stdexcept>

#include "physics/spectrum/spectral_data.h"

namespace skyig::atmosphere {

glm::dvec3 xyzToRec709(const glm::dvec3& c) {
  return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
          -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
          0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

namespace {

// Weight of sample i in the piecewise-linear reconstruction at wavelength w.
double hat(const std::vector<double>& s, std::size_t i, double w) {
  const std::size_t n = s.size();
  if (n == 1) return 1.0;
  if (w <= s.front()) return i == 0 ? 1.0 : 0.0;
  if (w >= s.back()) return i == n - 1 ? 1.0 : 0.0;
  if (i > 0 && w >= s[i - 1] && w <= s[i]) return (w - s[i - 1]) / (s[i] - s[i - 1]);
  if (i + 1 < n && w >= s[i] && w <= s[i + 1]) return (s[i + 1] - w) / (s[i + 1] - s[i]);
  return 0.0;
}

}  // namespace

SpectralConverter::SpectralConverter(std::vector<double> wavelengthsNm)
    : wavelengths_(std::move(wavelengthsNm)) {
  if (wavelengths_.empty()) throw std::invalid_argument("SpectralConverter: no wavelengths");
  for (std::size_t i = 0; i < wavelengths_.size(); ++i) {
    const double w = wavelengths_[i];
    if (!(w >= kSpectralDataMinNm && w <= kSpectralDataMaxNm) ||
        (i > 0 && !(w > wavelengths_[i - 1]))) {
      std::ostringstream msg;
      msg << "SpectralConverter: wavelength " << w << " nm (index " << i
          << ") must be in [360, 830] nm and larger than the previous one";
      throw std::invalid_argument(msg.str());
    }
  }
  // 1 nm midpoint rule over 360-830 nm; the tables interpolate linearly in between.
  weights_.assign(wavelengths_.size(), glm::dvec3(0.0));
  for (std::size_t i = 0; i < wavelengths_.size(); ++i) {
    const double sunI = solarIrradiance(wavelengths_[i]);
    for (double w = kSpectralDataMinNm + 0.5; w < kSpectralDataMaxNm; w += 1.0) {
      const double h = hat(wavelengths_, i, w);
      if (h == 0.0) continue;
      weights_[i] += cie1931ColourMatching(w) * (h * solarIrradiance(w) / sunI);
    }
    weights_[i] *= kMaxLuminousEfficacy;
  }
}

glm::dvec3 SpectralConverter::toXyz(const std::vector<double>& spectrum) const {
  if (spectrum.size() != wavelengths_.size()) {
    std::ostringstream msg;
    msg << "SpectralConverter: spectrum has " << spectrum.size() << " samples, expected "
        << wavelengths_.size();
    throw std::invalid_argument(msg.str());
  }
  glm::dvec3 xyz(0.0);
  for (std::size_t i = 0; i < spectrum.size(); ++i) xyz += weights_[i] * spectrum[i];
  return xyz;
}

double SpectralConverter::at(const std::vector<double>& spectrum, double wavelengthNm) const {
  if (spectrum.size() != wavelengths_.size()) {
    throw std::invalid_argument("SpectralConverter::at: spectrum size mismatch");
  }
  double v = 0.0;
  for (std::size_t i = 0; i < spectrum.size(); ++i) {
    v += hat(wavelengths_, i, wavelengthNm) * spectrum[i];
  }
  return v;
}

}  // namespace skyig::atmosphere
