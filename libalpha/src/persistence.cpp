#include "alpha/persistence.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace alpha {
namespace {

// Union-find whose root keeps the component's elder member.
class ElderUnionFind {
public:
  explicit ElderUnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
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

}  // namespace

std::vector<PersistencePair> persistence_pairs(const Triangulation& t, const Simplices& s,
                                               const FiltrationRanks& r, bool keep_zero_length) {
  std::vector<PersistencePair> pairs;
  const std::size_t ne = s.num_edges(), nf = s.num_triangles();

  // Dimension 0: edges in filtration order join vertex components.
  std::vector<Index> edges(ne);
  std::iota(edges.begin(), edges.end(), 0);
  std::sort(edges.begin(), edges.end(), [&](Index a, Index b) {
    return std::tie(r.edge[a], a) < std::tie(r.edge[b], b);
  });
  ElderUnionFind vertices(t.num_points());
  auto vertex_key = [&](Index v) { return std::make_tuple(r.vertex[v], v); };
  std::vector<char> edge_creates_cycle(ne, 0);
  for (Index e : edges) {
    Index a = vertices.find(s.edge(e)[0]), b = vertices.find(s.edge(e)[1]);
    if (a == b) {
      edge_creates_cycle[e] = 1;
      continue;
    }
    if (vertex_key(a) > vertex_key(b)) std::swap(a, b);
    pairs.push_back({0, r.vertex[b], r.edge[e], b, e});
    vertices.merge(a, b);
  }
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex && vertices.find(v) == v)
      pairs.push_back({0, r.vertex[v], kNever, v, kNone});

  // Dimension 2: in reverse order, each triangle joins the complement
  // components on its two sides; node 0 is the outside (never filled).
  std::vector<Index> triangles(nf);
  std::iota(triangles.begin(), triangles.end(), 0);
  std::sort(triangles.begin(), triangles.end(), [&](Index a, Index b) {
    return std::tie(r.triangle[a], a) < std::tie(r.triangle[b], b);
  });
  ElderUnionFind complement(t.num_cells() + 1);
  auto node = [&](Index c) { return t.is_infinite(c) ? Index(0) : c + 1; };
  // A complement component is born (in reverse) at its last-entering cell.
  auto cell_key = [&](Index n) { return n == 0 ? Key{kNever, 4, 0} : Key{r.cell[n - 1], 3, n - 1}; };
  std::vector<char> triangle_kills_cycle(nf, 0);
  for (auto it = triangles.rbegin(); it != triangles.rend(); ++it) {
    const Index f = *it;
    Index a = complement.find(node(s.triangle_cells(f)[0])), b = complement.find(node(s.triangle_cells(f)[1]));
    if (a == b) {
      triangle_kills_cycle[f] = 1;
      continue;
    }
    if (cell_key(a) < cell_key(b)) std::swap(a, b);  // a: elder (enters later)
    pairs.push_back({2, r.triangle[f], r.cell[b - 1], f, b - 1});
    complement.merge(a, b);
  }

  // Dimension 1: reduce the cycle-killing triangles' boundaries, restricted
  // to cycle-creating edges, in filtration order. Columns hold edges sorted
  // by decreasing filtration position; the pivot is the first.
  std::vector<Index> edge_position(ne);
  for (Index k = 0; k < ne; ++k) edge_position[edges[k]] = k;
  std::vector<std::vector<Index>> reduced(ne);  // by pivot edge position
  std::vector<Index> column, sum;
  for (Index f : triangles) {
    if (!triangle_kills_cycle[f]) continue;
    column.clear();
    for (Index e : s.triangle_edges(f))
      if (edge_creates_cycle[e]) column.push_back(edge_position[e]);
    std::sort(column.begin(), column.end(), std::greater<>());
    while (!column.empty() && !reduced[column.front()].empty()) {
      const auto& other = reduced[column.front()];
      sum.clear();
      std::set_symmetric_difference(column.begin(), column.end(), other.begin(), other.end(),
                                    std::back_inserter(sum), std::greater<>());
      column.swap(sum);
    }
    if (column.empty()) continue;  // cannot happen for a killing triangle
    const Index e = edges[column.front()];
    pairs.push_back({1, r.edge[e], r.triangle[f], e, f});
    reduced[column.front()] = column;
    edge_creates_cycle[e] = 2;  // paired
  }
  for (Index e = 0; e < ne; ++e)
    if (edge_creates_cycle[e] == 1) pairs.push_back({1, r.edge[e], kNever, e, kNone});

  if (!keep_zero_length)
    std::erase_if(pairs, [](const PersistencePair& p) { return p.birth == p.death; });
  std::sort(pairs.begin(), pairs.end(), [](const PersistencePair& a, const PersistencePair& b) {
    return std::tie(a.dim, a.birth, a.death, a.birth_simplex) < std::tie(b.dim, b.birth, b.death, b.birth_simplex);
  });
  return pairs;
}

std::array<std::size_t, 3> betti_at(const std::vector<PersistencePair>& pairs, Index r) {
  std::array<std::size_t, 3> b{0, 0, 0};
  for (const PersistencePair& p : pairs)
    if (p.birth <= r && (p.death == kNever || p.death > r)) ++b[p.dim];
  return b;
}

}  // namespace alpha
