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
// A triangle whose centroid is further than d plus its own reach cannot be
// within d: only the others get the exact distance (on an assembly a
// query's cube holds hundreds of mouths, a few of them near).
// The margins (1e-9) are far above the distances' rounding errors.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "alpha/point_grid.hpp"
#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"
#include "cavities/cavity_space.hpp"

namespace molecule {

class NearestTriangle {
public:
  // `triangles`: ids in s; borrowed.
  NearestTriangle(const alpha::Triangulation& t, const alpha::Simplices& s, std::span<const alpha::Index> triangles)
      : t_(t), s_(s), triangles_(triangles), grid_(4) {
    for (alpha::Index k = 0; k < triangles.size(); ++k) {
      const auto& v = s.triangle(triangles[k]);
      const alpha::Vec3 c = centroid(v);
      double reach = 0;
      for (const alpha::Index i : v) reach = std::max(reach, norm(t.point(i) - c));
      reach_ = std::max(reach_, reach);
      bounds_.push_back({c, reach});
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
    if (hint != alpha::kNone && triangle_distance(x, hint) <= d) return true;
    return grid_.any(x, (d + reach_) * (1 + 1e-9) + 1e-9, [&](alpha::Index k) {
      if (!may_be_within(x, k, d) || triangle_distance(x, k) > d) return false;
      hint = k;
      return true;
    });
  }

  // The smallest distance from x to a triangle (infinite if there are none).
  // `hint`: a triangle likely near (kNone: none yet), whose distance bounds
  // the search's cube (a deep cavity's cell is far from every mouth: cubes
  // doubled from a small one would visit the same triangles several times
  // over); set to the nearest found.
  double distance(const alpha::Vec3& x, alpha::Index& hint) const {
    double d = std::numeric_limits<double>::infinity();
    if (triangles_.empty()) return d;
    if (hint != alpha::kNone) d = triangle_distance(x, hint);
    for (double h = hint == alpha::kNone ? 2 * reach_ + 4 : (d + reach_) * (1 + 1e-8) + 1e-8;; h *= 2) {
      grid_.visit(x, h, [&](alpha::Index k) {
        if (!may_be_within(x, k, d)) return;
        if (const double dk = triangle_distance(x, k); dk < d) {
          d = dk;
          hint = k;
        }
      });
      if (d < (h - reach_) * (1 - 1e-9) - 1e-9 || grid_.covers_all(x, h)) return d;
    }
  }

private:
  const alpha::Triangulation& t_;
  const alpha::Simplices& s_;
  std::span<const alpha::Index> triangles_;
  alpha::PointGrid grid_;
  struct Bound {
    alpha::Vec3 centroid;
    double reach;  // to the furthest corner
  };
  std::vector<Bound> bounds_;  // per triangle
  double reach_ = 0;           // the largest

  template <class V>
  alpha::Vec3 centroid(const V& v) const {
    const alpha::Vec3 sum = t_.point(v[0]) + t_.point(v[1]) + t_.point(v[2]);
    return (1.0 / 3) * sum;
  }
  // False only if triangle k is further than d from x.
  bool may_be_within(const alpha::Vec3& x, alpha::Index k, double d) const {
    const alpha::Vec3 y = x - bounds_[k].centroid;
    const double r = (d + bounds_[k].reach) * (1 + 1e-9) + 1e-9;
    return dot(y, y) <= r * r;
  }
  double triangle_distance(const alpha::Vec3& x, alpha::Index k) const {
    const auto& v = s_.triangle(triangles_[k]);
    return point_triangle_distance(x, t_.point(v[0]), t_.point(v[1]), t_.point(v[2]));
  }
};

}  // namespace molecule
