#pragma once
// The units every part of skyig converts with, defined once: a degree in radians (angles are
// degrees at every interface and radians inside, docs/design.md) and a kilometre in metres
// (the host says metres, the atmosphere's visibility is in kilometres). Plain C++ with no
// dependency, so the ephemeris and the protocol may include it too.
#include <numbers>

namespace skyig {

inline constexpr double kDeg = std::numbers::pi / 180.0;       // radians per degree
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;  // degrees per radian
inline constexpr double kMetresPerKm = 1000.0;

inline constexpr double kmFromMetres(double metres) { return metres / kMetresPerKm; }
inline constexpr double metresFromKm(double km) { return km * kMetresPerKm; }

}  // namespace skyig
