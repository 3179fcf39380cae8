#include "physics/atmosphere/extinction_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/atmosphere/precompute/precompute.h"
#include "physics/spectrum/spectrum.h"

namespace skyig::atmosphere {

namespace {

constexpr double kHalfPi = kPi / 2.0;

// Inverse of textureCoordinate at the centre of sample i.
double sampleElevation(int i) {
  const double u = (i + 0.5) / ExtinctionProfile::kSamples;
  const double s = 2.0 * u - 1.0;  // sign(e) sqrt(|e| / 90 deg)
  return std::copysign(s * s * kHalfPi, s);
}

// The two samples around an elevation and the weight of the second.
struct Bracket {
  int i0, i1;
  double f;
};

Bracket bracket(double elevationRad) {
  const double x = ExtinctionProfile::textureCoordinate(elevationRad) * ExtinctionProfile::kSamples - 0.5;
  const int i0 = std::clamp(static_cast<int>(std::floor(x)), 0, ExtinctionProfile::kSamples - 1);
  return {i0, std::min(i0 + 1, ExtinctionProfile::kSamples - 1), std::clamp(x - i0, 0.0, 1.0)};
}

}  // namespace

double ExtinctionProfile::textureCoordinate(double elevationRad) {
  const double e = std::clamp(elevationRad, -kHalfPi, kHalfPi);
  return 0.5 * (1.0 + std::copysign(std::sqrt(std::abs(e) / kHalfPi), e));
}

ExtinctionProfile::ExtinctionProfile(const Medium& medium, double altitudeM,
                                     const std::vector<double>& wavelengthsNm)
    : altitudeM_(altitudeM), wavelengths_(wavelengthsNm) {
  validate(medium);
  const double top = medium.topRadiusM - medium.bottomRadiusM;
  if (!std::isfinite(altitudeM) || altitudeM < -1000.0 || altitudeM >= top)
    throw std::invalid_argument("extinction profile: altitude " + std::to_string(altitudeM) +
                                " m is outside [-1000, " + std::to_string(top) + ") m");
  const SpectralConverter converter(wavelengthsNm);  // validates the wavelengths
  // The optical depth is the shader's (eq. 5 by the trapezoid rule); a camera below the ground
  // is taken at the ground, where the medium's profiles are defined.
  const double r = medium.bottomRadiusM + std::max(altitudeM, 0.0);
  spectral_.assign(kSamples, std::vector<double>(wavelengths_.size(), 0.0));
  for (std::size_t g = 0; g * 4 < wavelengths_.size(); ++g) {
    std::array<double, 4> w{};
    for (std::size_t i = 0; i < 4; ++i) w[i] = wavelengths_[std::min(g * 4 + i, wavelengths_.size() - 1)];
    const AtmosphereParameters a = makeParameters(medium, w, TableSizes{});
    for (int s = 0; s < kSamples; ++s) {
      const double mu = std::sin(sampleElevation(s));
      if (shader::rayIntersectsGround(a, r, mu)) continue;  // stays 0
      const glm::dvec4 t = glm::exp(-shader::opticalDepthToTopAtmosphereBoundary(a, r, mu));
      for (std::size_t i = 0; i < 4 && g * 4 + i < wavelengths_.size(); ++i) spectral_[s][g * 4 + i] = t[static_cast<int>(i)];
    }
  }
  // Weighted by the sun's spectrum: the converter's weights fold in ASTM G-173, so a spectrum
  // of ones is the sun's colour.
  const std::vector<double> ones(wavelengths_.size(), 1.0);
  const glm::dvec3 sun = converter.toRec709(ones);
  rec709Table_.resize(kSamples);
  for (int s = 0; s < kSamples; ++s) rec709Table_[s] = glm::vec3(converter.toRec709(spectral_[s]) / sun);
}

ExtinctionProfile ExtinctionProfile::dimmedBy(const std::function<double(double)>& grey) const {
  ExtinctionProfile out = *this;
  for (int s = 0; s < kSamples; ++s) {
    const double t = std::clamp(grey(sampleElevation(s)), 0.0, 1.0);
    for (double& v : out.spectral_[static_cast<std::size_t>(s)]) v *= t;
    out.rec709Table_[static_cast<std::size_t>(s)] *= static_cast<float>(t);
  }
  return out;
}

std::vector<double> ExtinctionProfile::spectral(double elevationRad) const {
  const auto [i0, i1, f] = bracket(elevationRad);
  std::vector<double> out(wavelengths_.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = spectral_[i0][k] * (1.0 - f) + spectral_[i1][k] * f;
  return out;
}

glm::dvec3 ExtinctionProfile::rec709(double elevationRad) const {
  const auto [i0, i1, f] = bracket(elevationRad);
  return glm::dvec3(rec709Table_[i0]) * (1.0 - f) + glm::dvec3(rec709Table_[i1]) * f;
}

}  // namespace skyig::atmosphere
