#pragma once
// A 64-bit FNV-1a hash over every parameter that shapes the precomputed tables (medium,
// wavelengths, table sizes, scattering orders) and the physics revision, so a cache file made
// with any other parameter, or by older physics, is never mistaken for a match.
#include <cstdint>
#include <string>

#include "physics/atmosphere/model.h"

namespace skyig::atmosphere {

// Bump when the GLSL physics or the precomputation changes the tables it produces.
// 2: transmittanceAlongRay splits a dipping ray at its lowest point (the sky's horizon texel in
//    haze was computed from a ratio of two underflowing transmittances).
// 3: the transmittance table holds the optical depth (no underflow in fog), and the orders
//    after the last are summed as a geometric series (PrecomputeOptions::ordersTail).
inline constexpr std::uint32_t kPhysicsRevision = 3;

class Fnv1a64 {
 public:
  // FNV-1a, 64 bit (Fowler, Noll, Vo; offset basis and prime from the IETF draft).
  void bytes(const void* data, std::size_t size);
  void f64(double v);  // hashes the IEEE-754 bit pattern (+0 and -0 differ; NaN is rejected)
  void i64(std::int64_t v);
  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 14695981039346656037ull;
};

std::uint64_t parameterHash(const ModelConfig& config);
std::string hexHash(std::uint64_t hash);

}  // namespace skyig::atmosphere
