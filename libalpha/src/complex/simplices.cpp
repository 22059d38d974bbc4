// SPDX-License-Identifier: Apache-2.0
#include "alpha/simplices.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>

#include "alpha/error.hpp"
#include "util/huge_pages.hpp"
#include "util/parallel.hpp"
#include "util/prefetch.hpp"

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

Simplices::Simplices(const Triangulation& t, unsigned threads) : t_(&t) {
  if (t.num_cells() >= (std::size_t(1) << 30))
    fail("too many cells for 32-bit triangle records", ErrorKind::LimitExceeded);
  std::vector<std::array<Index, 6>> cell_edges;  // temporary
  std::array<Index, 6> none;
  none.fill(kNone);
  assign_huge(cell_edges, t.num_cells(), none);
  threads = std::max(threads, 1u);
  const EdgeIds ids = number_edges(cell_edges, threads);
  number_triangles(cell_edges, ids, threads);
  release(cell_edges);
  index_vertex_edges();
}

// The facets' far sides and the rings start in the neighbours, which lie
// anywhere (at 1e6 random points, more than half of the ring steps go
// 65,536 cells or further in memory).
void Simplices::prefetch_neighbours(Index c) const {
  if (c + kAhead < t_->num_cells())
    for (const Index n : t_->cell(c + Index(kAhead)).n) prefetch(&t_->cell(n));
}

// Edges in order of the first cell holding them (the smallest id around
// them): walking the cells in storage order keeps memory access local. The
// first cell of an edge turns around it and records the id in every cell
// of that ring. On threads, each thread numbers the edges whose first cell
// lies in its range of cells, the ids tagged with the thread; a ring that
// reaches a cell before the range belongs to an earlier thread (the range's
// own earlier cells would have numbered it already) and is left to it. Ids
// are written and tested through atomic_ref: a thread may test a cell's
// slot while the ring's owner writes it.
Simplices::EdgeIds Simplices::number_edges(std::vector<std::array<Index, 6>>& cell_edges, unsigned threads) {
  const Triangulation& t = *t_;
  // Counts from Euler's relation for the 3-sphere (the infinite vertex
  // included): V - E + F - C = 0 with F = 2C, so E = V + C, less the hull
  // vertices' edges to infinity; each infinite cell has 3 of the F facets
  // through infinity, each shared by two cells.
  const std::size_t max_edges = t.num_vertices() + 1 + t.num_cells();
  reserve_huge(edges_, max_edges);
  reserve_huge(edge_cells_, max_edges);
  // Few enough threads that none can run out of ids below its tag.
  while (threads > 1 && max_edges >= (std::uint64_t(1) << (32 - std::bit_width(threads - 1))) - 1) threads /= 2;
  EdgeIds ids;
  ids.shift = 32 - std::bit_width(threads - 1);
  ids.first.assign(threads, 0);
  struct alignas(64) Found {
    std::vector<std::array<Index, 2>> edges;
    std::vector<Index> cells;
  };
  std::vector<Found> found(threads - 1);  // the first thread's go straight to edges_
  for (Found& f : found) reserve_huge(f.edges, max_edges), reserve_huge(f.cells, max_edges);
  // A ring around an edge of c also reaches the neighbours' neighbours
  // (the whole ring when it has up to 5 cells), asked for once the
  // neighbours have arrived.
  const auto prefetch_rings = [&](Index c) {
    prefetch_neighbours(c + Index(kAhead));  // checks its own range
    if (c + kAhead < t.num_cells())
      for (const Index n : t.cell(c + Index(kAhead)).n)
        for (const Index m : t.cell(n).n) prefetch(&t.cell(m));
  };
  const auto read = [](Index& slot) { return std::atomic_ref(slot).load(std::memory_order_relaxed); };
  const auto write = [](Index& slot, Index id) { std::atomic_ref(slot).store(id, std::memory_order_relaxed); };
  in_parallel(threads, t.num_cells(), [&](unsigned k, std::size_t begin, std::size_t end) {
    auto& edges = k == 0 ? edges_ : found[k - 1].edges;
    auto& first_cells = k == 0 ? edge_cells_ : found[k - 1].cells;
    const Index tag = Index(std::uint64_t(k) << ids.shift);
    std::vector<Index*> ring;  // the slots of a ring, written once it is known to be the thread's
    // The first range's rings all start at their first cell: written as walked.
    const bool first_range = begin == 0;
    for (Index c = Index(begin); c < end; ++c) {
      prefetch_rings(c);
      for (int e = 0; e < 6; ++e) {
        const Index a = t.cell(c).v[kEdge[e][0]], b = t.cell(c).v[kEdge[e][1]];
        if (a == kInfinite || b == kInfinite || read(cell_edges[c][e]) != kNone) continue;
        // Cells around ab: cross the facet opposite one of the two other
        // vertices; in the next cell, cross the facet opposite the vertex
        // shared with the previous one.
        const Index id = tag | Index(edges.size());
        ring.clear();
        bool earlier = false;
        Index cur = c;
        Index across = t.cell(c).v[kEdge[5 - e][0]];
        do {
          const auto& cv = t.cell(cur).v;
          const int ia = position(cv, a), ib = position(cv, b);
          Index& slot = cell_edges[cur][kLocalEdge[ia][ib]];
          if (first_range) write(slot, id);
          else ring.push_back(&slot), earlier |= cur < c;
          cur = ring_step(t, cur, ia, ib, position(cv, across), across);
        } while (cur != c);
        if (earlier) continue;
        for (Index* slot : ring) write(*slot, id);
        edges.push_back({std::min(a, b), std::max(a, b)});
        first_cells.push_back(c);
      }
    }
  });
  for (unsigned k = 1; k < threads; ++k) {
    ids.first[k] = Index(edges_.size());
    edges_.insert(edges_.end(), found[k - 1].edges.begin(), found[k - 1].edges.end());
    edge_cells_.insert(edge_cells_.end(), found[k - 1].cells.begin(), found[k - 1].cells.end());
    release(found[k - 1].edges), release(found[k - 1].cells);
  }
  return ids;
}

// Triangles: each finite facet once, from the cell with the smaller id, in
// cell order. Facet i of a cell misses vertex i, so its edges are the local
// edges avoiding i, listed opposite to the facet's vertices f[0], f[1],
// f[2]. On threads, each thread counts the facets of its range of cells,
// then writes them from the ids that follow the earlier ranges'.
void Simplices::number_triangles(const std::vector<std::array<Index, 6>>& cell_edges, const EdgeIds& ids,
                                 unsigned threads) {
  const Triangulation& t = *t_;
  const std::size_t nc = t.num_cells();
  // Written once each, by the threads: no fill first.
  const std::size_t num_triangles = count_simplices(t).triangles;
  reserve_huge(cell_triangles_, 4 * nc), cell_triangles_.resize(4 * nc);
  reserve_huge(triangle_facets_, num_triangles), triangle_facets_.resize(num_triangles);
  reserve_huge(triangle_edges_, num_triangles), triangle_edges_.resize(num_triangles);
  // Facet i of cell c, holding infinity at `inf` (or -1), is a triangle c stores.
  const auto stores = [&](Index c, int i, int inf) { return t.cell(c).n[i] >= c && (inf < 0 || inf == i); };
  struct alignas(64) Range {
    Index first = 0;  // its first triangle's id
    std::size_t hull = 0;
  };
  std::vector<Range> ranges(threads);
  if (threads > 1)
    in_parallel(threads, nc, [&](unsigned k, std::size_t begin, std::size_t end) {
      if (k + 1 == threads) return;
      Index n = 0;
      for (Index c = Index(begin); c < end; ++c) {
        const int inf = t.infinite_position(c);
        for (int i = 0; i < 4; ++i) n += stores(c, i, inf);
      }
      ranges[k + 1].first = n;
    });
  for (unsigned k = 1; k < threads; ++k) ranges[k].first += ranges[k - 1].first;
  auto local_edge = [](int a, int b) { return static_cast<std::size_t>(kLocalEdge[a][b]); };
  in_parallel(threads, nc, [&](unsigned k, std::size_t begin, std::size_t end) {
    Index id = ranges[k].first;
    std::size_t hull = 0;
    for (Index c = Index(begin); c < end; ++c) {
      prefetch_neighbours(c);
      const int inf = t.infinite_position(c);
      for (int i = 0; i < 4; ++i) {
        if (inf >= 0 && inf != i) cell_triangles_[4 * std::size_t(c) + i] = kNone;  // through infinity
        if (!stores(c, i, inf)) continue;
        const Index n = t.cell(c).n[i];
        const auto& f = kFacet[i];
        const auto& ce = cell_edges[c];
        triangle_facets_[id] = c << 2 | Index(i);
        triangle_edges_[id] = {ids.global(ce[local_edge(f[1], f[2])]), ids.global(ce[local_edge(f[0], f[2])]),
                               ids.global(ce[local_edge(f[0], f[1])])};
        cell_triangles_[4 * std::size_t(c) + i] = id;
        cell_triangles_[4 * std::size_t(n) + t.mirror_index(c, i)] = id;
        hull += inf >= 0 || t.is_infinite(n);
        ++id;
      }
    }
    ranges[k].hull = hull;
  });
  for (const Range& r : ranges) num_hull_triangles_ += r.hull;
}

// Each vertex's edges, as compressed rows (32-bit offsets).
void Simplices::index_vertex_edges() {
  const std::size_t np = t_->num_points();
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
