// SPDX-License-Identifier: Apache-2.0
#include "mesh/chord_offset.hpp"

#include <vector>

namespace alpha {

void offset_chords(SurfaceMesh& mesh, std::span<const Vec3> normals) {
  const std::size_t n = mesh.points.size();
  std::vector<double> bend(n, 0.0);
  std::vector<int> edges(n, 0);
  auto on_surface = [&](Index v) { return normals[v] != Vec3{}; };
  // Each edge once per triangle: twice in a closed mesh, alike for both ends.
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index v = t[k], w = t[(k + 1) % 3];
      if (!on_surface(v) || !on_surface(w)) continue;
      const double b = dot(normals[w] - normals[v], mesh.points[w] - mesh.points[v]);
      bend[v] += b, bend[w] += b;
      ++edges[v], ++edges[w];
    }
  for (std::size_t v = 0; v < n; ++v)
    if (edges[v] > 0) mesh.points[v] = mesh.points[v] + (bend[v] / (8.0 * edges[v])) * normals[v];
}

}  // namespace alpha
