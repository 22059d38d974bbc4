// SPDX-License-Identifier: Apache-2.0
// The hood of a point: the pieces of the eroded union's boundary (balls'
// spheres, circles of edges of K, boundary vertices) that its nearest-point
// tests can find near it, gathered by ErodedUnion::Integrator
// (eroded_union_integrator.hpp) and narrowed to a part of it.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "alpha/eroded_union.hpp"
#include "union/eroded_union_geometry.hpp"

namespace alpha {
namespace eroded_union_detail {

// A point of F found nearer to x than t: on a sphere (the nearest point
// of a hood ball), a circle (of a hood circle) or a vertex.
struct Nearer {
  enum Kind { kNone, kBall, kCircle, kVertex } kind = kNone;
  std::size_t which = 0;  // in the hood's list
};

inline constexpr std::size_t kNoCover = std::size_t(-1);

}  // namespace eroded_union_detail

using namespace eroded_union_detail;

// What can be within reach of a point (2r of a piece): balls whose sphere
// comes near, the circles of edges of K between them, boundary vertices.
struct ErodedUnion::Nearby::Hood {
  struct Ball {
    Vec3 c;
    double radius, radius_sq;
    Index id;
    mutable std::size_t cover = kNoCover;  // see on_boundary
  };
  std::vector<Ball> balls;  // by id
  std::vector<std::pair<Index, Circle>> circles;
  // Per circle: a ball (centre, radius) holding all its arcs' points,
  // clear()'s first test.
  std::vector<std::pair<Vec3, double>> arc_bounds;
  std::vector<std::size_t> vertices;
  std::vector<std::pair<Vec3, double>> buried;  // (centre, squared radius) of balls with no boundary
  mutable std::vector<std::pair<double, std::size_t>> holding;  // nearest()'s scratch
  // The last point clear() found nearer: the next tests (nearby points)
  // try it first.
  mutable Nearer last;
  // Every point clear() tests against it lies in a ball left out of it
  // (see keep_at_r).
  bool inside = false;
  // Empty, to take the part of h that narrow() or keep_at_r() keeps.
  void start_part_of(const Hood& h) {
    balls.clear();
    circles.clear();
    arc_bounds.clear();
    vertices.clear();
    last = {};
    inside = h.inside;
  }
};

namespace eroded_union_detail {

using Hood = ErodedUnion::Nearby::Hood;

// n, found in `part` (a part of h), as the index of the same piece in h;
// false if h does not hold it.
inline bool index_in(const Hood& h, const Hood& part, Nearer& n) {
  const auto find = [&](const auto& list, const auto& same) {
    for (std::size_t k = 0; k < list.size(); ++k)
      if (same(list[k])) {
        n.which = k;
        return true;
      }
    return false;
  };
  switch (n.kind) {
    case Nearer::kBall:
      return find(h.balls, [&](const Hood::Ball& b) { return b.id == part.balls[n.which].id; });
    case Nearer::kCircle:
      return find(h.circles, [&](const auto& c) { return c.first == part.circles[n.which].first; });
    case Nearer::kVertex:
      return find(h.vertices, [&](std::size_t v) { return v == part.vertices[n.which]; });
    case Nearer::kNone: break;
  }
  return true;
}

}  // namespace eroded_union_detail
}  // namespace alpha
