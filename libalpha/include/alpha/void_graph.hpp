// SPDX-License-Identifier: Apache-2.0
// The void graph of a set of balls: the 1-skeleton of their power diagram,
// the graph a probe travels on through the free space between the balls.
//
// Nodes are the power-diagram vertices, i.e. the orthocentres of the finite
// cells of the regular triangulation (node id = cell id), and one node
// outside() standing for all infinite cells (the space beyond the convex
// hull). Each finite triangle f is an edge (edge id = alpha::Simplices
// triangle id): the power-diagram edge dual to f, the segment joining the
// orthocentres of f's two cells (a ray to infinity from a hull triangle's
// finite cell).
//
// Clearance: the radius of the largest ball centred at x that meets none
// of f's three balls is d(x) = min_i (|x - p_i| - r_i). On the dual edge,
// the line through f's orthocentre z perpendicular to f's plane, every
// point is x = z + s n with |x - p_i|^2 = |z - p_i|^2 + s^2 for the three
// vertices (they lie in the plane, z is their common foot), so each term
// and hence d grows with |s|: the narrowest point of the edge is the point
// of the segment nearest z, z itself when the segment holds it, otherwise
// an endpoint. The segment holds z exactly when f is not attached (no
// vertex of its cells lies inside its orthosphere); when the opposite
// vertex q of cell c attaches f, the orthocentre of c lies beyond f's
// plane, on the other cell's side (|q - z|^2 - w_q - size(f) = 2 t (q - z).n
// for c's orthocentre z + t n), and it is the narrowest point. Both cases
// are decided by the exact predicates. The radii r_i may differ from the
// balls that make the diagram (sqrt of the weights): for atoms, clearances
// are to the van der Waals spheres while the diagram is of balls grown by
// a probe; the argument above holds for any radii.
#pragma once
#include <span>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/geometry.hpp"

namespace alpha {

class VoidGraph {
public:
  // radii[i] is the radius of ball i for the clearances (one per input point).
  // Throws alpha::Error when the count does not match.
  VoidGraph(const AlphaComplex& ac, std::span<const double> radii);

  const Triangulation& triangulation() const { return *t_; }
  const Simplices& simplices() const { return *s_; }
  std::size_t num_nodes() const { return t_->num_cells() + 1; }  // ids of infinite cells are unused
  Index outside() const { return Index(t_->num_cells()); }
  // The node of cell c: c itself when finite, outside() otherwise.
  Index node_of_cell(Index c) const { return t_->is_infinite(c) ? outside() : c; }
  bool is_node(Index n) const { return n == outside() || (n < t_->num_cells() && !t_->is_infinite(n)); }

  // A finite node's power-diagram vertex (the cell's orthocentre, floating point).
  const Vec3& position(Index n) const { return position_[n]; }
  // Clearance at a finite node: min over its cell's four balls.
  double node_clearance(Index n) const { return node_clearance_[n]; }

  std::size_t num_edges() const { return clearance_.size(); }
  // The two nodes of edge f, in the order of Simplices::triangle_cells.
  std::array<Index, 2> ends(Index f) const {
    const auto c = s_->triangle_cells(f);
    return {node_of_cell(c[0]), node_of_cell(c[1])};
  }
  Index other_end(Index f, Index n) const {
    const auto e = ends(f);
    return e[0] == n ? e[1] : e[0];
  }
  // The narrowest point of edge f and the clearance there (see above).
  const Vec3& narrowest(Index f) const { return narrowest_[f]; }
  double clearance(Index f) const { return clearance_[f]; }

  // Calls fn(edge, other node) for every edge at node n (four for a finite
  // node, the hull triangles for outside()), in a fixed order.
  template <class F>
  void for_each_edge(Index n, F fn) const {
    if (n == outside()) {
      for (const Index f : hull_edges_) fn(f, other_end(f, n));
      return;
    }
    for (int k = 0; k < 4; ++k) {
      const Index f = s_->cell_triangle(n, k);
      fn(f, node_of_cell(t_->cell(n).n[k]));
    }
  }

private:
  const Triangulation* t_;
  const Simplices* s_;
  std::vector<Vec3> position_;
  std::vector<double> node_clearance_;
  std::vector<Vec3> narrowest_;
  std::vector<double> clearance_;
  std::vector<Index> hull_edges_;
};

}  // namespace alpha
