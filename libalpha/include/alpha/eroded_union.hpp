// SPDX-License-Identifier: Apache-2.0
// A union of balls eroded by a ball of radius r: the points whose distance
// to the outside of the union is at least r. For the probe-inflated atoms
// of a molecule (radii r_i + r) it is the body bounded by the molecular
// (solvent-excluded, Connolly) surface: the space a probe of radius r
// rolling on the atoms cannot reach.
//
// Let U be the union (balls B_i, radii R_i >= r), F the closure of its
// complement and L = U minus the eroded body: the layer of points within r
// of F. Every point x of L has a nearest point q in F, on the boundary of
// U, and lies on the segment from q along a normal of F at q, at distance
// t <= r. The layer is split by the piece of the boundary q lies on
// (Connolly's decomposition, kept exact where probe positions come closer
// than 2r, the "singular" case):
//  - a spherical patch of sphere i: x on the radius from q towards p_i.
//    The ball of radius t about x lies inside B_i, so q is x's only nearest
//    point and the whole shell between radii R_i - r and R_i under the
//    patch belongs to it: volume A_i (R_i^3 - (R_i - r)^3) / (3 R_i^2),
//    eroded face (contact patch) area A_i ((R_i - r) / R_i)^2, with A_i the
//    patch's area (UnionOfBalls);
//  - an arc of the circle where spheres i and j meet: x = q + t u with u in
//    the wedge between the directions from q to p_i and p_j (toroidal);
//  - a vertex where three spheres meet: u in the cone spanned by the
//    directions to the three centres (reentrant spherical).
// On arcs and vertices q stays x's nearest point only up to the cut
// distance tau(q, u) <= r along the ray: beyond it some other point of F
// (another probe position, the same torus past its axis) is nearer. tau
// is found by bisection on the nearest-point test (no point of F strictly
// nearer to x than t), which holds on an initial segment of the ray. With
// rho the circle's radius and psi the angle of u from the circle's plane,
// the layer's volume on an arc is the integral over the arc's angle phi
// and psi of int_0^tau |rho - t cos psi| t dt, on a vertex the integral of
// tau^3 / 3 over the cone's solid angle; the eroded surface is where
// tau = r, with area elements |rho - r cos psi| r dpsi dphi and r^2 dOmega.
//
// Precision: the integrands are evaluated exactly in doubles (tau to
// 1e-8 r); the integrals over phi and psi, and over a cone in geodesic
// polar coordinates about a corner, are 8 x 8-node Gauss-Legendre products
// (arc pieces of at most pi/4), and where tau = r starts or stops between
// nodes the change is located by bisection. A piece whose 64 nodes all see
// tau = r (no singularity) takes the closed form, exact to rounding. So a
// small cut-off region that falls between the nodes of a piece counts
// whole: on 1A26 chain A, testing on finer grids (arcs split 4 times finer
// in phi and psi, cones cut into spherical triangles of 0.5 rad) moves the
// volume by 8e-6 and the area by 2e-4 (relative). Tests: Monte Carlo on an
// independent nearest-point test, the area against -d volume / d r.
//
// The boundary's pieces are read from the dual complex K (alpha_sq = 0):
// circles of edges of K, clipped to the power facet by the edge's ring of
// neighbours; vertices of triangles of K, kept where they lie on the
// triangle's Voronoi edge. Where more than three spheres meet in a point
// (degenerate input) several triangles give the same vertex; a direction
// in two of their cones goes to the one of smaller triangle id.
//
// Per cell of the triangulation the layer is split by regions of space
// (share_cell's rule): a patch's shell under the part of the patch in the
// cell's cone at the sphere's centre (patch_area, closed form), an arc's
// pieces by the cell's angular sector around the arc's edge, a vertex to
// the cell on its side of its triangle. The totals are summed from the
// same pieces; the finite cells' shares sum to them when no ball reaches
// outside the convex hull.
//
// Per ball (layer(per_ball)), every point goes to the power cell holding
// it, the rule of UnionOfBalls' per-ball area and volume: ball i gets the
// layer's volume and the eroded surface's area inside its power cell P_i,
// so the eroded body's volume in P_i is ball_volumes()[i] less its layer
// share (never more than it, never negative but for the quadrature's
// error), and these sum to the totals. The pieces are split without
// touching the totals: a shell under a patch of sphere i lies in P_i when
// p_i does (P_i is convex and holds the patch); else the part beyond a
// radical plane passing behind p_i (a small ball beside a large one, as an
// O on a C) goes to that neighbour, integrated over its latitude band in
// closed-form arcs, and the same amount is taken from i. Toroidal and
// reentrant pieces are integrated again ray by ray, psi (the cone) cut at
// the power planes of their own balls, each ray cut where the power cell
// changes along it (power differences are linear in t), and their totals
// are divided in those proportions: exact sums, per-ball errors of the
// quadrature (on 60 atoms of 1FKG: each atom's area equals minus the
// derivative of its volume in r to 5e-3, its volume a Monte Carlo count by
// power cell within 4.5 sigma).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "alpha/point_grid.hpp"
#include "alpha/union_of_balls.hpp"

namespace alpha {

// Volume and area of the layer, or of its share in one cell: the layer's
// volume (points of the union within r of the outside) and the area of the
// eroded body's boundary.
struct LayerShare {
  double volume = 0;
  double area = 0;
};

class ErodedUnion {
public:
  // `balls`: the union (the complex's weights are the squared radii R_i^2).
  // r >= 0 and at most the radius of every ball on the union's boundary.
  // Finds the boundary's arcs and vertices; integrates nothing yet. Keeps a
  // reference to balls. Throws alpha::Error for a bad r.
  ErodedUnion(const UnionOfBalls& balls, double r);

  double r() const { return r_; }
  const UnionOfBalls& balls() const { return *balls_; }

  // The whole layer: every piece integrated (time proportional to the
  // union's boundary). The eroded body's volume is balls.volume() minus
  // its volume; the eroded body's boundary area is its area.
  LayerShare layer() const;
  // The same totals (bit for bit), and per input point (balls' indices)
  // the layer's volume and the eroded surface's area inside its power cell
  // (see above): they sum to the totals up to rounding; 0 for hidden
  // points. About 3.5 times layer()'s time.
  LayerShare layer(std::vector<LayerShare>& per_ball) const;

  // The share of cell c (see above); {} for an infinite cell.
  LayerShare cell_share(Index c) const;
  // The sum of the cells' shares, added in their order (quicker than
  // cell_share one by one: its scratch space is kept from cell to cell).
  LayerShare cells_share(std::span<const Index> cells) const;
  // The area of the sphere of cell c's vertex k on the union's boundary
  // inside the cell's cone at its centre (spanned by the directions to the
  // other three vertices), in closed form; 0 for an infinite cell.
  double patch_area(Index c, int k) const;

  // The point of F (the closure of the union's complement) nearest to a
  // point x, and the piece of the union's boundary it lies on: x itself
  // when x is outside the union; `far` when no point of F is nearer than
  // the limit asked for (x deep inside).
  struct Nearest {
    enum class On : std::uint8_t { outside, sphere, circle, vertex, far } on = On::far;
    double distance = 0;  // |x - point|; the limit for `far`
    Vec3 point{};
    Index which = kNone;  // the ball (sphere), the edge (circle) or the boundary vertex (vertex)
  };

private:
  class Integrator;  // eroded_union_integrator.hpp

public:
  // Nearest-point queries about the points near `center`, with the
  // boundary's pieces that can be within r of a point within `reach` of
  // it gathered once: nearest(x, limit) needs |x - center| + limit - r <= reach.
  class Nearby {
  public:
    // The nearest point of F to x, exact (up to rounding) when nearer than
    // `limit` (see nearby()).
    Nearest nearest(const Vec3& x, double limit) const;
    // A lower bound of the distance from x to the union, exact when below
    // reach - |x - center| (infinite when no ball comes within reach).
    double outside_by(const Vec3& x) const;
    // The same queries about the points within `reach` of `center` (a ball
    // inside this one's), against only the pieces that can matter there:
    // the same answers, from fewer pieces per call.
    Nearby narrowed(const Vec3& center, double reach) const;
    Nearby(Nearby&&) noexcept;
    Nearby& operator=(Nearby&&) noexcept;
    ~Nearby();
    struct Hood;  // defined where it is used

  private:
    friend class ErodedUnion;
    Nearby(std::shared_ptr<const Integrator> in, std::unique_ptr<Hood> hood);
    // Made once per Nearby and shared with the ones narrowed from it, not
    // made per query (it holds scratch space for integrals that nearest()
    // does not use).
    std::shared_ptr<const Integrator> in_;
    std::unique_ptr<Hood> hood_;
  };
  Nearby nearby(const Vec3& center, double reach) const;

  // The cell whose share (cell_share, and UnionOfBalls::cell_cover outside
  // the union) counts the point x, whose nearest point of F is n: the cell
  // holding x when x is outside the union, else the cell on whose side of
  // the piece n.point lies (its cone at a sphere's centre, its wedge about
  // an arc's edge, its side of a vertex's triangle). hint: a cell near x
  // (kNone: any). kNone for `far` points; may be infinite.
  Index share_cell(const Vec3& x, const Nearest& n, Index hint = kNone) const;

  struct Arc {
    double begin, length;  // radians about the circle's axis, begin in [0, 2 pi)
  };
  struct ArcEnds {
    double cos_begin, sin_begin, cos_end, sin_end;
  };
  struct Vertex {
    Vec3 p;
    Index triangle;
    Index cell;  // the cell on its side of the triangle (may be infinite)
  };
  // A neighbour's ball as a test of covering: a point x is inside when
  // |x - c|^2 < limit (its squared radius less the tolerance).
  struct Cover {
    Vec3 c;
    double limit;
  };

private:
  LayerShare share(const Integrator& in, Index c) const;
  LayerShare measure(std::vector<LayerShare>* per_ball) const;
  const UnionOfBalls* balls_;
  double r_;
  double tolerance_;  // lengths closer than this are equal
  // Per edge of the triangulation: its circle's arcs on the boundary (none
  // for edges not in K), compressed rows.
  std::vector<std::size_t> arc_start_;
  std::vector<Arc> arcs_;
  std::vector<ArcEnds> arc_ends_;  // per arc
  // Per arc: a ball (centre, radius) holding all its edge's arcs.
  std::vector<std::pair<Vec3, double>> arc_bounds_;
  // Per input point k: the edges (k, m) with arcs whose first vertex it
  // is, in vertex_edges order; compressed rows.
  std::vector<std::size_t> circle_start_;
  std::vector<Index> circle_edges_;
  // Per triangle: its vertices on the boundary (0 to 2), compressed rows.
  std::vector<std::size_t> vertex_start_;
  std::vector<Vertex> vertices_;
  // Per input point: the shell's volume and the contact patch's area per
  // unit of sphere area on the boundary.
  std::vector<double> shell_factor_, contact_factor_;
  // Per input point on the boundary: the balls of its neighbours in the
  // triangulation that meet its sphere (only they can cover a point of
  // it), in vertex_edges order; compressed rows.
  std::vector<std::size_t> cover_start_;
  std::vector<Cover> covers_;
  double max_radius_ = 0;
  PointGrid ball_grid_, vertex_grid_;  // the boundary's balls and vertices
};

}  // namespace alpha
