// SPDX-License-Identifier: Apache-2.0
#include "alpha/persistence.hpp"

#include <algorithm>
#include <bit>
#include <numeric>
#include <span>
#include <tuple>

#include "alpha/error.hpp"
#include "huge_pages.hpp"
#include "radix_sort.hpp"

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

private:
  std::vector<Index> parent_;
};

// Filtration key: rank, then dimension, then id.
using Key = std::tuple<Index, int, Index>;

// The simplices of one dimension in filtration order (by rank, then id),
// each as rank << 32 | id: the ranks come along at no cost.
std::vector<std::uint64_t> filtration_order(const std::vector<Index>& rank) {
  std::vector<std::uint64_t> keyed;
  reserve_huge(keyed, rank.size());
  for (Index i = 0; i < rank.size(); ++i) keyed.push_back(std::uint64_t(rank[i]) << 32 | i);
  radix_sort(keyed, [](std::uint64_t k) { return std::uint32_t(k >> 32); });  // stable: ids stay increasing
  return keyed;
}
Index id_of(std::uint64_t keyed) { return Index(keyed); }
Index rank_of(std::uint64_t keyed) { return Index(keyed >> 32); }

// A set of positions 0..n-1, with the rank of a member (how many members
// precede it) in constant time once indexed.
class RankedBits {
public:
  explicit RankedBits(std::size_t n) : bits_((n + 63) / 64, 0) {}
  void set(std::size_t k) { bits_[k >> 6] |= std::uint64_t(1) << (k & 63); }
  bool test(std::size_t k) const { return bits_[k >> 6] >> (k & 63) & 1; }
  void index() {
    before_.resize(bits_.size() + 1);
    before_[0] = 0;
    for (std::size_t w = 0; w < bits_.size(); ++w) before_[w + 1] = before_[w] + Index(std::popcount(bits_[w]));
  }
  Index rank(std::size_t k) const {
    return before_[k >> 6] + Index(std::popcount(bits_[k >> 6] & ((std::uint64_t(1) << (k & 63)) - 1)));
  }
  Index count() const { return before_.back(); }

private:
  std::vector<std::uint64_t> bits_;
  std::vector<Index> before_;  // members before each word
};

// A column of the dimension-1 reduction, as a max-heap of edge positions
// with repeats: over Z/2, equal entries cancel in pairs when they reach the
// top. Adding a short column to a long one then costs the short one's
// length (times a logarithm), not the long one's.
class HeapColumn {
public:
  void clear() { heap_.clear(); }
  void push(Index x) {
    heap_.push_back(x);
    std::push_heap(heap_.begin(), heap_.end());
  }
  // The largest entry present an odd number of times, or kNone.
  Index pivot() {
    while (!heap_.empty()) {
      const Index top = heap_[0];
      const bool twice = (heap_.size() > 1 && heap_[1] == top) || (heap_.size() > 2 && heap_[2] == top);
      if (!twice) return top;
      pop(), pop();
    }
    return kNone;
  }
  // Removes and returns the pivot.
  Index pop_pivot() {
    const Index p = pivot();
    if (p != kNone) pop();
    return p;
  }

private:
  std::vector<Index> heap_;
  void pop() {
    std::pop_heap(heap_.begin(), heap_.end());
    heap_.pop_back();
  }
};

// The pairs found so far; zero-length ones are dropped unless kept.
struct Pairs {
  bool keep_zero_length;
  std::vector<PersistencePair> list;
  void add(const PersistencePair& p) {
    if (keep_zero_length || p.birth != p.death) list.push_back(p);
  }
};

// Dimension 0: edges in filtration order join vertex components (elder
// rule). Returns, by edge id, 1 for the edges that create a cycle instead.
std::vector<char> vertex_pairs(const Triangulation& t, const Simplices& s, const FiltrationRanks& r,
                               const std::vector<std::uint64_t>& edges, Pairs& pairs) {
  ElderUnionFind vertices(t.num_points());
  auto vertex_key = [&](Index v) { return std::make_tuple(r.vertex[v], v); };
  std::vector<char> creates_cycle(edges.size(), 0);
  for (const std::uint64_t k : edges) {
    const Index e = id_of(k);
    Index a = vertices.find(s.edge(e)[0]), b = vertices.find(s.edge(e)[1]);
    if (a == b) {
      creates_cycle[e] = 1;
      continue;
    }
    if (vertex_key(a) > vertex_key(b)) std::swap(a, b);
    pairs.add({0, r.vertex[b], rank_of(k), b, e});
    vertices.merge(a, b);
  }
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex && vertices.find(v) == v) pairs.add({0, r.vertex[v], kNever, v, kNone});
  return creates_cycle;
}

// Dimension 2: in reverse filtration order, each triangle joins the
// complement components on its two sides (Alexander duality); node 0 is
// the outside, never filled. Returns the positions of the triangles that
// kill a 1-cycle instead. The sides are gathered by position first, walking
// the triangles in id order (local), not in filtration order (random).
RankedBits complement_pairs(const Triangulation& t, const Simplices& s, const FiltrationRanks& r,
                            const std::vector<std::uint64_t>& triangles, const std::vector<Index>& position,
                            Pairs& pairs) {
  const std::size_t nf = triangles.size();
  std::vector<std::array<Index, 2>> sides;
  assign_huge(sides, nf);
  for (Index f = 0; f < nf; ++f)
    for (int i = 0; i < 2; ++i) {
      const Index c = s.triangle_cells(f)[i];
      sides[position[f]][i] = t.is_infinite(c) ? Index(0) : c + 1;
    }
  ElderUnionFind complement(t.num_cells() + 1);
  // A complement component is born (in reverse) at its last-entering cell.
  auto cell_key = [&](Index n) { return n == 0 ? Key{kNever, 4, 0} : Key{r.cell[n - 1], 3, n - 1}; };
  RankedBits kills(nf);
  for (Index k = Index(nf); k-- > 0;) {
    Index a = complement.find(sides[k][0]), b = complement.find(sides[k][1]);
    if (a == b) {
      kills.set(k);
      continue;
    }
    if (cell_key(a) < cell_key(b)) std::swap(a, b);  // a: elder (enters later)
    pairs.add({2, rank_of(triangles[k]), r.cell[b - 1], id_of(triangles[k]), b - 1});
    complement.merge(a, b);
  }
  kills.index();
  return kills;
}

// Dimension 1: reduces the boundaries of the cycle-killing triangles,
// restricted to cycle-creating edges, in filtration order. Columns hold edge
// positions and are found through their pivots. Most columns need no
// addition and most reduced ones have at most three entries: a reduced
// column stays in its triangle's boundary slot (kNone pads), and only a
// longer one goes to `longer` (its length, then its entries), the slot then
// holding kLonger and the offset. Marks the paired edges 2 in creates_cycle.
void cycle_pairs(const Simplices& s, const std::vector<std::uint64_t>& edges,
                 const std::vector<std::uint64_t>& triangles, std::vector<Index> position, const RankedBits& kills,
                 std::vector<char>& creates_cycle, Pairs& pairs) {
  std::vector<Index> edge_position;
  assign_huge(edge_position, edges.size());
  for (Index k = 0; k < edges.size(); ++k) edge_position[id_of(edges[k])] = k;
  // The boundaries, by killing triangle in filtration order.
  using Slot = std::array<Index, 3>;
  std::vector<Slot> slots;
  assign_huge(slots, kills.count());
  for (Index f = 0; f < triangles.size(); ++f) {
    if (!kills.test(position[f])) continue;
    Slot& b = slots[kills.rank(position[f])];
    for (int i = 0; i < 3; ++i) {
      const Index e = s.triangle_edges(f)[i];
      b[i] = creates_cycle[e] ? edge_position[e] : kNone;
    }
  }
  // (Assigning {} would keep the capacity.)
  position = std::vector<Index>();
  edge_position = std::vector<Index>();
  constexpr Index kLonger = kNone - 1;  // above any edge position
  std::vector<Index> reduced_at;        // by pivot position: the slot
  assign_huge(reduced_at, edges.size(), kNone);
  std::vector<Index> longer;
  auto column_of = [&](const Slot& b) {
    return b[0] == kLonger ? std::span<const Index>(longer.data() + b[1] + 1, longer[b[1]]) : std::span<const Index>(b);
  };
  HeapColumn column;
  std::vector<Index> reduced;
  Index next = 0;  // the next killing triangle's slot
  for (Index k = 0; k < triangles.size(); ++k) {
    if (!kills.test(k)) continue;
    Slot& b = slots[next++];
    Index p = kNone;  // the largest entry
    for (const Index e : b)
      if (e != kNone && (p == kNone || e > p)) p = e;
    if (p != kNone && reduced_at[p] != kNone) {
      column.clear();
      for (const Index e : b)
        if (e != kNone) column.push(e);
      for (; p != kNone && reduced_at[p] != kNone; p = column.pivot())
        for (const Index e : column_of(slots[reduced_at[p]]))
          if (e != kNone) column.push(e);
      reduced.clear();
      for (Index x = column.pop_pivot(); x != kNone; x = column.pop_pivot()) reduced.push_back(x);
      b.fill(kNone);
      if (reduced.size() <= b.size()) {
        std::copy(reduced.begin(), reduced.end(), b.begin());
      } else {
        b = {kLonger, Index(longer.size()), kNone};
        longer.push_back(Index(reduced.size()));
        longer.insert(longer.end(), reduced.begin(), reduced.end());
        if (longer.size() >= kLonger) fail("persistence: too many reduced entries for 32-bit offsets", ErrorKind::LimitExceeded);
      }
    }
    if (p == kNone) continue;  // cannot happen for a killing triangle
    const std::uint64_t edge = edges[p];
    pairs.add({1, rank_of(edge), rank_of(triangles[k]), id_of(edge), id_of(triangles[k])});
    creates_cycle[id_of(edge)] = 2;
    reduced_at[p] = next - 1;
  }
}

void find_pairs(const Triangulation& t, const Simplices& s, const FiltrationRanks& r, Pairs& pairs) {
  const std::vector<std::uint64_t> edges = filtration_order(r.edge);
  std::vector<char> creates_cycle = vertex_pairs(t, s, r, edges, pairs);
  const std::vector<std::uint64_t> triangles = filtration_order(r.triangle);
  std::vector<Index> position;  // of each triangle in filtration order
  assign_huge(position, triangles.size());
  for (Index k = 0; k < triangles.size(); ++k) position[id_of(triangles[k])] = k;
  const RankedBits kills = complement_pairs(t, s, r, triangles, position, pairs);
  cycle_pairs(s, edges, triangles, std::move(position), kills, creates_cycle, pairs);
  for (Index e = 0; e < edges.size(); ++e)
    if (creates_cycle[e] == 1) pairs.add({1, r.edge[e], kNever, e, kNone});
}

}  // namespace

std::vector<PersistencePair> persistence_pairs(const Triangulation& t, const Simplices& s,
                                               const FiltrationRanks& r, bool keep_zero_length) {
  Pairs pairs{keep_zero_length, {}};
  // A bound on the pairs (of dimension 0 born at distinct vertices, 1 at
  // distinct edges, 2 dying at distinct cells), reserved as address space
  // (memory only as written): no copies of a growing vector.
  reserve_huge(pairs.list, t.num_points() + s.num_edges() + t.num_cells());
  find_pairs(t, s, r, pairs);
  // By (dim, birth, death, birth_simplex), a total order (a simplex creates
  // at most one class): least significant key first, each pass stable. A
  // comparison sort spent more than the pairs' computation in this.
  radix_sort(pairs.list, [](const PersistencePair& p) { return p.birth_simplex; });
  radix_sort(pairs.list, [](const PersistencePair& p) { return std::uint64_t(p.birth) << 32 | p.death; });
  radix_sort(pairs.list, [](const PersistencePair& p) { return unsigned(p.dim); });
  pairs.list.shrink_to_fit();
  return std::move(pairs.list);
}

std::array<std::size_t, 3> betti_at(const std::vector<PersistencePair>& pairs, Index r) {
  std::array<std::size_t, 3> b{0, 0, 0};
  for (const PersistencePair& p : pairs)
    if (p.birth <= r && (p.death == kNever || p.death > r)) ++b[p.dim];
  return b;
}

}  // namespace alpha
