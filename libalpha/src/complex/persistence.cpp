// SPDX-License-Identifier: Apache-2.0
#include "alpha/persistence.hpp"

#include <algorithm>
#include <numeric>
#include <span>
#include <thread>
#include <tuple>

#include "alpha/error.hpp"
#include "util/huge_pages.hpp"
#include "util/prefetch.hpp"
#include "util/radix_sort.hpp"

namespace alpha {
namespace {

// Union-find whose root keeps the component's elder member.
class ElderUnionFind {
public:
  explicit ElderUnionFind(std::size_t n) {
    assign_huge(parent_, n);
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  Index find(Index x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // Attaches root `young` below root `elder`.
  void merge(Index elder, Index young) { parent_[young] = elder; }
  void prefetch(Index x) const { alpha::prefetch(&parent_[x]); }

private:
  std::vector<Index> parent_;
};

// Filtration key: rank, then dimension, then id.
using Key = std::tuple<Index, int, Index>;

// The simplices of one dimension in filtration order (by rank, then id):
// their ids, sorted stably by rank (4 bytes a simplex while sorting, not 8
// with the ranks along: the triangles' would be 216 MB at 1e6 points).
std::vector<Index> filtration_order(const std::vector<Index>& rank) {
  std::vector<Index> ids;
  reserve_huge(ids, rank.size());
  for (Index i = 0; i < rank.size(); ++i) ids.push_back(i);
  radix_sort(std::span(ids), [&](Index i) { return rank[i]; });
  return ids;
}

// A column of the dimension-1 reduction, as a max-heap of edge keys (the
// filtration order's rank << 32 | id) with repeats: over Z/2, equal entries
// cancel in pairs when they reach the top. Adding a short column to a long
// one then costs the short one's length (times a logarithm), not the long
// one's.
class HeapColumn {
public:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
  void clear() { heap_.clear(); }
  void push(std::uint64_t x) {
    heap_.push_back(x);
    std::push_heap(heap_.begin(), heap_.end());
  }
  // The largest entry present an odd number of times, or kEmpty.
  std::uint64_t pivot() {
    while (!heap_.empty()) {
      const std::uint64_t top = heap_[0];
      const bool twice = (heap_.size() > 1 && heap_[1] == top) || (heap_.size() > 2 && heap_[2] == top);
      if (!twice) return top;
      pop(), pop();
    }
    return kEmpty;
  }
  // Removes and returns the pivot.
  std::uint64_t pop_pivot() {
    const std::uint64_t p = pivot();
    if (p != kEmpty) pop();
    return p;
  }

private:
  std::vector<std::uint64_t> heap_;
  void pop() {
    std::pop_heap(heap_.begin(), heap_.end());
    heap_.pop_back();
  }
};

// The pairs found so far, by dimension, as their two simplices (the death
// simplex kNone for a class that never dies): 8 bytes a pair instead of a
// PersistencePair's 20 while the reduction's arrays are alive; the ranks
// are read back at the end. Zero-length ones are dropped unless kept.
struct Pairs {
  bool keep_zero_length;
  // Each dimension's list on cache lines of its own: dimensions 0 and 2
  // grow side by side on threads.
  struct alignas(64) List : std::vector<std::array<Index, 2>> {};
  std::array<List, 3> simplices;
  void add(int dim, Index birth, Index death, Index birth_simplex, Index death_simplex) {
    if (keep_zero_length || birth != death) simplices[dim].push_back({birth_simplex, death_simplex});
  }
};

// Dimension 0: edges in filtration order join vertex components (elder
// rule). Returns, by edge id, 1 for the edges that create a cycle instead.
std::vector<char> vertex_pairs(const Triangulation& t, const Simplices& s, const FiltrationRanks& r, Pairs& pairs) {
  const std::vector<Index> edges = filtration_order(r.edge);
  ElderUnionFind vertices(t.num_points());
  auto vertex_key = [&](Index v) { return std::make_tuple(r.vertex[v], v); };
  std::vector<char> creates_cycle(edges.size(), 0);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (k + 2 * kAhead < edges.size()) prefetch(&s.edge(edges[k + 2 * kAhead]));
    if (k + kAhead < edges.size())
      for (const Index v : s.edge(edges[k + kAhead])) vertices.prefetch(v);
    const Index e = edges[k];
    Index a = vertices.find(s.edge(e)[0]), b = vertices.find(s.edge(e)[1]);
    if (a == b) {
      creates_cycle[e] = 1;
      continue;
    }
    if (vertex_key(a) > vertex_key(b)) std::swap(a, b);
    pairs.add(0, r.vertex[b], r.edge[e], b, e);
    vertices.merge(a, b);
  }
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex && vertices.find(v) == v) pairs.add(0, r.vertex[v], kNever, v, kNone);
  return creates_cycle;
}

// Dimension 2: in reverse filtration order, each triangle joins the
// complement components on its two sides (Alexander duality); node 0 is
// the outside, never filled. Returns the triangles that kill a 1-cycle
// instead, in filtration order.
std::vector<Index> complement_pairs(const Triangulation& t, const Simplices& s, const FiltrationRanks& r,
                                    Pairs& pairs) {
  const std::vector<Index> triangles = filtration_order(r.triangle);
  // Cell c is node c + 1; the infinite cells' nodes hang below the
  // outside's from the start, so that a triangle's nodes are known without
  // reading its cells.
  ElderUnionFind complement(t.num_cells() + 1);
  for (Index c = 0; c < t.num_cells(); ++c)
    if (t.is_infinite(c)) complement.merge(0, c + 1);
  // A complement component is born (in reverse) at its last-entering cell.
  auto cell_key = [&](Index n) { return n == 0 ? Key{kNever, 4, 0} : Key{r.cell[n - 1], 3, n - 1}; };
  // The complement is connected: every finite cell's node merges once.
  std::vector<Index> killers;
  reserve_huge(killers, triangles.size() - t.num_finite_cells());
  for (Index k = Index(triangles.size()); k-- > 0;) {
    if (k >= 3 * kAhead) prefetch(s.triangle_record(triangles[k - 3 * kAhead]));
    if (k >= 2 * kAhead) prefetch(&t.cell(s.triangle_cell(triangles[k - 2 * kAhead])));
    if (k >= kAhead)
      for (const Index c : s.triangle_cells(triangles[k - kAhead])) complement.prefetch(c + 1);
    const Index f = triangles[k];
    const auto cells = s.triangle_cells(f);
    Index a = complement.find(cells[0] + 1), b = complement.find(cells[1] + 1);
    if (a == b) {
      killers.push_back(f);
      continue;
    }
    if (cell_key(a) < cell_key(b)) std::swap(a, b);  // a: elder (enters later)
    pairs.add(2, r.triangle[f], r.cell[b - 1], f, b - 1);
    complement.merge(a, b);
  }
  std::reverse(killers.begin(), killers.end());
  return killers;
}

// Dimension 1: reduces the boundaries of the cycle-killing triangles,
// restricted to cycle-creating edges, in filtration order; an edge's key
// (rank << 32 | id) is its place in the filtration order. Columns are found
// through their pivots. Most columns need no addition: such a reduced
// column is its triangle's boundary, read again from the triangle; only
// the others are stored (their length, then their entries). Marks the
// paired edges 2 in creates_cycle.
void cycle_pairs(const Simplices& s, const FiltrationRanks& r, const std::vector<Index>& killers,
                 std::vector<char>& creates_cycle, Pairs& pairs) {
  auto key = [&](Index e) { return std::uint64_t(r.edge[e]) << 32 | e; };
  // By pivot edge: the reduced column, as its triangle's id or as kStored |
  // its offset in `stored`.
  constexpr Index kStored = Index(1) << 31;
  if (s.num_triangles() > kStored) fail("persistence: too many triangles for 31-bit ids", ErrorKind::LimitExceeded);
  std::vector<Index> reduced_at;
  assign_huge(reduced_at, s.num_edges(), kNone);
  std::vector<Index> stored;
  reserve_huge(stored, 2 * killers.size());  // address space: no copies as it grows
  auto for_each_entry = [&](Index column, auto visit) {
    if (column & kStored) {
      const Index* c = stored.data() + (column & ~kStored);
      std::for_each(c + 1, c + 1 + c[0], visit);
    } else {
      for (const Index e : s.triangle_edges(column))
        if (creates_cycle[e]) visit(e);
    }
  };
  HeapColumn column;
  for (std::size_t k = 0; k < killers.size(); ++k) {
    if (k + 2 * kAhead < killers.size()) prefetch(&s.triangle_edges(killers[k + 2 * kAhead]));
    if (k + kAhead < killers.size()) {
      prefetch(&r.triangle[killers[k + kAhead]]);
      for (const Index e : s.triangle_edges(killers[k + kAhead])) {
        prefetch(&creates_cycle[e]);
        prefetch(&r.edge[e]);
        prefetch(&reduced_at[e]);
      }
    }
    const Index f = killers[k];
    std::uint64_t p = HeapColumn::kEmpty;  // the largest entry's key
    for_each_entry(f, [&](Index e) {
      if (p == HeapColumn::kEmpty || key(e) > p) p = key(e);
    });
    Index at = f;
    if (p != HeapColumn::kEmpty && reduced_at[Index(p)] != kNone) {
      column.clear();
      for_each_entry(f, [&](Index e) { column.push(key(e)); });
      for (; p != HeapColumn::kEmpty && reduced_at[Index(p)] != kNone; p = column.pivot())
        for_each_entry(reduced_at[Index(p)], [&](Index e) { column.push(key(e)); });
      if (stored.size() >= kStored) fail("persistence: too many reduced entries for 31-bit offsets", ErrorKind::LimitExceeded);
      at = kStored | Index(stored.size());
      stored.push_back(0);
      for (std::uint64_t x = column.pop_pivot(); x != HeapColumn::kEmpty; x = column.pop_pivot())
        stored.push_back(Index(x)), ++stored[at & ~kStored];
    }
    if (p == HeapColumn::kEmpty) continue;  // cannot happen for a killing triangle
    const Index edge = Index(p);
    pairs.add(1, r.edge[edge], r.triangle[f], edge, f);
    creates_cycle[edge] = 2;
    reduced_at[edge] = at;
  }
}

void find_pairs(const Triangulation& t, const Simplices& s, const FiltrationRanks& r, Pairs& pairs, unsigned threads) {
  // One dimension at a time, each freeing its arrays before the next; on
  // threads, dimensions 0 and 2 side by side (they share no array).
  std::vector<char> creates_cycle;
  std::vector<Index> killers;
  {
    const auto dimension_0 = [&] { creates_cycle = vertex_pairs(t, s, r, pairs); };
    std::jthread side;
    if (threads > 1) side = std::jthread(dimension_0);
    else dimension_0();
    killers = complement_pairs(t, s, r, pairs);
  }  // joins the side thread
  cycle_pairs(s, r, killers, creates_cycle, pairs);
  for (Index e = 0; e < s.num_edges(); ++e)
    if (creates_cycle[e] == 1) pairs.add(1, r.edge[e], kNever, e, kNone);
}

}  // namespace

std::vector<PersistencePair> persistence_pairs(const Triangulation& t, const Simplices& s,
                                               const FiltrationRanks& r, bool keep_zero_length, unsigned threads) {
  Pairs pairs{keep_zero_length, {}};
  // Bounds on the pairs (of dimension 0 born at distinct vertices, 1 at
  // distinct edges, 2 dying at distinct cells), reserved as address space
  // (memory only as written): no copies of a growing vector.
  reserve_huge(pairs.simplices[0], t.num_points());
  reserve_huge(pairs.simplices[1], s.num_edges());
  reserve_huge(pairs.simplices[2], t.num_cells());
  find_pairs(t, s, r, pairs, threads);
  const std::array<const std::vector<Index>*, 4> ranks{&r.vertex, &r.edge, &r.triangle, &r.cell};
  std::vector<PersistencePair> list;
  reserve_huge(list, pairs.simplices[0].size() + pairs.simplices[1].size() + pairs.simplices[2].size());
  // By (dim, birth, death, birth_simplex), a total order (a simplex creates
  // at most one class): each dimension's block sorted in place (a buffer
  // would add to the peak memory).
  for (int dim = 0; dim < 3; ++dim) {
    const std::size_t first = list.size();
    const auto& found = pairs.simplices[dim];
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (k + kAhead < found.size()) {
        const auto [born, dies] = found[k + kAhead];
        prefetch(&(*ranks[dim])[born]);
        if (dies != kNone) prefetch(&(*ranks[dim + 1])[dies]);
      }
      const auto [born, dies] = found[k];
      list.push_back({dim, (*ranks[dim])[born], dies == kNone ? kNever : (*ranks[dim + 1])[dies], born, dies});
    }
    release(pairs.simplices[dim]);
    const auto block = std::span(list).subspan(first);
    radix_sort_in_place(block, [](const PersistencePair& p) { return std::uint64_t(p.birth) << 32 | p.death; },
                        [](const PersistencePair& p) { return p.birth_simplex; });
  }
  return list;
}

std::array<std::size_t, 3> betti_at(const std::vector<PersistencePair>& pairs, Index r) {
  std::array<std::size_t, 3> b{0, 0, 0};
  for (const PersistencePair& p : pairs)
    if (p.birth <= r && (p.death == kNever || p.death > r)) ++b[p.dim];
  return b;
}

}  // namespace alpha
