// SPDX-License-Identifier: Apache-2.0
#include "alpha/validation.hpp"

#include <algorithm>

namespace alpha {
namespace {
constexpr std::size_t kMaxProblems = 10;

std::string cell_name(Index c) { return "cell " + std::to_string(c); }
}  // namespace

void ValidationReport::add(std::string problem) {
  valid = false;
  if (problems.size() < kMaxProblems) problems.push_back(std::move(problem));
}

ValidationReport validate(const Triangulation& t) {
  ValidationReport report;
  Kernel kernel = t.kernel();
  std::vector<char> used(t.num_points(), 0);
  for (Index c = 0; c < t.num_cells(); ++c) {
    const Cell& cell = t.cell(c);
    for (Index v : cell.v) {
      if (v == kInfinite) continue;
      if (v >= t.num_points() || t.status(v) != PointStatus::vertex)
        report.add(cell_name(c) + " uses point " + std::to_string(v) + " which is not a vertex");
      else
        used[v] = 1;
    }
    const int inf = t.infinite_position(c);
    if (inf < 0 && kernel.orient3d(cell.v[0], cell.v[1], cell.v[2], cell.v[3]) <= 0)
      report.add(cell_name(c) + " is not positively oriented");
    for (int i = 0; i < 4; ++i) {
      const Index n = cell.n[i];
      if (n >= t.num_cells()) {
        report.add(cell_name(c) + " has no neighbour " + std::to_string(i));
        continue;
      }
      const int m = t.mirror_index(c, i);
      if (m < 0) {
        report.add(cell_name(c) + " is not a neighbour of its neighbour " + std::to_string(n));
        continue;
      }
      for (int k = 0; k < 4; ++k)
        if (k != i && t.index_of(n, cell.v[k]) < 0)
          report.add(cell_name(c) + " and " + cell_name(n) + " do not share a facet");
      // Local regularity: the far vertex of the neighbour does not conflict.
      const Index q = t.cell(n).v[m];
      if (q == kInfinite) continue;
      bool conflict;
      if (inf >= 0) {
        const auto& f = kFacet[inf];
        conflict = kernel.hull_conflict(cell.v[f[0]], cell.v[f[1]], cell.v[f[2]], q);
      } else {
        conflict = kernel.power_conflict(cell.v[0], cell.v[1], cell.v[2], cell.v[3], q);
      }
      if (conflict)
        report.add(cell_name(c) + (inf >= 0 ? ": hull is not convex at its facet" : ": facet " + std::to_string(i) +
                                                                                       " is not locally regular"));
    }
  }
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex && !used[v])
      report.add("vertex " + std::to_string(v) + " is in no cell");
  return report;
}

}  // namespace alpha
