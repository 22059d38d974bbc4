// SPDX-License-Identifier: Apache-2.0
// Distance from a point to the nearest of a set of triangles, equal to the
// smallest point_triangle_distance over all of them (what a scan gives),
// without the scan: a cavity's depth asks it for every cell, and on a large
// assembly one region of empty space has tens of thousands of mouth
// triangles. The triangles are bucketed by centroid in a PointGrid; a
// query looks in a cube of half-side h about the point, doubling h until
// the nearest triangle found is nearer than any triangle whose centroid
// lies beyond the cube can be (farther than h less the largest
// centroid-to-corner distance), as alpha::NearestBall does for spheres.
// The margins (1e-9) are far above the distances' rounding errors.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "alpha/point_grid.hpp"
#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"
#include "cavity_space.hpp"

namespace molecule {

class NearestTriangle {
public:
  // `triangles`: ids in s; borrowed.
  NearestTriangle(const alpha::Triangulation& t, const alpha::Simplices& s, std::span<const alpha::Index> triangles)
      : t_(t), s_(s), triangles_(triangles), grid_(4) {
    for (alpha::Index k = 0; k < triangles.size(); ++k) {
      const auto& v = s.triangle(triangles[k]);
      const alpha::Vec3 c = centroid(v);
      for (const alpha::Index i : v) reach_ = std::max(reach_, norm(t.point(i) - c));
      grid_.add(c, k);
    }
    grid_.finish();
  }

  bool empty() const { return triangles_.empty(); }

  // Whether some triangle is within d of x (distance <= d). `hint`: the
  // triangle tried first, and the one found (kNone: none yet); the queries
  // of a cavity's neighbouring cells mostly find the same one, where a
  // search of a deep cavity's cube visits thousands.
  bool within(const alpha::Vec3& x, double d, alpha::Index& hint) const {
    if (hint != alpha::kNone && distance(x, hint) <= d) return true;
    return grid_.any(x, (d + reach_) * (1 + 1e-9) + 1e-9, [&](alpha::Index k) {
      if (distance(x, k) > d) return false;
      hint = k;
      return true;
    });
  }

  // The smallest distance from x to a triangle (infinite if there are none).
  // `beyond`: where the search starts, a distance it likely exceeds (a
  // deep cavity's cell is far from every mouth: a search from 0 would visit
  // the same triangles several times over).
  double distance(const alpha::Vec3& x, double beyond = 0) const {
    double d = std::numeric_limits<double>::infinity();
    if (triangles_.empty()) return d;
    for (double h = beyond + 2 * reach_ + 4;; h *= 2) {
      grid_.visit(x, h, [&](alpha::Index k) { d = std::min(d, distance(x, k)); });
      if (d < (h - reach_) * (1 - 1e-9) - 1e-9 || grid_.covers_all(x, h)) return d;
    }
  }

private:
  const alpha::Triangulation& t_;
  const alpha::Simplices& s_;
  std::span<const alpha::Index> triangles_;
  alpha::PointGrid grid_;
  double reach_ = 0;  // the largest distance from a triangle's centroid to its corners

  template <class V>
  alpha::Vec3 centroid(const V& v) const {
    const alpha::Vec3 sum = t_.point(v[0]) + t_.point(v[1]) + t_.point(v[2]);
    return (1.0 / 3) * sum;
  }
  double distance(const alpha::Vec3& x, alpha::Index k) const {
    const auto& v = s_.triangle(triangles_[k]);
    return point_triangle_distance(x, t_.point(v[0]), t_.point(v[1]), t_.point(v[2]));
  }
};

}  // namespace molecule
