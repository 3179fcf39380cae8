#pragma once
// C++ stand-ins for GLSL's sampler2D / sampler3D and texture(), so the atmosphere's GLSL can
// read tables on the CPU in double precision (the tests' reference path and skyig's CPU-side
// evaluation). Filtering matches GL_LINEAR with GL_CLAMP_TO_EDGE: texel centres at
// (i + 0.5) / size, coordinates outside [0, 1] clamp to the edge texels. Each texel holds a
// vec4, one value per wavelength of a group of four. Included by physics/atmosphere/atmosphere_physics.h.
#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::shader::cpu_texture {

struct sampler2D {
  int width = 0;
  int height = 0;
  std::vector<glm::dvec4> texels;  // x fastest

  sampler2D() = default;
  sampler2D(int w, int h) : width(w), height(h), texels(checkedCount(w, h, 1)) {}

  glm::dvec4& at(int x, int y) { return texels[index(x, y)]; }
  const glm::dvec4& at(int x, int y) const { return texels[index(x, y)]; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }

  static std::size_t checkedCount(int w, int h, int d) {
    if (w <= 0 || h <= 0 || d <= 0) {
      throw std::invalid_argument("texture size " + std::to_string(w) + "x" + std::to_string(h) +
                                  "x" + std::to_string(d) + " must be positive");
    }
    return static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
           static_cast<std::size_t>(d);
  }
};

struct sampler3D {
  int width = 0;
  int height = 0;
  int depth = 0;
  std::vector<glm::dvec4> texels;  // x fastest, then y, then z

  sampler3D() = default;
  sampler3D(int w, int h, int d)
      : width(w), height(h), depth(d), texels(sampler2D::checkedCount(w, h, d)) {}

  glm::dvec4& at(int x, int y, int z) { return texels[index(x, y, z)]; }
  const glm::dvec4& at(int x, int y, int z) const { return texels[index(x, y, z)]; }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(height) +
            static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
};

// Linear filtering along one axis: the two texels around u and the weight of the second.
struct LinearTap {
  int i0;
  int i1;
  double f;
};

inline LinearTap linearTap(double u, int size) {
  double x = u * static_cast<double>(size) - 0.5;
  if (!(x > 0.0)) return {0, 0, 0.0};  // also catches NaN: the edge texel, never UB
  double last = static_cast<double>(size - 1);
  if (x >= last) return {size - 1, size - 1, 0.0};
  double fl = std::floor(x);
  int i = static_cast<int>(fl);
  return {i, i + 1, x - fl};
}

inline glm::dvec4 texture(const sampler2D& t, const glm::dvec2& uv) {
  LinearTap tx = linearTap(uv.x, t.width);
  LinearTap ty = linearTap(uv.y, t.height);
  glm::dvec4 a = t.at(tx.i0, ty.i0) * (1.0 - tx.f) + t.at(tx.i1, ty.i0) * tx.f;
  glm::dvec4 b = t.at(tx.i0, ty.i1) * (1.0 - tx.f) + t.at(tx.i1, ty.i1) * tx.f;
  return a * (1.0 - ty.f) + b * ty.f;
}

inline glm::dvec4 texture(const sampler3D& t, const glm::dvec3& uvw) {
  // The hot loop of the CPU precomputation: index arithmetic once, then eight loads.
  const LinearTap tx = linearTap(uvw.x, t.width);
  const LinearTap ty = linearTap(uvw.y, t.height);
  const LinearTap tz = linearTap(uvw.z, t.depth);
  const std::size_t w = static_cast<std::size_t>(t.width);
  const std::size_t plane = w * static_cast<std::size_t>(t.height);
  const glm::dvec4* z0 = t.texels.data() + plane * static_cast<std::size_t>(tz.i0);
  const glm::dvec4* z1 = t.texels.data() + plane * static_cast<std::size_t>(tz.i1);
  const std::size_t y0 = w * static_cast<std::size_t>(ty.i0);
  const std::size_t y1 = w * static_cast<std::size_t>(ty.i1);
  const auto x0 = static_cast<std::size_t>(tx.i0);
  const auto x1 = static_cast<std::size_t>(tx.i1);
  const double fx = tx.f;
  const double fy = ty.f;
  const double fz = tz.f;
  const glm::dvec4 a0 = z0[y0 + x0] + (z0[y0 + x1] - z0[y0 + x0]) * fx;
  const glm::dvec4 b0 = z0[y1 + x0] + (z0[y1 + x1] - z0[y1 + x0]) * fx;
  const glm::dvec4 a1 = z1[y0 + x0] + (z1[y0 + x1] - z1[y0 + x0]) * fx;
  const glm::dvec4 b1 = z1[y1 + x0] + (z1[y1 + x1] - z1[y1 + x0]) * fx;
  const glm::dvec4 c0 = a0 + (b0 - a0) * fy;
  const glm::dvec4 c1 = a1 + (b1 - a1) * fy;
  return c0 + (c1 - c0) * fz;
}

}  // namespace skyig::shader::cpu_texture
