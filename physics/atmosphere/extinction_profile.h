#pragma once
// Extinction of light from outside the atmosphere (moon, planets, stars, Milky Way, zodiacal
// light) on its way to an observer: the transmittance to space along every view elevation, from
// the same medium as the day sky (Bruneton & Neyret 2008, eq. 5), so the night objects are
// dimmed and reddened near the horizon exactly as the sun is. Computed by quadrature of the
// medium, with no precomputed tables, so it serves every sky model.
#include <glm/vec3.hpp>

#include <functional>
#include <vector>

#include "physics/atmosphere/medium.h"

namespace skyig::atmosphere {

class ExtinctionProfile {
 public:
  // Samples over the elevation, dense near the horizon: u = (1 + sign(e) sqrt(|e| / 90 deg)) / 2.
  static constexpr int kSamples = 512;

  // Observer `altitudeM` above the ground of `medium`. Costs ~10-40 ms (kSamples x 16
  // wavelengths of a 500-step quadrature): build once per altitude band, not per frame.
  // Throws std::invalid_argument for a bad medium or an altitude outside [−1 km, top).
  ExtinctionProfile(const Medium& medium, double altitudeM,
                    const std::vector<double>& wavelengthsNm = defaultWavelengths());

  double altitudeM() const { return altitudeM_; }
  const std::vector<double>& wavelengths() const { return wavelengths_; }

  // Spectral transmittance to space at an elevation (radians, airless; 0 where the ray meets
  // the ground), interpolated linearly between samples.
  std::vector<double> spectral(double elevationRad) const;
  // The same for a source with the sun's spectrum, as a factor on each linear Rec.709 channel:
  // a sunlike source of colour c is seen as c * rec709(e). Good to a few per cent for stars of
  // other colours too (the transmittance is smooth across each channel's band).
  glm::dvec3 rec709(double elevationRad) const;

  // The Rec.709 factors at the kSamples sample points, for a 1D texture (GL_LINEAR,
  // CLAMP_TO_EDGE): texel i holds u = (i + 0.5) / kSamples.
  const std::vector<glm::vec3>& rec709Table() const { return rec709Table_; }
  // Texture coordinate of an elevation, matching rec709Table().
  static double textureCoordinate(double elevationRad);

  // The profile seen through something grey besides the medium (a fog layer,
  // physics/weather/fog_layer.h): every sample times grey(elevation in radians), in [0, 1].
  ExtinctionProfile dimmedBy(const std::function<double(double)>& grey) const;

 private:
  double altitudeM_;
  std::vector<double> wavelengths_;
  std::vector<std::vector<double>> spectral_;  // [sample][wavelength]
  std::vector<glm::vec3> rec709Table_;
};

}  // namespace skyig::atmosphere
