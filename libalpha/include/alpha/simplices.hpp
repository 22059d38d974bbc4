// The finite edges and triangles of a triangulation, with ids and the
// incidences the alpha complex walks: down (a triangle's edges, an edge's
// vertices) and up (a vertex's edges, an edge's triangles, a triangle's two
// cells, a cell's four triangles). Ids are deterministic: edges sorted by
// their vertex pair, triangles in order of the cell that first holds them.
#pragma once
#include <array>
#include <span>
#include <vector>

#include "alpha/triangulation.hpp"

namespace alpha {

class Simplices {
public:
  explicit Simplices(const Triangulation& t);

  std::size_t num_edges() const { return edges_.size(); }
  const std::array<Index, 2>& edge(Index e) const { return edges_[e]; }  // v0 < v1
  // The edge joining u and v, or kNone.
  Index find_edge(Index u, Index v) const;

  std::size_t num_triangles() const { return triangles_.size(); }
  // Vertices in the order of facet kFacet[i] of triangle_cells(f)[0].
  const std::array<Index, 3>& triangle(Index f) const { return triangles_[f]; }
  const std::array<Index, 3>& triangle_edges(Index f) const { return triangle_edges_[f]; }
  // The two cells sharing the triangle (either may be infinite).
  const std::array<Index, 2>& triangle_cells(Index f) const { return triangle_cells_[f]; }
  bool on_hull(Index f) const;
  std::size_t num_hull_triangles() const { return num_hull_triangles_; }
  // Triangle of facet i of cell c, or kNone when that facet contains kInfinite.
  Index cell_triangle(Index c, int i) const { return cell_triangles_[4 * std::size_t(c) + i]; }

  std::span<const Index> vertex_edges(Index v) const { return range(vertex_edge_start_, vertex_edges_, v); }
  std::span<const Index> edge_triangles(Index e) const { return range(edge_triangle_start_, edge_triangles_, e); }

  std::size_t memory_bytes() const;

private:
  const Triangulation* t_;
  std::vector<std::array<Index, 2>> edges_;
  std::vector<std::array<Index, 3>> triangles_, triangle_edges_;
  std::vector<std::array<Index, 2>> triangle_cells_;
  std::vector<Index> cell_triangles_;
  std::vector<std::size_t> vertex_edge_start_, edge_triangle_start_;  // CSR offsets
  std::vector<Index> vertex_edges_, edge_triangles_;
  std::size_t num_hull_triangles_ = 0;

  static std::span<const Index> range(const std::vector<std::size_t>& start, const std::vector<Index>& items, Index i) {
    return {items.data() + start[i], items.data() + start[i + 1]};
  }
};

}  // namespace alpha
