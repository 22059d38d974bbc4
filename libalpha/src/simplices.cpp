#include "alpha/simplices.hpp"

#include <algorithm>

namespace alpha {
namespace {

// Compressed rows from per-row counts: start[i]..start[i+1].
std::vector<std::size_t> offsets(const std::vector<std::size_t>& counts) {
  std::vector<std::size_t> start(counts.size() + 1, 0);
  for (std::size_t i = 0; i < counts.size(); ++i) start[i + 1] = start[i] + counts[i];
  return start;
}

}  // namespace

Simplices::Simplices(const Triangulation& t) : t_(&t) {
  const std::size_t np = t.num_points();
  // Edges: for each vertex u, its neighbours v > u found in its cells.
  std::vector<std::size_t> cell_count(np, 0);
  for (const Cell& c : t.cells())
    for (Index v : c.v)
      if (v != kInfinite) ++cell_count[v];
  std::vector<std::size_t> cell_start = offsets(cell_count);
  std::vector<Index> vertex_cells(cell_start.back());
  {
    std::vector<std::size_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (Index c = 0; c < t.num_cells(); ++c)
      for (Index v : t.cell(c).v)
        if (v != kInfinite) vertex_cells[fill[v]++] = c;
  }
  lower_edge_start_.assign(np + 1, 0);
  std::vector<Index> around;
  for (Index u = 0; u < np; ++u) {
    around.clear();
    for (std::size_t k = cell_start[u]; k < cell_start[u + 1]; ++k)
      for (Index v : t.cell(vertex_cells[k]).v)
        if (v != kInfinite && v > u) around.push_back(v);
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (Index v : around) edges_.push_back({u, v});
    lower_edge_start_[u + 1] = edges_.size();
  }
  // Triangles: each finite facet once, from the cell with the smaller id.
  cell_triangles_.assign(4 * t.num_cells(), kNone);
  for (Index c = 0; c < t.num_cells(); ++c) {
    const Cell& cell = t.cell(c);
    for (int i = 0; i < 4; ++i) {
      const Index n = cell.n[i];
      if (n < c) continue;
      const auto& f = kFacet[i];
      const std::array<Index, 3> tri{cell.v[f[0]], cell.v[f[1]], cell.v[f[2]]};
      if (std::find(tri.begin(), tri.end(), kInfinite) != tri.end()) continue;
      const Index id = static_cast<Index>(triangles_.size());
      triangles_.push_back(tri);
      triangle_cells_.push_back({c, n});
      triangle_edges_.push_back({find_edge(tri[1], tri[2]), find_edge(tri[0], tri[2]), find_edge(tri[0], tri[1])});
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
  if (u > v) std::swap(u, v);
  const auto first = edges_.begin() + lower_edge_start_[u], last = edges_.begin() + lower_edge_start_[u + 1];
  const auto it = std::lower_bound(first, last, v, [](const std::array<Index, 2>& e, Index x) { return e[1] < x; });
  return it != last && (*it)[1] == v ? static_cast<Index>(it - edges_.begin()) : kNone;
}

bool Simplices::on_hull(Index f) const {
  return t_->is_infinite(triangle_cells_[f][0]) || t_->is_infinite(triangle_cells_[f][1]);
}

std::size_t Simplices::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(edges_) + bytes(triangles_) + bytes(triangle_edges_) + bytes(triangle_cells_) + bytes(cell_triangles_) +
         bytes(vertex_edge_start_) + bytes(edge_triangle_start_) + bytes(vertex_edges_) + bytes(edge_triangles_) +
         bytes(lower_edge_start_);
}

}  // namespace alpha
