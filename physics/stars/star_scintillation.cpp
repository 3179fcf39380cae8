#include "physics/stars/star_scintillation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace skyig::sky::night {

namespace {

// A well-mixed hash (splitmix64 finaliser) of the star and a salt, to [0, 1).
double unitHash(std::uint64_t id, std::uint64_t salt) {
  std::uint64_t z = id * 0x9E3779B97F4A7C15ull + salt;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

}  // namespace

double scintillationAmplitude(double airmass) {
  return std::min(kScintillationMax, kScintillationZenith * std::pow(std::max(airmass, 1.0), 1.75));
}

double scintillationFactor(int starId, double timeS, double airmass) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const auto id = static_cast<std::uint64_t>(static_cast<std::int64_t>(starId));
  const double f1 = 0.7 + 2.3 * unitHash(id, 1), f2 = 0.7 + 2.3 * unitHash(id, 2);
  const double p1 = kTwoPi * unitHash(id, 3), p2 = kTwoPi * unitHash(id, 4);
  // Weights 0.6 + 0.4 = 1: the signal stays within [-1, 1].
  const double signal = 0.6 * std::sin(kTwoPi * f1 * timeS + p1) + 0.4 * std::sin(kTwoPi * f2 * timeS + p2);
  return 1.0 + scintillationAmplitude(airmass) * signal;
}

double airmassKastenYoung(double altitudeRad) {
  const double h = std::max(altitudeRad, 0.0) * 180.0 / std::numbers::pi;
  return 1.0 / (std::sin(std::max(altitudeRad, 0.0)) + 0.50572 * std::pow(h + 6.07995, -1.6364));
}

}  // namespace skyig::sky::night
