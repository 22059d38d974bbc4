// SPDX-License-Identifier: Apache-2.0
// Dynamic update against rebuilding, in one run: random points moved by a
// fraction of their mean nearest-neighbour distance, the time of
// Triangulation::move_points over that of building the moved points
// afresh (medians). Usage: bench_dynamic_update [reps_1e5 reps_1e6]. See README.md.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "alpha/triangulation.hpp"
#include "median.hpp"
#include "point_sets.hpp"

namespace {

using alpha::Index;
using alpha::Vec3;

double seconds_of(auto&& work) {
  const auto t0 = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The nearest neighbour is a Delaunay neighbour: the shortest edge at each vertex.
double mean_nearest(const alpha::Triangulation& t) {
  std::vector<double> best(t.num_points(), INFINITY);
  for (const alpha::Cell& c : t.cells())
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Index a = c.v[i], b = c.v[j];
        if (a == alpha::kInfinite || b == alpha::kInfinite) continue;
        const double d = alpha::norm(t.point(a) - t.point(b));
        best[a] = std::min(best[a], d), best[b] = std::min(best[b], d);
      }
  double sum = 0;
  for (double d : best) sum += d;
  return sum / double(best.size());
}

}  // namespace

int main(int argc, char** argv) {
  const int reps_small = argc > 1 ? std::atoi(argv[1]) : 5, reps_large = argc > 2 ? std::atoi(argv[2]) : 3;
  std::printf("%8s %6s %4s %10s %10s %7s %10s\n", "n", "move", "reps", "build s", "update s", "ratio", "relocated");
  for (const std::size_t n : {std::size_t(100000), std::size_t(1000000)}) {
    const std::vector<Vec3> start = testing::random_points(n, 1);
    const alpha::Triangulation t0(start);
    const double nn = mean_nearest(t0);
    const int reps = n > 100000 ? reps_large : reps_small;
    for (const double move : {0.05, 0.1, 0.2, 0.5, 1.0}) {
      if (n > 100000 && move == 1.0) continue;
      std::vector<double> build, update;
      double relocated = 0;
      for (int r = 0; r < reps; ++r) {
        const std::vector<Vec3> to = testing::jitter(start, move * nn, 100 + r);
        alpha::Triangulation t = t0;  // not timed
        alpha::UpdateReport report;
        update.push_back(seconds_of([&] { report = t.move_points(to); }));
        relocated = double(report.relocated) / double(n);
        std::vector<Vec3> copy = to;
        build.push_back(seconds_of([&] { alpha::Triangulation fresh(std::move(copy)); }));
      }
      const double b = bench::median(build), u = bench::median(update);
      std::printf("%8zu %6.2f %4d %10.3f %10.3f %7.2f %9.1f%%\n", n, move, reps, b, u, u / b, 100 * relocated);
      std::fflush(stdout);
    }
  }
}
