// Basic value types shared by the whole library.
#pragma once
#include <cstdint>
#include <limits>

namespace alpha {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

// Indices of points, vertices, cells, edges and triangles.
using Index = std::uint32_t;
inline constexpr Index kNone = std::numeric_limits<Index>::max();
// The vertex at infinity: every hull facet is joined to it by one cell.
inline constexpr Index kInfinite = kNone - 1;

}  // namespace alpha
