// SPDX-License-Identifier: Apache-2.0
// Construction time and memory of alpha::Triangulation against CGAL's
// Delaunay_triangulation_3 / Regular_triangulation_3 (Epick, sequential) on
// the same point sets, in one run; prints a table. See README.md.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "alpha/triangulation.hpp"
#include "point_sets.hpp"
#include "rss.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Case {
  std::string name;
  std::vector<alpha::Vec3> points;
  std::vector<double> weights;  // empty: Delaunay
  int reps;
};

struct Run {
  double seconds;
  long peak_bytes;  // growth of the resident set during the build
  std::size_t finite_cells;
};

// Builds with `build` (which returns the number of finite cells).
template <class Build>
Run measure(Build build) {
  std::size_t cells = 0;
  const bench::Measurement m = bench::measure([&] { cells = build(); });
  return {m.seconds, m.peak_bytes, cells};
}

struct Summary {
  double seconds;  // median
  long peak_bytes;  // largest over the repetitions
  std::size_t finite_cells;
};

Summary summarize(std::vector<Run> runs) {
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.seconds < b.seconds; });
  long peak = 0;
  for (const Run& r : runs) peak = std::max(peak, r.peak_bytes);
  return {runs[runs.size() / 2].seconds, peak, runs.front().finite_cells};
}

struct Result {
  Summary ours, cgal;
  std::size_t memory_bytes;
  alpha::PredicateStats stats;
};

Result run_case(const Case& c) {
  // Inputs are converted before timing; each side copies/sorts them itself.
  std::vector<K::Point_3> cgal_points;
  std::vector<K::Weighted_point_3> cgal_weighted;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const K::Point_3 p(c.points[i].x, c.points[i].y, c.points[i].z);
    if (c.weights.empty())
      cgal_points.push_back(p);
    else
      cgal_weighted.emplace_back(p, c.weights[i]);
  }

  Result result{};
  std::vector<Run> ours, cgal;
  for (int rep = 0; rep < c.reps; ++rep) {
    ours.push_back(measure([&] {
      const alpha::Triangulation t(c.points, c.weights);
      result.memory_bytes = t.memory_bytes();
      result.stats = t.predicate_stats();
      return t.num_finite_cells();
    }));
    cgal.push_back(measure([&] {
      if (c.weights.empty()) return CGAL::Delaunay_triangulation_3<K>(cgal_points.begin(), cgal_points.end()).number_of_finite_cells();
      return CGAL::Regular_triangulation_3<K>(cgal_weighted.begin(), cgal_weighted.end()).number_of_finite_cells();
    }));
  }
  result.ours = summarize(ours);
  result.cgal = summarize(cgal);
  return result;
}

}  // namespace

int main() {
  const std::size_t small = 100'000, large = 1'000'000;
  const std::vector<Case> cases = {
      {"random 1e5", testing::random_points(small, 1), {}, 3},
      {"random 1e6", testing::random_points(large, 2), {}, 3},
      {"grid 47^3", testing::grid_points(47), {}, 3},
      // Unit density, weights (squared radii) in [0,1): about 8% hidden.
      {"weighted 1e5", testing::random_points(small, 3, std::cbrt(double(small))),
       testing::random_weights(small, 4, 0.0, 1.0), 3},
      {"weighted 1e6", testing::random_points(large, 5, std::cbrt(double(large))),
       testing::random_weights(large, 6, 0.0, 1.0), 3},
  };

  std::vector<Result> results;
  std::printf("%-13s %8s %4s %9s %9s %9s %10s %10s %10s %9s %9s\n", "set", "n", "reps", "ours s", "CGAL s",
              "ours/CGAL", "ours B/pt", "oursRSS/pt", "CGALRSS/pt", "cells", "CGALcells");
  for (const Case& c : cases) {
    const Result r = run_case(c);
    const double n = double(c.points.size());
    std::printf("%-13s %8zu %4d %9.3f %9.3f %9.2f %10.1f %10.1f %10.1f %9zu %9zu\n", c.name.c_str(),
                c.points.size(), c.reps, r.ours.seconds, r.cgal.seconds, r.ours.seconds / r.cgal.seconds,
                r.memory_bytes / n, r.ours.peak_bytes / n, r.cgal.peak_bytes / n, r.ours.finite_cells,
                r.cgal.finite_cells);
    std::fflush(stdout);
    results.push_back(r);
  }

  // Cases 0 and 2: random and grid of about 1e5 points; per-point times.
  const auto per_point = [&](std::size_t i, const Summary Result::*side) {
    return (results[i].*side).seconds / double(cases[i].points.size());
  };
  std::printf("\ngrid/random time per point at 1e5: ours %.2f, CGAL %.2f\n",
              per_point(2, &Result::ours) / per_point(0, &Result::ours),
              per_point(2, &Result::cgal) / per_point(0, &Result::cgal));

  std::printf("\npredicate stages (ours, one build)\n%-13s %12s %10s %10s %12s %10s %10s\n", "set", "orient filt",
              "exact", "degen", "power filt", "exact", "perturbed");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const alpha::PredicateStats& s = results[i].stats;
    std::printf("%-13s %12llu %10llu %10llu %12llu %10llu %10llu\n", cases[i].name.c_str(),
                (unsigned long long)s.orient.filtered, (unsigned long long)s.orient.exact,
                (unsigned long long)s.orient.perturbed, (unsigned long long)s.power.filtered,
                (unsigned long long)s.power.exact, (unsigned long long)s.power.perturbed);
  }
}
