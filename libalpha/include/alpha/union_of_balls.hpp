// SPDX-License-Identifier: Apache-2.0
// Area and volume of a union of balls, analytically, from its dual complex.
//
// A weighted point (p, w) is the ball of center p and radius r = sqrt(w).
// The dual complex K of the union is the alpha complex at alpha_sq = 0
// (Edelsbrunner 1995, "The union of balls and its dual shape"), and the
// short inclusion-exclusion formula over K is exact:
//   Vol = sum_v V(B_v) - sum_e V(B_u & B_v) + sum_t V(3 balls) - sum_T V(4 balls),
// and likewise the area of the union's boundary.
//
// Per ball i, the terms split exactly (Edelsbrunner & Fu; Liang et al. 1998):
//  - area: the part of sphere S_i on the union's boundary, S_i & P_i, where
//    P_i is the power cell of i; each term of a simplex s containing i
//    contributes the area of S_i inside the other balls of s.
//  - volume: V(B_i & P_i). By the divergence theorem it is
//      (r_i A_i + sum_j h_ij F_ij) / 3,
//    with A_i the area above, h_ij the signed distance from p_i to the
//    radical plane of i and j, and F_ij the area of the power diagram's facet
//    between i and j inside the balls (a disc minus circular segments plus
//    disc sectors, by the same inclusion-exclusion in that plane).
// Every term is computed from one formula: Gauss-Bonnet for spherical
// patches bounded by circle arcs (angles by atan2, never acos/asin), the
// shoelace formula for planar patches, with all vectors taken relative to a
// vertex of the simplex (translation does not cost digits).
//
// Per cell T of the triangulation the union's part is exact: it is the
// union of the B_i & P_i & T (the restricted power cells partition it), and
// B_i & P_i is B_i cut by the half-spaces of i's neighbours in K (a facet of
// P_i that cuts B_i joins i to a ball it meets there: an edge of K). Each
// B_i & P_i & T is a ball inside a convex polyhedron, measured in closed
// form (ball_in_polyhedron.hpp). Only the balls reaching T count; a flat
// cell covers nothing. Cells tile space, so the cells' parts sum to the
// whole union when it lies inside the convex hull, and the parts of any
// set of cells (a pocket, open or not) are the union's volume and area
// inside it.
// Precision: double arithmetic, not exact (unlike K itself, which is exact).
// Each term has a relative error of a few ulps away from tangencies. Where
// two balls barely touch (circle radius a below 10^-5.5 r), the angles of
// the tiny circle would lose digits (error ~ eps r / a): such an edge and
// its cofaces are left out, an error below 1e-10 r^2 in area per edge.
// Other near-degeneracies (three spheres almost meeting in one point, four
// almost on one orthogonal sphere) stay well conditioned. Sums use
// compensated (Neumaier) summation in a fixed order: results are
// deterministic, and for 1e4-1e5 balls the total area and volume have a
// relative error of about 1e-13. Per-ball values within 1e-11 of the
// sphere's area (ball's volume) are rounding noise and reported as 0.
// Tests: an independent numerical integration agrees to 1e-9, translation
// changes results by less than 1e-11, and FreeSASA's Lee-Richards converges
// to our protein areas (5e-8 at 16000 slices per atom).
#pragma once
#include <array>
#include <span>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/point_grid.hpp"

namespace alpha {

// The union's part of one cell of the triangulation (see above).
struct CellCover {
  double volume = 0;  // volume of the cell covered by the union
  double area = 0;    // area of the union's boundary inside the cell
};

// Appends four balls of radius 0 (weight 0) around the balls (centres
// `points`, squared radii `weights`), farther from each ball than its
// radius: they add nothing to the union (no area, no volume, no ball of
// the dual complex touches them) but make any set of balls, even one ball
// or balls centred on a line or a plane, span 3D, so that it has a regular
// triangulation. The input balls keep their indices.
void add_far_points(std::vector<Vec3>& points, std::vector<double>& weights);

class UnionOfBalls {
public:
  // complex: the alpha complex of a triangulation whose weights are the
  // squared radii; an unweighted triangulation is a union of points (all
  // measures 0). Throws alpha::Error for a negative weight. Keeps a
  // reference to complex.
  explicit UnionOfBalls(const AlphaComplex& complex);

  const AlphaComplex& complex() const { return *complex_; }
  double area() const { return area_; }
  double volume() const { return volume_; }

  // Per input point: the area of its sphere on the union's boundary and the
  // volume of its ball inside its power cell. 0 for hidden and duplicate
  // points (their balls lie inside the union) and for balls covered by
  // others. They sum to area() and volume().
  std::span<const double> ball_areas() const { return ball_area_; }
  std::span<const double> ball_volumes() const { return ball_volume_; }

  // The union's part of finite cell c (see above); zero for an infinite
  // cell.
  CellCover cell_cover(Index c) const;

  // Whether a simplex is in the dual complex K (alpha complex at 0).
  bool in_dual_complex_vertex(Index v) const;
  bool in_dual_complex_edge(Index e) const { return complex_->edge_interval(e).entry < level_; }
  bool in_dual_complex_triangle(Index f) const { return complex_->triangle_interval(f).entry < level_; }
  bool in_dual_complex_cell(Index c) const { return complex_->cell_entry(c) < level_; }

  std::size_t memory_bytes() const;

private:
  const AlphaComplex* complex_;
  Index level_;  // simplices with entry rank below it are in K
  double area_ = 0, volume_ = 0;
  std::vector<double> ball_area_, ball_volume_;
  std::vector<double> radius_;
  double max_radius_ = 0;
  PointGrid balls_;                                   // the balls of K
  std::vector<Index> neighbour_start_, neighbours_;  // per ball, its neighbours in K
};

}  // namespace alpha
