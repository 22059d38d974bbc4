// SPDX-License-Identifier: Apache-2.0
// The empty space of the cells and triangles of the solvent-accessible
// complex (alpha_sq = 0 on the probe-inflated balls), what a cavity's
// volume, area, centre, mouths and depth are summed from.
#pragma once
#include "alpha/alpha_complex.hpp"
#include "alpha/union_of_balls.hpp"

namespace molecule {

// A cell's measures (see CavitySpace::cell).
struct CellSpace {
  double volume = 0;    // of the tetrahedron, A^3
  double sa_empty = 0;  // the part not covered by the inflated balls, A^3
  double sa_area = 0;   // the inflated spheres' boundary inside the cell, A^2
  alpha::Vec3 centroid{};
};

class CavitySpace {
public:
  // `u`: the union of the probe-inflated balls (of their complex, weights =
  // squared radii); kept alive by the caller.
  explicit CavitySpace(const alpha::UnionOfBalls& u);

  // The cell's part of the inflated balls' union (alpha::UnionOfBalls::
  // cell_cover): exact per cell, so exact over any set of cells.
  CellSpace cell(alpha::Index c) const;

  // Area of a triangle not covered by the discs its three inflated balls
  // cut from its plane, split the same way: each disc's sector in its
  // corner, less half the lens of each edge in the dual complex (the lens
  // is symmetric about the edge). Exact when no disc reaches the opposite
  // edge.
  double open_area(alpha::Index triangle) const;

  const alpha::UnionOfBalls& union_of_balls() const { return union_; }

private:
  const alpha::AlphaComplex& ac_;
  const alpha::UnionOfBalls& union_;
  alpha::Index level_;
};

// Euclidean distance from p to the triangle abc.
double point_triangle_distance(const alpha::Vec3& p, const alpha::Vec3& a, const alpha::Vec3& b, const alpha::Vec3& c);

}  // namespace molecule
