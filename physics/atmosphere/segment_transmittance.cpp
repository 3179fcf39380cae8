#include "physics/atmosphere/segment_transmittance.h"

#include <algorithm>
#include <cmath>

namespace skyig::atmosphere {

double luminanceTransmittance(const AtmosphereModel& model, double r, double mu, double d) {
  const Spectrum solar = model.solarRadiance();
  const double solarY = model.converter().luminance(solar);
  const auto weighed = [&](const Spectrum& t) {
    Spectrum s(solar.size());
    for (std::size_t i = 0; i < solar.size(); ++i) s[i] = solar[i] * t.at(i);
    return solarY > 0.0 ? model.converter().luminance(s) / solarY : 0.0;
  };
  const double rP = std::sqrt(std::max(r * r + d * d + 2.0 * r * d * mu, 0.0));
  const double muP = rP > 0.0 ? std::clamp((r * mu + d) / rP, -1.0, 1.0) : 1.0;
  const bool up = mu >= 0.0;
  const double near = weighed(up ? model.transmittanceToTop(r, mu) : model.transmittanceToTop(rP, -muP));
  const double far = weighed(up ? model.transmittanceToTop(rP, muP) : model.transmittanceToTop(r, -mu));
  return far > 0.0 ? std::clamp(near / far, 0.0, 1.0) : 0.0;
}

}  // namespace skyig::atmosphere
