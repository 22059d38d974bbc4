// SPDX-License-Identifier: Apache-2.0
// An independent test of the molecular surface: the distance from a point
// to the outside of a union of balls, by brute force over the candidates
// for its nearest boundary point (each sphere's nearest point, each
// circle's where two spheres meet, each point where three meet), keeping
// those inside no other ball. The nearest point of the outside is among
// them: on a sphere (a circle) the distance from x only grows away from the
// nearest point, so a patch's (an arc's) nearest point is that point or on
// its rim. A grid keeps each query to the balls near it.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "alpha/geometry.hpp"

namespace testing {

class DepthOracle {
public:
  // Balls of the union; `reach`: the largest depth asked about.
  DepthOracle(std::vector<alpha::Vec3> centers, std::vector<double> radii, double reach);

  // Whether x lies in the union at distance at least `depth` from its outside.
  bool deeper(const alpha::Vec3& x, double depth) const;

  // Monte Carlo estimate of the volume of {x : deeper(x, depth)}, and its
  // standard error, from `samples` uniform points of the union's bounding box.
  std::pair<double, double> volume_deeper(double depth, long samples, std::uint64_t seed) const;
  // The same per ball, of the part in its power cell (the ball of least
  // power |x - c|^2 - r^2, by brute force): estimates and standard errors.
  std::pair<std::vector<double>, std::vector<double>> cell_volumes_deeper(double depth, long samples,
                                                                          std::uint64_t seed) const;

private:
  std::vector<alpha::Vec3> c_;
  std::vector<double> r_;
  double max_radius_ = 0, reach_, cell_;
  alpha::Vec3 lo_, hi_;
  int n_[3];
  std::vector<std::vector<int>> balls_, triple_points_;  // per grid cell
  std::vector<alpha::Vec3> triple_;

  int cell_of(const alpha::Vec3& p, int axis) const;
  // The balls (or triple points) in grid cells within `radius` of p.
  template <class F>
  void near(const std::vector<std::vector<int>>& grid, const alpha::Vec3& p, double radius, F f) const;
  bool on_boundary(const alpha::Vec3& p) const;
};

}  // namespace testing
