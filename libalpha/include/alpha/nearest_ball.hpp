// SPDX-License-Identifier: Apache-2.0
// Distance from a point to the nearest of a set of balls' spheres (the
// radius of the largest ball centred there that meets none of them;
// negative inside a ball), exact per query: the balls are bucketed in a
// PointGrid and a query looks in a cube of half-side h about the point,
// doubling h until the nearest sphere found is nearer than any centre
// beyond the cube can be (farther than h, so beyond h - max radius), or
// every ball is seen. Infinite for a point at infinity (the orthocentre of
// a flat cell). The arrays are borrowed.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "alpha/geometry.hpp"
#include "alpha/point_grid.hpp"

namespace alpha {

class NearestBall {
public:
  // `start` is the first cube's half-side (>= 1 is used: zero radii).
  NearestBall(std::span<const Vec3> centres, std::span<const double> radii, double start)
      : centres_(centres), radii_(radii), grid_(4), start_(start) {
    for (Index i = 0; i < centres.size(); ++i) grid_.add(centres[i], i);
    grid_.finish();
    for (const double r : radii) max_radius_ = std::max(max_radius_, r);
  }

  double distance(const Vec3& x) const {
    double d = std::numeric_limits<double>::infinity();
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) return d;
    for (double h = std::max(start_ + 2 * max_radius_, 1.0);; h *= 2) {
      grid_.visit(x, h, [&](Index i) { d = std::min(d, norm(x - centres_[i]) - radii_[i]); });
      if (d < (h - max_radius_) * (1 - 1e-9) || grid_.covers_all(x, h)) return d;
    }
  }

  // Calls f(i) for every ball whose sphere is within `gap` of x (and maybe
  // a few more: the caller tests).
  template <class F>
  void visit_near(const Vec3& x, double gap, F f) const {
    grid_.visit(x, gap + max_radius_, f);
  }

private:
  std::span<const Vec3> centres_;
  std::span<const double> radii_;
  PointGrid grid_;
  double start_;
  double max_radius_ = 0;
};

}  // namespace alpha
