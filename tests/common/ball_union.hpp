// SPDX-License-Identifier: Apache-2.0
// A union of balls for the tests, with the triangulation and complex it
// refers to kept alive.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "alpha/point_set_complex.hpp"
#include "alpha/union_of_balls.hpp"

namespace testing {

struct BallSet {
  std::vector<alpha::Vec3> centers;
  std::vector<double> radii;
};

struct BallUnion {
  std::optional<alpha::PointSetComplex> shape;
  std::unique_ptr<alpha::UnionOfBalls> u;  // refers to shape's complex
  // pad: add 4 far points of radius 0 (alpha::add_far_points): for inputs
  // of fewer than 4 balls, or to keep every ball inside the convex hull.
  explicit BallUnion(const BallSet& s, bool pad = false) {
    std::vector<double> w;
    for (double r : s.radii) w.push_back(r * r);
    build(s.centers, std::move(w), pad);
  }
  // The balls of weighted points (weight = squared radius).
  static BallUnion of_weighted(std::vector<alpha::Vec3> p, std::vector<double> w) {
    BallUnion b;
    b.build(std::move(p), std::move(w), false);
    return b;
  }
  const alpha::Triangulation& t() const { return shape->triangulation(); }
  const alpha::AlphaComplex& ac() const { return shape->complex(); }
  double ball_area(std::size_t i) const { return u->ball_areas()[i]; }
  double ball_volume(std::size_t i) const { return u->ball_volumes()[i]; }

private:
  BallUnion() = default;
  void build(std::vector<alpha::Vec3> p, std::vector<double> w, bool pad) {
    if (pad) alpha::add_far_points(p, w);
    shape.emplace(std::move(p), std::move(w));
    u = std::make_unique<alpha::UnionOfBalls>(shape->complex());
  }
};

}  // namespace testing
