// SPDX-License-Identifier: Apache-2.0
#include "alpha/persistent_basins.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>

#include "alpha/error.hpp"

namespace alpha {
namespace {

// The radius of an orthosphere of size alpha_sq, extended to negative sizes
// (imaginary radii) so that it stays increasing.
double signed_radius(double alpha_sq) { return std::copysign(std::sqrt(std::fabs(alpha_sq)), alpha_sq); }

}  // namespace

std::vector<std::vector<Index>> persistent_basins(const AlphaComplex& ac, Index level, std::span<const Index> cells,
                                                  const BasinMerging& merging) {
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  if (!(merging.threshold >= 0)) fail("persistent_basins: threshold must be >= 0", ErrorKind::Misuse);
  if (!merging.mass.empty() && merging.mass.size() != cells.size())
    fail("persistent_basins: " + std::to_string(merging.mass.size()) + " masses for " + std::to_string(cells.size()) +
         " cells", ErrorKind::Misuse);
  for (double m : merging.mass)
    if (!(m >= 0) || !std::isfinite(m)) fail("persistent_basins: a mass is not a finite value >= 0", ErrorKind::Misuse);
  if (!std::is_sorted(cells.begin(), cells.end())) fail("persistent_basins: cells not sorted", ErrorKind::Misuse);
  for (Index c : cells)
    if (c >= t.num_cells() || t.is_infinite(c) || ac.cell_entry(c) < level)
      fail("persistent_basins: cell " + std::to_string(c) + " is not an empty finite cell", ErrorKind::Misuse);
  const auto position = [&](Index c) -> Index {
    const auto it = std::lower_bound(cells.begin(), cells.end(), c);
    return it != cells.end() && *it == c ? Index(it - cells.begin()) : kNone;
  };

  // Saddle candidates: empty triangles between two of the cells, highest first.
  struct Passage {
    Index entry, triangle, a, b;  // a, b: positions in cells
  };
  std::vector<Passage> passages;
  for (Index k = 0; k < cells.size(); ++k)
    for (int i = 0; i < 4; ++i) {
      const Index n = position(t.cell(cells[k]).n[i]);
      const Index f = s.cell_triangle(cells[k], i);
      if (n == kNone || n < k || ac.triangle_interval(f).entry < level) continue;
      passages.push_back({ac.triangle_interval(f).entry, f, k, n});
    }
  std::sort(passages.begin(), passages.end(), [](const Passage& x, const Passage& y) {
    return std::tie(y.entry, x.triangle) < std::tie(x.entry, y.triangle);
  });

  // Union-find whose root is the component's largest cell (the elder),
  // with the component's mass at its root.
  std::vector<Index> parent(cells.size());
  std::vector<double> mass(merging.mass.begin(), merging.mass.end());
  mass.resize(cells.size(), 0.0);
  std::iota(parent.begin(), parent.end(), Index(0));
  const auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  const auto elder = [&](Index x, Index y) {  // larger entry rank, then larger id (as persistence_pairs)
    const Index ex = ac.cell_entry(cells[x]), ey = ac.cell_entry(cells[y]);
    return ex != ey ? ex > ey : cells[x] > cells[y];
  };
  // Spectrum values are exact roundings (costly): look up each rank once,
  // and none for a passage at the rank of the younger maximum (persistence
  // 0, the common case of a cell flowing into its neighbour).
  std::unordered_map<Index, double> radius_of_rank;
  const auto radius = [&](Index rank) {
    const auto [it, added] = radius_of_rank.try_emplace(rank, 0.0);
    if (added) it->second = signed_radius(ac.spectrum_value(rank));
    return it->second;
  };
  for (const Passage& p : passages) {
    Index a = find(p.a), b = find(p.b);
    if (a == b) continue;
    if (!elder(a, b)) std::swap(a, b);
    const Index top = ac.cell_entry(cells[b]);
    if (top != p.entry) {
      if (radius(top) - radius(p.entry) > merging.threshold) continue;
      if (mass[a] >= merging.min_mass && mass[b] >= merging.min_mass && mass[a] + mass[b] > merging.max_mass) continue;
    }
    parent[b] = a;
    mass[a] += mass[b];
  }

  std::vector<std::vector<Index>> basins;
  std::vector<Index> basin_of(cells.size(), kNone);
  for (Index k = 0; k < cells.size(); ++k) {
    Index& b = basin_of[find(k)];
    if (b == kNone) b = Index(basins.size()), basins.emplace_back();
    basins[b].push_back(cells[k]);
  }
  return basins;
}

}  // namespace alpha
