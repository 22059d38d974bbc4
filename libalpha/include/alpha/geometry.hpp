// SPDX-License-Identifier: Apache-2.0
// Basic value types shared by the whole library.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

namespace alpha {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

// Floating-point vector arithmetic (measures, meshes; never predicates).
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double tetrahedron_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return std::fabs(dot(b - a, cross(c - a, d - a))) / 6;
}
inline double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) { return norm(cross(b - a, c - a)) / 2; }
// Solid angle of tetrahedron (a, b, c, d) at a (Van Oosterom & Strackee).
inline double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 x = b - a, y = c - a, z = d - a;
  const double lx = norm(x), ly = norm(y), lz = norm(z);
  const double num = std::fabs(dot(x, cross(y, z)));
  const double den = lx * ly * lz + dot(x, y) * lz + dot(x, z) * ly + dot(y, z) * lx;
  return 2 * std::atan2(num, den);
}

// Indices of points, vertices, cells, edges and triangles.
using Index = std::uint32_t;
inline constexpr Index kNone = std::numeric_limits<Index>::max();
// The vertex at infinity: every hull facet is joined to it by one cell.
inline constexpr Index kInfinite = kNone - 1;

}  // namespace alpha
