#pragma once
// Small 3-vector and row-major 3x3 matrix types for the ephemeris (no GLM: ephemeris depends on
// the standard library and GeographicLib only). Rotations follow the SOFA convention: rx(a)
// rotates the reference frame, not the vector, by +a about x.
#include <array>
#include <cmath>

namespace skyig::ephemeris {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) { return (1.0 / norm(a)) * a; }

// Angle between two directions, robust for tiny angles (atan2 of |a x b| and a.b).
inline double angleBetween(Vec3 a, Vec3 b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// Row-major 3x3 matrix: m[3 * row + column].
struct Mat3 {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

inline Vec3 operator*(const Mat3& a, Vec3 v) {
  return {a.m[0] * v.x + a.m[1] * v.y + a.m[2] * v.z, a.m[3] * v.x + a.m[4] * v.y + a.m[5] * v.z,
          a.m[6] * v.x + a.m[7] * v.y + a.m[8] * v.z};
}

inline Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.m[3 * i + j] = a.m[3 * i] * b.m[j] + a.m[3 * i + 1] * b.m[3 + j] + a.m[3 * i + 2] * b.m[6 + j];
  return r;
}

inline Mat3 transposed(const Mat3& a) {
  return {{a.m[0], a.m[3], a.m[6], a.m[1], a.m[4], a.m[7], a.m[2], a.m[5], a.m[8]}};
}

inline Mat3 rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {{1, 0, 0, 0, c, s, 0, -s, c}};
}
inline Mat3 rotY(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {{c, 0, -s, 0, 1, 0, s, 0, c}};
}
inline Mat3 rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {{c, s, 0, -s, c, 0, 0, 0, 1}};
}

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kArcsecToRad = kPi / 648000.0;
inline constexpr double kAuKm = 149597870.700;          // IAU 2012 B2
inline constexpr double kLightKmPerS = 299792.458;
inline constexpr double kLightTimeAuDays = kAuKm / kLightKmPerS / 86400.0;  // days per au

// Angle reduced to [0, 2 pi).
inline double wrapTwoPi(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

}  // namespace skyig::ephemeris
