// SPDX-License-Identifier: Apache-2.0
// A union of balls eroded by a ball of radius r: the points whose distance
// to the outside of the union is at least r. For the probe-inflated atoms
// of a molecule (radii r_i + r) it is the body bounded by the molecular
// (solvent-excluded, Connolly) surface: the space a probe of radius r
// rolling on the atoms cannot reach.
//
// How its volume and area are derived (Connolly's decomposition, kept exact
// where probe positions come closer than 2r; the quadrature and its
// precision; the split per cell and per ball): docs/eroded_union.md.
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
