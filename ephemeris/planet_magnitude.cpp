#include "ephemeris/planet_magnitude.h"

#include <cmath>

namespace skyig::ephemeris {

double planetMagnitude(Planet planet, double rAu, double deltaAu, double phaseAngleRad,
                       double saturnRingTiltRad) {
  const double a = phaseAngleRad * 180.0 / 3.14159265358979323846;  // degrees
  const double distance = 5.0 * std::log10(rAu * deltaAu);
  switch (planet) {
    case Planet::Mercury:  // eq. 2
      return distance - 0.613 +
             a * (6.3280e-02 + a * (-1.6336e-03 + a * (3.3644e-05 + a * (-3.4265e-07 + a * (1.6893e-09 - 3.0334e-12 * a)))));
    case Planet::Venus:  // eq. 3 and 4
      if (a < 163.7) return distance - 4.384 + a * (-1.044e-03 + a * (3.687e-04 + a * (-2.814e-06 + 8.938e-09 * a)));
      return distance + 236.05828 + a * (-2.81914 + 8.39034e-03 * a);
    case Planet::Mars:  // eq. 5 and 6
      if (a <= 50.0) return distance - 1.601 + a * (2.267e-02 - 1.302e-04 * a);
      return distance - 0.367 + a * (-0.02573 + 3.445e-04 * a);
    case Planet::Jupiter:  // eq. 7 (phase angles seen from the earth stay below 12 degrees)
      return distance - 9.395 + a * (-3.7e-04 + 6.16e-04 * a);
    case Planet::Saturn: {  // eq. 10, globe and rings
      const double sb = std::sin(std::fabs(saturnRingTiltRad));
      return distance - 8.914 - 1.825 * sb + 0.026 * a - 0.378 * sb * std::exp(-2.25 * a);
    }
  }
  return 0.0;
}

}  // namespace skyig::ephemeris
