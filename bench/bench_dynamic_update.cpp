// SPDX-License-Identifier: Apache-2.0
// Dynamic update against rebuilding, in one run: the time of
// Triangulation::move_points over that of building the moved points
// afresh (medians), and that of the AlphaComplex recomputed on top. Either
// random points moved by a fraction of their mean nearest-neighbour
// distance, or the frames of a trajectory (a multi-frame .gro file, as
// dynamic_update_md.sh writes: atoms weighted by their radius squared).
// Usage: bench_dynamic_update [reps_1e5 reps_1e6 [N: that size, small moves]] | --frames FILE.gro [reps]
// | --one N SHARE BY (one update, e.g. under callgrind). See README.md.
#include <time.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
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
  double sum = 0, count = 0;
  for (double d : best)
    if (std::isfinite(d)) sum += d, ++count;
  return sum / count;
}

// With `only` (a point count), that size alone, the small moves (up to 0.2 NN) and no complex.
void random_sets(int reps_small, int reps_large, std::size_t only) {
  std::printf("%8s %6s %6s %4s %9s %9s %7s %10s %8s %8s %7s %7s\n", "n", "moved", "by", "reps", "build s", "update s",
              "ratio", "relocated", "flips/n", "rebuilt", "complex", "c/build");
  struct Move {
    double share, by;  // of the points; in mean nearest-neighbour distances
  };
  for (const std::size_t n : {std::size_t(100000), std::size_t(1000000)}) {
    if (only && n != only) continue;
    const std::vector<Vec3> start = testing::random_points(n, 1);
    const alpha::Triangulation t0(start);
    const double nn = mean_nearest(t0);
    const int reps = n > 100000 ? reps_large : reps_small;
    std::vector<double> complex;
    for (int r = 0; r < (only ? 1 : reps); ++r)
      complex.push_back(only ? 0.0 : seconds_of([&] { alpha::AlphaComplex k(t0); }));
    for (const Move move : {Move{1, 0.05}, Move{1, 0.2}, Move{1, 0.5}, Move{0.1, 0.05}, Move{0.1, 0.2},
                            Move{0.1, 0.5}, Move{0.01, 0.05}, Move{0.01, 0.2}, Move{0.01, 0.5}, Move{0.01, 2}}) {
      if (only && move.by > 0.2) continue;
      std::vector<double> build, update;
      double relocated = 0, flips = 0;
      int rebuilt = 0;
      alpha::Triangulation t(start);  // t0's cells, with a build's spare capacity
      for (int r = 0; r < reps; ++r) {
        const std::vector<Vec3> moved = testing::jitter(start, move.by * nn, 100 + r);
        std::vector<Index> ids;
        std::vector<Vec3> to, all = start;
        const std::size_t every = std::size_t(1 / move.share);
        for (Index i = Index(r); i < n; i += Index(every)) ids.push_back(i), to.push_back(moved[i]), all[i] = moved[i];
        t = t0;  // not timed; into t's storage, as an update in place frame after frame would find it
        alpha::UpdateReport report;
        update.push_back(seconds_of([&] { report = t.move_points(ids, to); }));
        relocated = double(report.relocated) / double(n);
        flips = double(report.flips23 + report.flips32 + report.flips41) / double(n);
        rebuilt += report.rebuilt;
        build.push_back(seconds_of([&] { alpha::Triangulation fresh(std::move(all)); }));
      }
      const double b = bench::median(build), u = bench::median(update), k = bench::median(complex);
      std::printf("%8zu %5.0f%% %6.2f %4d %9.3f %9.3f %7.2f %9.2f%% %8.3f %6d/%d %7.3f %7.2f\n", n, 100 * move.share,
                  move.by, reps, b, u, u / b, 100 * relocated, flips, rebuilt, reps, k, k / b);
      std::fflush(stdout);
    }
  }
}

// Radius (A) by the atom name's first letter; coordinates of .gro are in nm.
double radius_of(const std::string& name) {
  const std::size_t k = name.find_first_not_of(' ');
  switch (k == std::string::npos ? ' ' : name[k]) {
    case 'H': return 1.1;
    case 'N': return 1.55;
    case 'O': return 1.52;
    case 'S': return 1.8;
    default: return 1.7;
  }
}

struct Frame {
  std::vector<Vec3> points;
  std::vector<double> weights;
};

std::vector<Frame> read_gro(const char* path) {
  std::ifstream in(path);
  std::vector<Frame> frames;
  std::string line;
  while (std::getline(in, line) && std::getline(in, line)) {
    const std::size_t atoms = std::stoul(line);
    Frame f;
    for (std::size_t i = 0; i < atoms && std::getline(in, line); ++i) {
      if (line.size() < 44) throw std::runtime_error(std::string(path) + ": short atom line");
      f.points.push_back({10 * std::stod(line.substr(20, 8)), 10 * std::stod(line.substr(28, 8)),
                          10 * std::stod(line.substr(36, 8))});
      const double r = radius_of(line.substr(10, 5));
      f.weights.push_back(r * r);
    }
    std::getline(in, line);  // the box
    frames.push_back(std::move(f));
  }
  return frames;
}

// Per pair of consecutive frames: the update from one to the next against
// building the next (each timed over `reps` runs), medians over the pairs.
void trajectory(const char* path, int reps) {
  const std::vector<Frame> frames = read_gro(path);
  if (frames.size() < 2) {
    std::fprintf(stderr, "%s: fewer than 2 frames\n", path);
    std::exit(1);
  }
  std::vector<double> ratio, complex_ratio, moved_nn, flips, relocated;
  int rebuilt = 0;
  for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
    const alpha::Triangulation t0(frames[f].points, frames[f].weights);
    const Frame& next = frames[f + 1];
    double rms = 0;
    for (std::size_t i = 0; i < next.points.size(); ++i) { const Vec3 d = next.points[i] - frames[f].points[i]; rms += alpha::dot(d, d); }
    moved_nn.push_back(std::sqrt(rms / double(next.points.size())) / mean_nearest(t0));
    std::vector<alpha::Triangulation> copies;  // built, not copied: with a build's spare capacity
    for (int r = 0; r < reps; ++r) copies.emplace_back(frames[f].points, frames[f].weights);
    alpha::UpdateReport report;
    const double u = seconds_of([&] {
      for (auto& t : copies) report = t.move_points(next.points, next.weights);
    });
    const double b = seconds_of([&] {
      for (int r = 0; r < reps; ++r) alpha::Triangulation fresh(next.points, next.weights);
    });
    const double k = seconds_of([&] {
      for (int r = 0; r < reps; ++r) alpha::AlphaComplex complex(copies[0]);
    });
    ratio.push_back(u / b), complex_ratio.push_back(k / b);
    flips.push_back(double(report.flips23 + report.flips32 + report.flips41) / double(next.points.size()));
    relocated.push_back(double(report.relocated) / double(next.points.size()));
    rebuilt += report.rebuilt;
  }
  std::printf("%s: %zu atoms, %zu frame pairs (medians): rms move %.3f NN, update/build %.2f, "
              "complex/build %.2f, flips/atom %.3f, relocated %.2f%%, rebuilt %d\n",
              path, frames[0].points.size(), ratio.size(), bench::median(moved_nn), bench::median(ratio),
              bench::median(complex_ratio), bench::median(flips), 100 * bench::median(relocated), rebuilt);
}

}  // namespace

// One update of n random points, a share of them moved by `by` NN: the
// update alone, for callgrind (--toggle-collect=*move_points*).
void one(std::size_t n, double share, double by) {
  const std::vector<Vec3> start = testing::random_points(n, 1);
  alpha::Triangulation t(start);
  const std::vector<Vec3> moved = testing::jitter(start, by * mean_nearest(t), 100);
  std::vector<Index> ids;
  std::vector<Vec3> to;
  for (Index i = 0; i < n; i += Index(1 / share)) ids.push_back(i), to.push_back(moved[i]);
  alpha::UpdateReport report;
  const double s = seconds_of([&] { report = t.move_points(ids, to); });
  std::printf("relocated %zu, returned %zu, flips %zu, rebuilt %d, %.4f s\n", report.relocated, report.returned,
              report.flips23 + report.flips32 + report.flips41, int(report.rebuilt), s);
}

int main(int argc, char** argv) {
  if (argc > 4 && std::strcmp(argv[1], "--one") == 0) {
    one(std::size_t(std::atof(argv[2])), std::atof(argv[3]), std::atof(argv[4]));
    return 0;
  }
  if (argc > 2 && std::strcmp(argv[1], "--frames") == 0) {
    trajectory(argv[2], argc > 3 ? std::atoi(argv[3]) : 50);
    return 0;
  }
  random_sets(argc > 1 ? std::atoi(argv[1]) : 5, argc > 2 ? std::atoi(argv[2]) : 3,
              argc > 3 ? std::size_t(std::atof(argv[3])) : 0);
}
