#include "alpha/simplices.hpp"

#include <algorithm>

namespace alpha {
namespace {

// Local edge k of a cell joins vertices kEdge[k]; kEdge[5-k] is the opposite
// edge; kLocalEdge inverts the table.
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int kLocalEdge[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};

// Compressed rows from per-row counts: start[i]..start[i+1].
std::vector<std::size_t> offsets(const std::vector<std::size_t>& counts) {
  std::vector<std::size_t> start(counts.size() + 1, 0);
  for (std::size_t i = 0; i < counts.size(); ++i) start[i + 1] = start[i] + counts[i];
  return start;
}

}  // namespace

Simplices::Simplices(const Triangulation& t) : t_(&t) {
  const std::size_t np = t.num_points();
  // Edges in order of the first cell holding them: walking the cells in
  // storage order keeps memory access local. The first cell of an edge
  // turns around it and records the new id in every cell of that ring.
  std::vector<std::array<Index, 6>> cell_edges(t.num_cells());  // temporary
  for (auto& ce : cell_edges) ce.fill(kNone);
  edges_.reserve(t.num_cells() * 11 / 10 + 16);
  for (Index c = 0; c < t.num_cells(); ++c) {
    for (int e = 0; e < 6; ++e) {
      const Index a = t.cell(c).v[kEdge[e][0]], b = t.cell(c).v[kEdge[e][1]];
      if (cell_edges[c][e] != kNone || a == kInfinite || b == kInfinite) continue;
      const Index id = static_cast<Index>(edges_.size());
      edges_.push_back({std::min(a, b), std::max(a, b)});
      // Cells around ab: cross the facet opposite one of the two other
      // vertices; in the next cell, cross the facet opposite the vertex
      // shared with the previous one.
      Index cur = c;
      Index across = t.cell(c).v[kEdge[5 - e][0]];
      do {
        const Cell& cell = t.cell(cur);
        const int ia = t.index_of(cur, a), ib = t.index_of(cur, b);
        cell_edges[cur][kLocalEdge[ia][ib]] = id;
        const int k = t.index_of(cur, across);
        const Index next = cell.n[k];
        across = cell.v[6 - ia - ib - k];  // the remaining vertex: shared with next
        cur = next;
      } while (cur != c);
    }
  }
  // Triangles: each finite facet once, from the cell with the smaller id.
  // Facet i of a cell misses vertex i, so its edges are the local edges
  // avoiding i, listed opposite to the facet's vertices f[0], f[1], f[2].
  cell_triangles_.assign(4 * t.num_cells(), kNone);
  triangles_.reserve(2 * t.num_cells());
  triangle_cells_.reserve(2 * t.num_cells());
  triangle_edges_.reserve(2 * t.num_cells());
  auto local_edge = [](int a, int b) { return static_cast<std::size_t>(kLocalEdge[a][b]); };
  for (Index c = 0; c < t.num_cells(); ++c) {
    const Cell& cell = t.cell(c);
    for (int i = 0; i < 4; ++i) {
      const Index n = cell.n[i];
      if (n < c) continue;
      const auto& f = kFacet[i];
      const std::array<Index, 3> tri{cell.v[f[0]], cell.v[f[1]], cell.v[f[2]]};
      if (std::find(tri.begin(), tri.end(), kInfinite) != tri.end()) continue;
      const Index id = static_cast<Index>(triangles_.size());
      const auto& ce = cell_edges[c];
      triangles_.push_back(tri);
      triangle_cells_.push_back({c, n});
      triangle_edges_.push_back({ce[local_edge(f[1], f[2])], ce[local_edge(f[0], f[2])], ce[local_edge(f[0], f[1])]});
      cell_triangles_[4 * std::size_t(c) + i] = id;
      cell_triangles_[4 * std::size_t(n) + t.mirror_index(c, i)] = id;
      num_hull_triangles_ += t.is_infinite(c) || t.is_infinite(n);
    }
  }
  // Up incidences.
  std::vector<std::size_t> count(np, 0);
  for (const auto& e : edges_) ++count[e[0]], ++count[e[1]];
  vertex_edge_start_ = offsets(count);
  vertex_edges_.resize(vertex_edge_start_.back());
  std::vector<std::size_t> fill(vertex_edge_start_.begin(), vertex_edge_start_.end() - 1);
  for (Index e = 0; e < edges_.size(); ++e)
    for (Index v : edges_[e]) vertex_edges_[fill[v]++] = e;
  count.assign(edges_.size(), 0);
  for (const auto& te : triangle_edges_)
    for (Index e : te) ++count[e];
  edge_triangle_start_ = offsets(count);
  edge_triangles_.resize(edge_triangle_start_.back());
  fill.assign(edge_triangle_start_.begin(), edge_triangle_start_.end() - 1);
  for (Index f = 0; f < triangle_edges_.size(); ++f)
    for (Index e : triangle_edges_[f]) edge_triangles_[fill[e]++] = f;
}

Index Simplices::find_edge(Index u, Index v) const {
  const std::array<Index, 2> key{std::min(u, v), std::max(u, v)};
  for (Index e : vertex_edges(u))
    if (edges_[e] == key) return e;
  return kNone;
}

bool Simplices::on_hull(Index f) const {
  return t_->is_infinite(triangle_cells_[f][0]) || t_->is_infinite(triangle_cells_[f][1]);
}

std::size_t Simplices::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(edges_) + bytes(triangles_) + bytes(triangle_edges_) + bytes(triangle_cells_) + bytes(cell_triangles_) +
         bytes(vertex_edge_start_) + bytes(edge_triangle_start_) + bytes(vertex_edges_) + bytes(edge_triangles_);
}

}  // namespace alpha
