// SPDX-License-Identifier: Apache-2.0
// CGAL's sequential Delaunay triangulation (Epick, range insertion with its
// own spatial sort, as bench_triangulation) of a point file of "x y z"
// lines: the peer of bench/persistence_process.sh, timed in a process of
// its own as ours is. Prints the construction's wall seconds (reading
// excluded) and the number of finite cells.
//
// Usage: cgal_delaunay POINTS.xyz
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s POINTS.xyz\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1]);
  std::vector<K::Point_3> points;
  for (double x, y, z; in >> x >> y >> z;) points.emplace_back(x, y, z);
  if (!in.eof() || points.size() < 4) {
    std::fprintf(stderr, "%s: not a file of at least four \"x y z\" lines\n", argv[1]);
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  const CGAL::Delaunay_triangulation_3<K> t(points.begin(), points.end());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%.3f %zu\n", seconds, t.number_of_finite_cells());
}
