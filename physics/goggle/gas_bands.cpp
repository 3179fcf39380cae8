#include "physics/goggle/gas_bands.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skyig::sky::nvis {

double relativeAirMass(double elevationDeg) {
  const double e = std::clamp(elevationDeg, 0.0, 90.0);
  return 1.0 / (std::sin(e * std::numbers::pi / 180.0) + 0.50572 * std::pow(e + 6.07995, -1.6364));
}

double gasTransmittance(double wavelengthNm, double elevationRad, double altitudeM) {
  for (const GasBand& b : kGasBands) {
    if (std::abs(b.wavelengthNm - wavelengthNm) > 0.5) continue;
    const double m = relativeAirMass(elevationRad * 180.0 / std::numbers::pi);
    const double h = std::max(altitudeM, 0.0);
    return std::exp(-m * (b.oxygenDepth * std::exp(-h / kOxygenScaleHeightM) + b.waterDepth * std::exp(-h / kWaterScaleHeightM)));
  }
  return 1.0;
}

}  // namespace skyig::sky::nvis
