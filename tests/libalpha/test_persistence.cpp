// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "alpha/persistence.hpp"
#include "point_sets.hpp"

using namespace alpha;

namespace {

// Lower-star filtration of random vertex values: a simplex enters with its
// last vertex, so faces never come after cofaces.
FiltrationRanks lower_star(const Triangulation& t, const Simplices& s, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  FiltrationRanks r;
  r.vertex.resize(t.num_points());
  for (auto& v : r.vertex) v = rng() % 40;
  for (Index e = 0; e < s.num_edges(); ++e) r.edge.push_back(std::max(r.vertex[s.edge(e)[0]], r.vertex[s.edge(e)[1]]));
  for (Index f = 0; f < s.num_triangles(); ++f) {
    Index m = 0;
    for (Index v : s.triangle(f)) m = std::max(m, r.vertex[v]);
    r.triangle.push_back(m);
  }
  for (Index c = 0; c < t.num_cells(); ++c) {
    Index m = 0;
    for (Index v : t.cell(c).v) m = v == kInfinite ? kNever : std::max(m, r.vertex[v]);
    r.cell.push_back(m);
  }
  return r;
}

// Rank over Z/2 of a boundary matrix given as columns of row indices.
std::size_t rank_z2(std::vector<std::vector<char>> m) {
  std::size_t rank = 0;
  const std::size_t rows = m.empty() ? 0 : m[0].size();
  for (std::size_t row = 0; row < rows; ++row) {
    auto pivot = std::find_if(m.begin() + rank, m.end(), [&](const auto& c) { return c[row]; });
    if (pivot == m.end()) continue;
    std::swap(*pivot, m[rank]);
    for (std::size_t k = 0; k < m.size(); ++k)
      if (k != rank && m[k][row])
        for (std::size_t i = 0; i < rows; ++i) m[k][i] ^= m[rank][i];
    ++rank;
  }
  return rank;
}

// Betti numbers of the sub-complex at rank <= r by linear algebra.
std::array<long, 3> brute_betti(const Triangulation& t, const Simplices& s, const FiltrationRanks& f, Index r) {
  std::vector<Index> vs, es, ts, cs;
  for (Index v = 0; v < t.num_points(); ++v)
    if (f.vertex[v] <= r) vs.push_back(v);
  for (Index e = 0; e < s.num_edges(); ++e)
    if (f.edge[e] <= r) es.push_back(e);
  for (Index x = 0; x < s.num_triangles(); ++x)
    if (f.triangle[x] <= r) ts.push_back(x);
  for (Index c = 0; c < t.num_cells(); ++c)
    if (f.cell[c] <= r) cs.push_back(c);
  auto pos = [](const std::vector<Index>& list, Index x) {
    return std::size_t(std::lower_bound(list.begin(), list.end(), x) - list.begin());
  };
  std::vector<std::vector<char>> d1, d2, d3;
  for (Index e : es) {
    d1.emplace_back(vs.size(), 0);
    for (Index v : s.edge(e)) d1.back()[pos(vs, v)] = 1;
  }
  for (Index x : ts) {
    d2.emplace_back(es.size(), 0);
    for (Index e : s.triangle_edges(x)) d2.back()[pos(es, e)] = 1;
  }
  for (Index c : cs) {
    d3.emplace_back(ts.size(), 0);
    for (int i = 0; i < 4; ++i) d3.back()[pos(ts, s.cell_triangle(c, i))] = 1;
  }
  const long r1 = long(rank_z2(d1)), r2 = long(rank_z2(d2)), r3 = long(rank_z2(d3));
  return {long(vs.size()) - r1, long(es.size()) - r1 - r2, long(ts.size()) - r2 - r3};
}

}  // namespace

TEST_CASE("Persistence agrees with Z/2 linear algebra at every rank", "[persistence]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const Triangulation t(seed == 3 ? testing::grid_points(3) : testing::random_points(40, seed));
    const Simplices s(t);
    const FiltrationRanks f = lower_star(t, s, seed);
    const auto pairs = persistence_pairs(t, s, f);
    for (Index r = 0; r < 40; ++r) {
      const auto b = betti_at(pairs, r);
      const auto expected = brute_betti(t, s, f, r);
      INFO("seed " << seed << " rank " << r);
      CHECK(long(b[0]) == expected[0]);
      CHECK(long(b[1]) == expected[1]);
      CHECK(long(b[2]) == expected[2]);
    }
    // The whole triangulation is a ball: one component, no cycles or voids.
    CHECK(betti_at(pairs, 100) == std::array<std::size_t, 3>{1, 0, 0});
  }
}
