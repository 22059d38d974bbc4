// SPDX-License-Identifier: Apache-2.0
// Dynamic update against rebuilding, in one run: random points moved by a
// fraction of their mean nearest-neighbour distance, the time of
// Triangulation::move_points over that of building the moved points
// afresh (medians). Usage: bench_dynamic_update [reps_1e5 reps_1e6]. See README.md.
#include <time.h>
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

// CPU time of this thread: the shared machine's load changes wall time far more.
double seconds_of(auto&& work) {
  const auto now = [] {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  };
  const double t0 = now();
  work();
  return now() - t0;
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
  std::printf("%8s %6s %6s %4s %10s %10s %7s %10s %8s\n", "n", "moved", "by", "reps", "build s", "update s", "ratio",
              "relocated", "rebuilt");
  struct Move {
    double share, by;  // of the points; in mean nearest-neighbour distances
  };
  for (const std::size_t n : {std::size_t(100000), std::size_t(1000000)}) {
    const std::vector<Vec3> start = testing::random_points(n, 1);
    const alpha::Triangulation t0(start);
    const double nn = mean_nearest(t0);
    const int reps = n > 100000 ? reps_large : reps_small;
    for (const Move move : {Move{1, 0.05}, Move{1, 0.1}, Move{1, 0.2}, Move{1, 0.5}, Move{0.01, 0.5}, Move{0.01, 2}}) {
      std::vector<double> build, update;
      double relocated = 0;
      int rebuilt = 0;
      for (int r = 0; r < reps; ++r) {
        const std::vector<Vec3> moved = testing::jitter(start, move.by * nn, 100 + r);
        std::vector<Index> ids;
        std::vector<Vec3> to, all = start;
        const std::size_t every = std::size_t(1 / move.share);
        for (Index i = Index(r); i < n; i += Index(every)) ids.push_back(i), to.push_back(moved[i]), all[i] = moved[i];
        alpha::Triangulation t = t0;  // not timed
        alpha::UpdateReport report;
        update.push_back(seconds_of([&] { report = t.move_points(ids, to); }));
        relocated = double(report.relocated) / double(n);
        rebuilt += report.rebuilt;
        build.push_back(seconds_of([&] { alpha::Triangulation fresh(std::move(all)); }));
      }
      const double b = bench::median(build), u = bench::median(update);
      std::printf("%8zu %5.0f%% %6.2f %4d %10.3f %10.3f %7.2f %9.2f%% %5d/%d\n", n, 100 * move.share, move.by, reps, b,
                  u, u / b, 100 * relocated, rebuilt, reps);
      std::fflush(stdout);
    }
  }
}
