// SPDX-License-Identifier: Apache-2.0
#include "alpha/simplices.hpp"

#include <algorithm>

#include "alpha/error.hpp"
#include "huge_pages.hpp"
#include "prefetch.hpp"

namespace alpha {
namespace {

// Local edge k of a cell joins vertices kEdge[k]; kEdge[5-k] is the opposite
// edge; kLocalEdge inverts the table.
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int kLocalEdge[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};

// The local index of a vertex that cell vertices cv hold, without
// branches: around a ring it is anywhere, and branches would mispredict.
int position(const std::array<Index, 4>& cv, Index v) {
  return int(cv[1] == v) + 2 * int(cv[2] == v) + 3 * int(cv[3] == v);
}

}  // namespace

SimplexCounts count_simplices(const Triangulation& t) {
  const std::size_t cells = t.num_finite_cells(), hull = t.num_cells() - cells;
  const std::size_t triangles = (4 * cells + hull) / 2;
  return {t.num_vertices() + triangles - cells - 1, triangles, hull};
}

Simplices::Simplices(const Triangulation& t) : t_(&t) {
  const std::size_t np = t.num_points();
  // Edges in order of the first cell holding them: walking the cells in
  // storage order keeps memory access local. The first cell of an edge
  // turns around it and records the new id in every cell of that ring.
  // Counts from Euler's relation for the 3-sphere (the infinite vertex
  // included): V - E + F - C = 0 with F = 2C, so E = V + C, less the hull
  // vertices' edges to infinity; each infinite cell has 3 of the F facets
  // through infinity, each shared by two cells.
  const std::size_t nc = t.num_cells(), infinite_cells = nc - t.num_finite_cells();
  std::vector<std::array<Index, 6>> cell_edges;  // temporary
  std::array<Index, 6> none;
  none.fill(kNone);
  assign_huge(cell_edges, nc, none);
  reserve_huge(edges_, t.num_vertices() + 1 + nc);
  reserve_huge(edge_cells_, t.num_vertices() + 1 + nc);
  // The facets' far sides and the rings start in the neighbours, which lie
  // anywhere (at 1e6 random points, more than half of the ring steps go
  // 65,536 cells or further in memory).
  const auto prefetch_neighbours = [&](Index c) {
    if (c + kAhead < t.num_cells())
      for (const Index n : t.cell(c + Index(kAhead)).n) prefetch(&t.cell(n));
  };
  // A ring around an edge of c also reaches the neighbours' neighbours
  // (the whole ring when it has up to 5 cells), asked for once the
  // neighbours have arrived.
  const auto prefetch_rings = [&](Index c) {
    prefetch_neighbours(c + Index(kAhead));  // checks its own range
    if (c + kAhead < t.num_cells())
      for (const Index n : t.cell(c + Index(kAhead)).n)
        for (const Index m : t.cell(n).n) prefetch(&t.cell(m));
  };
  for (Index c = 0; c < t.num_cells(); ++c) {
    prefetch_rings(c);
    for (int e = 0; e < 6; ++e) {
      const Index a = t.cell(c).v[kEdge[e][0]], b = t.cell(c).v[kEdge[e][1]];
      if (cell_edges[c][e] != kNone || a == kInfinite || b == kInfinite) continue;
      const Index id = static_cast<Index>(edges_.size());
      edges_.push_back({std::min(a, b), std::max(a, b)});
      edge_cells_.push_back(c);
      // Cells around ab: cross the facet opposite one of the two other
      // vertices; in the next cell, cross the facet opposite the vertex
      // shared with the previous one.
      Index cur = c;
      Index across = t.cell(c).v[kEdge[5 - e][0]];
      do {
        const auto& cv = t.cell(cur).v;
        const int ia = position(cv, a), ib = position(cv, b);
        cell_edges[cur][kLocalEdge[ia][ib]] = id;
        cur = ring_step(t, cur, ia, ib, position(cv, across), across);
      } while (cur != c);
    }
  }
  // Triangles: each finite facet once, from the cell with the smaller id.
  // Facet i of a cell misses vertex i, so its edges are the local edges
  // avoiding i, listed opposite to the facet's vertices f[0], f[1], f[2].
  if (t.num_cells() >= (std::size_t(1) << 30)) fail("too many cells for 32-bit triangle records", ErrorKind::LimitExceeded);
  assign_huge(cell_triangles_, 4 * nc, kNone);
  reserve_huge(triangle_facets_, 2 * nc - 3 * infinite_cells / 2);
  reserve_huge(triangle_edges_, 2 * nc - 3 * infinite_cells / 2);
  auto local_edge = [](int a, int b) { return static_cast<std::size_t>(kLocalEdge[a][b]); };
  for (Index c = 0; c < t.num_cells(); ++c) {
    prefetch_neighbours(c);
    const Cell& cell = t.cell(c);
    const int inf = t.infinite_position(c);
    for (int i = 0; i < 4; ++i) {
      const Index n = cell.n[i];
      if (n < c || (inf >= 0 && inf != i)) continue;  // not ours, or not finite
      const auto& f = kFacet[i];
      const Index id = static_cast<Index>(triangle_facets_.size());
      const auto& ce = cell_edges[c];
      triangle_facets_.push_back(c << 2 | Index(i));
      triangle_edges_.push_back({ce[local_edge(f[1], f[2])], ce[local_edge(f[0], f[2])], ce[local_edge(f[0], f[1])]});
      cell_triangles_[4 * std::size_t(c) + i] = id;
      cell_triangles_[4 * std::size_t(n) + t.mirror_index(c, i)] = id;
      num_hull_triangles_ += inf >= 0 || t.is_infinite(n);
    }
  }
  release(cell_edges);
  // Each vertex's edges, as compressed rows (32-bit offsets).
  if (2 * edges_.size() >= kNone) fail("too many edges for 32-bit incidence offsets", ErrorKind::LimitExceeded);
  assign_huge(vertex_edge_start_, np + 1, Index(0));
  for (const auto& e : edges_) ++vertex_edge_start_[e[0] + 1], ++vertex_edge_start_[e[1] + 1];
  for (std::size_t v = 0; v < np; ++v) vertex_edge_start_[v + 1] += vertex_edge_start_[v];
  assign_huge(vertex_edges_, vertex_edge_start_[np], kNone);
  for (Index e = 0; e < edges_.size(); ++e)
    for (const Index v : edges_[e]) vertex_edges_[vertex_edge_start_[v]++] = e;
  for (std::size_t v = np; v > 0; --v) vertex_edge_start_[v] = vertex_edge_start_[v - 1];  // the fill moved them
  vertex_edge_start_[0] = 0;
}

Index Simplices::find_edge(Index u, Index v) const {
  const std::array<Index, 2> key{std::min(u, v), std::max(u, v)};
  for (Index e : vertex_edges(u))
    if (edges_[e] == key) return e;
  return kNone;
}

bool Simplices::on_hull(Index f) const {
  const auto cells = triangle_cells(f);
  return t_->is_infinite(cells[0]) || t_->is_infinite(cells[1]);
}

std::size_t Simplices::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(edges_) + bytes(edge_cells_) + bytes(triangle_facets_) + bytes(triangle_edges_) +
         bytes(cell_triangles_) + bytes(vertex_edge_start_) + bytes(vertex_edges_);
}

}  // namespace alpha
