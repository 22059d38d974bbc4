// SPDX-License-Identifier: Apache-2.0
// The finite edges and triangles of a triangulation, with ids and the
// incidences the alpha complex walks: down (a triangle's edges, an edge's
// vertices) and up (a vertex's edges, an edge's triangles, a triangle's two
// cells, a cell's four triangles). Ids are deterministic: edges and
// triangles in order of the cell that first holds them (cells are stored in
// spatial order, so simplices close in space get close ids).
//
// A triangle is stored as a facet of the cell with the smaller id, from
// which its vertices and its other cell are read: 4 bytes instead of 20.
// An edge's triangles are found by turning around it through the cells
// (from one stored cell), not stored.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <vector>

#include "alpha/triangulation.hpp"
#include "alpha/uninitialized_allocator.hpp"

namespace alpha {

class Simplices {
public:
  class EdgeTriangles;

  // The ids are the same for any number of threads.
  explicit Simplices(const Triangulation& t, unsigned threads = 1);

  std::size_t num_edges() const { return edges_.size(); }
  const std::array<Index, 2>& edge(Index e) const { return edges_[e]; }  // v0 < v1
  // The edge joining u and v, or kNone.
  Index find_edge(Index u, Index v) const;

  std::size_t num_triangles() const { return triangle_facets_.size(); }
  // Vertices in the order of facet kFacet[i] of triangle_cells(f)[0].
  std::array<Index, 3> triangle(Index f) const {
    const auto& v = t_->cell(triangle_cell(f)).v;
    const auto& k = kFacet[triangle_facets_[f] & 3];
    return {v[k[0]], v[k[1]], v[k[2]]};
  }
  const std::array<Index, 3>& triangle_edges(Index f) const { return triangle_edges_[f]; }
  // The two cells sharing the triangle (either may be infinite), the one
  // with the smaller id first.
  std::array<Index, 2> triangle_cells(Index f) const {
    const Index c = triangle_cell(f);
    return {c, t_->cell(c).n[triangle_facets_[f] & 3]};
  }
  // triangle_cells(f)[0], without reading the cell.
  Index triangle_cell(Index f) const { return triangle_facets_[f] >> 2; }
  // Where triangle(f) and triangle_cells(f) start reading, for callers that
  // prefetch it.
  const Index* triangle_record(Index f) const { return &triangle_facets_[f]; }
  bool on_hull(Index f) const;
  std::size_t num_hull_triangles() const { return num_hull_triangles_; }
  // Triangle of facet i of cell c, or kNone when that facet contains kInfinite.
  Index cell_triangle(Index c, int i) const { return cell_triangles_[4 * std::size_t(c) + i]; }

  std::span<const Index> vertex_edges(Index v) const {
    return {vertex_edges_.data() + vertex_edge_start_[v], vertex_edges_.data() + vertex_edge_start_[v + 1]};
  }
  // The triangles containing edge e, in the order of the cells around it:
  // a forward range of ids (for (Index f : edge_triangles(e)), .size()).
  EdgeTriangles edge_triangles(Index e) const;

  std::size_t memory_bytes() const;

private:
  const Triangulation* t_;
  std::vector<std::array<Index, 2>> edges_;
  std::vector<Index> edge_cells_;       // one cell holding each edge
  // Written by threads, each slot once: not zeroed first.
  std::vector<Index, UninitializedAllocator<Index>> triangle_facets_;  // cell << 2 | facet
  std::vector<std::array<Index, 3>, UninitializedAllocator<std::array<Index, 3>>> triangle_edges_;
  std::vector<Index, UninitializedAllocator<Index>> cell_triangles_;
  std::vector<Index> vertex_edge_start_, vertex_edges_;  // compressed rows
  std::size_t num_hull_triangles_ = 0;

  // Edge ids numbered on threads: thread k's edge j is k << shift | j,
  // global id first[k] + j once every thread's count is known.
  struct EdgeIds {
    int shift = 32;
    std::vector<Index> first;
    Index global(Index id) const {
      const auto k = std::size_t(std::uint64_t(id) >> shift);
      return first[k] + Index(id & ((std::uint64_t(1) << shift) - 1));
    }
  };
  EdgeIds number_edges(std::vector<std::array<Index, 6>>& cell_edges, unsigned threads);
  void number_triangles(const std::vector<std::array<Index, 6>>& cell_edges, const EdgeIds& ids, unsigned threads);
  void index_vertex_edges();
  void prefetch_neighbours(Index c) const;

  // One step around edge ab of `cell` (a, b at local indices ia, ib) across
  // its facet k: returns the next cell, sets `across` to the remaining
  // vertex of that facet (the one to cross from in the next cell).
  static Index ring_step(const Triangulation& t, Index cell, int ia, int ib, int k, Index& across) {
    const Cell& c = t.cell(cell);
    across = c.v[6 - ia - ib - k];
    return c.n[k];
  }
};

// The numbers of finite edges, triangles and hull triangles of t from its
// cell counts alone, for callers that need no tables: each infinite cell
// holds one hull triangle, each finite cell 4 triangles of which the
// interior ones are counted twice, and the finite complex is a ball
// (Euler: V - E + F - C = 1).
struct SimplexCounts {
  std::size_t edges = 0, triangles = 0, hull_triangles = 0;
};
SimplexCounts count_simplices(const Triangulation& t);

class Simplices::EdgeTriangles {
public:
  class iterator {
  public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = Index;
    using difference_type = std::ptrdiff_t;
    using pointer = const Index*;
    using reference = Index;

    iterator() = default;
    Index operator*() const { return triangle_; }
    iterator& operator++() {
      step();
      skip_infinite();
      return *this;
    }
    iterator operator++(int) {
      const iterator old = *this;
      ++*this;
      return old;
    }
    bool operator==(const iterator& o) const { return cell_ == o.cell_; }  // kNone: the end

  private:
    friend class Simplices;
    const Simplices* s_ = nullptr;
    Index a_ = kNone, b_ = kNone, start_ = kNone, cell_ = kNone, across_ = kNone, triangle_ = kNone;
    int k_ = 0;  // facet of cell_ holding triangle_: the one opposite across_

    iterator(const Simplices& s, Index e)
        : s_(&s), a_(s.edges_[e][0]), b_(s.edges_[e][1]), start_(s.edge_cells_[e]), cell_(start_) {
      const auto& v = s.t_->cell(cell_).v;
      for (int j = 0; j < 4 && across_ == kNone; ++j)  // start across the first other vertex
        if (v[j] != a_ && v[j] != b_) across_ = v[j];
      arrive();
      skip_infinite();
    }
    void arrive() {
      k_ = s_->t_->index_of(cell_, across_);
      triangle_ = s_->cell_triangle(cell_, k_);
    }
    void step() {
      const Triangulation& t = *s_->t_;
      const Index next = ring_step(t, cell_, t.index_of(cell_, a_), t.index_of(cell_, b_), k_, across_);
      cell_ = next == start_ ? kNone : next;
      if (cell_ != kNone) arrive();
    }
    void skip_infinite() {  // the facet between two infinite cells
      while (cell_ != kNone && triangle_ == kNone) step();
    }
  };

  iterator begin() const { return begin_; }
  iterator end() const { return {}; }
  std::size_t size() const { return std::size_t(std::distance(begin(), end())); }

private:
  friend class Simplices;
  explicit EdgeTriangles(iterator begin) : begin_(begin) {}
  iterator begin_;
};

inline Simplices::EdgeTriangles Simplices::edge_triangles(Index e) const {
  return EdgeTriangles(EdgeTriangles::iterator(*this, e));
}

}  // namespace alpha
