// SPDX-License-Identifier: Apache-2.0
// The whole alpha complex family (triangulation, intervals, exactly sorted
// spectrum, persistence) of alpha::AlphaComplex against CGAL's Alpha_shape_3
// and GUDHI's Alpha_complex + persistent cohomology, and against CGAL's
// triangulation alone (the targets' yardstick), on the same point sets, in one
// run; prints a table. See README.md.
//
// Usage: bench_alpha_complex [--large]   (--large: the peers on 1e6 points too)
#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Epeck_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <gudhi/Alpha_complex.h>
#include <gudhi/Persistent_cohomology.h>
#include <gudhi/Simplex_tree.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/triangulation.hpp"
#include "median.hpp"
#include "point_sets.hpp"
#include "rss.hpp"

namespace {

// CGAL: Epick with exact alpha comparisons (lazily exact alpha values), in
// GENERAL mode (intervals of every simplex and the whole spectrum).
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Tag_true;
using DelaunayAS = CGAL::Alpha_shape_3<
    CGAL::Delaunay_triangulation_3<
        K, CGAL::Triangulation_data_structure_3<CGAL::Alpha_shape_vertex_base_3<K, CGAL::Default, Exact>,
                                                CGAL::Alpha_shape_cell_base_3<K, CGAL::Default, Exact>>>,
    Exact>;
using RegularAS = CGAL::Alpha_shape_3<
    CGAL::Regular_triangulation_3<
        K, CGAL::Triangulation_data_structure_3<
               CGAL::Alpha_shape_vertex_base_3<K, CGAL::Regular_triangulation_vertex_base_3<K>, Exact, CGAL::Tag_true>,
               CGAL::Alpha_shape_cell_base_3<K, CGAL::Regular_triangulation_cell_base_3<K>, Exact, CGAL::Tag_true>>>,
    Exact>;

// GUDHI: its dD alpha complex on the exact kernel with exact filtration
// values (rounded to double in the simplex tree), Z/2 cohomology.
using Kd = CGAL::Epeck_d<CGAL::Dimension_tag<3>>;
using Tree = Gudhi::Simplex_tree<>;
using Cohomology = Gudhi::persistent_cohomology::Persistent_cohomology<Tree, Gudhi::persistent_cohomology::Field_Zp>;

struct Case {
  std::string name;
  std::vector<alpha::Vec3> points;
  std::vector<double> weights;  // empty: unweighted
  int reps;    // of ours; the peers run once (they take far longer)
  bool peers;  // whether CGAL and GUDHI run on it
};

// One side's runs: times (median) and peak RSS growth (largest).
struct Side {
  std::vector<double> seconds;
  long peak_bytes = 0;
  void add(const bench::Measurement& m) {
    seconds.push_back(m.seconds);
    peak_bytes = std::max(peak_bytes, m.peak_bytes);
  }
  double median_seconds() const { return bench::median(seconds); }
};

struct Result {
  Side ours, cgal, gudhi, cgal_triangulation;
  std::vector<double> ours_triangulation, ours_complex;  // the split of ours
  std::vector<double> ours_threads;                      // wall seconds on kThreads threads
  std::size_t memory_bytes = 0;                          // Triangulation + AlphaComplex
  std::size_t spectrum = 0, cgal_spectrum = 0;
  std::size_t pairs = 0, gudhi_pairs = 0;                // persistence pairs of positive length
};

void run_ours(const Case& c, Result& r) {
  double split[2];
  r.ours.add(bench::measure([&] {
    const double start = bench::cpu_seconds();
    const alpha::Triangulation t(c.points, c.weights);
    split[0] = bench::cpu_seconds() - start;
    const alpha::AlphaComplex a(t);
    r.pairs = a.persistence().size();  // computed on demand: part of the timed work
    split[1] = bench::cpu_seconds() - start - split[0];
    r.memory_bytes = t.memory_bytes() + a.memory_bytes();
    r.spectrum = a.spectrum_size();
  }));
  r.ours_triangulation.push_back(split[0]);
  r.ours_complex.push_back(split[1]);
}

// Ours again on two threads (the machine's cores), timed by the wall
// clock: CPU time would add up the threads. The pairs must be the same.
constexpr unsigned kThreads = 2;
void run_ours_on_threads(const Case& c, Result& r) {
  const auto start = std::chrono::steady_clock::now();
  const alpha::Triangulation t(c.points, c.weights, kThreads);
  const alpha::AlphaComplex a(t, kThreads);
  const std::size_t pairs = a.persistence().size();
  r.ours_threads.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (pairs != r.pairs)
    std::fprintf(stderr, "%s: %zu pairs on threads, %zu sequential\n", c.name.c_str(), pairs, r.pairs);
}

std::vector<K::Point_3> cgal_points(const Case& c) {
  std::vector<K::Point_3> pts;
  for (const auto& p : c.points) pts.emplace_back(p.x, p.y, p.z);
  return pts;
}

std::vector<K::Weighted_point_3> cgal_weighted_points(const Case& c) {
  std::vector<K::Weighted_point_3> pts;
  for (std::size_t i = 0; i < c.points.size(); ++i)
    pts.emplace_back(K::Point_3(c.points[i].x, c.points[i].y, c.points[i].z), c.weights[i]);
  return pts;
}

void run_cgal(const Case& c, Result& r) {
  if (c.weights.empty()) {
    const auto pts = cgal_points(c);
    r.cgal.add(bench::measure([&] {
      const DelaunayAS as(pts.begin(), pts.end(), 0, DelaunayAS::GENERAL);
      r.cgal_spectrum = as.number_of_alphas();
    }));
  } else {
    const auto pts = cgal_weighted_points(c);
    r.cgal.add(bench::measure([&] {
      const RegularAS as(pts.begin(), pts.end(), 0, RegularAS::GENERAL);
      r.cgal_spectrum = as.number_of_alphas();
    }));
  }
}

// CGAL's sequential triangulation alone (Epick, as bench_triangulation).
void run_cgal_triangulation(const Case& c, Result& r) {
  std::size_t cells = 0;
  if (c.weights.empty()) {
    const auto pts = cgal_points(c);
    r.cgal_triangulation.add(bench::measure([&] {
      const CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
      cells = dt.number_of_finite_cells();
    }));
  } else {
    const auto pts = cgal_weighted_points(c);
    r.cgal_triangulation.add(bench::measure([&] {
      const CGAL::Regular_triangulation_3<K> rt(pts.begin(), pts.end());
      cells = rt.number_of_finite_cells();
    }));
  }
  if (cells == 0) std::fprintf(stderr, "CGAL: no cells for %s\n", c.name.c_str());
}

template <class Complex>
std::size_t gudhi_pairs(Complex& ac) {
  Tree st;
  if (!ac.create_complex(st, std::numeric_limits<double>::infinity(), /*exact=*/true)) return 0;
  Cohomology pcoh(st);
  pcoh.init_coefficients(2);
  pcoh.compute_persistent_cohomology(0.0);  // drops intervals of length 0, as ours does
  std::size_t n = 0;
  for (int dim = 0; dim < 3; ++dim) n += pcoh.intervals_in_dimension(dim).size();
  return n;
}

void run_gudhi(const Case& c, Result& r) {
  std::vector<Kd::Point_d> pts;
  for (const auto& p : c.points) pts.emplace_back(p.x, p.y, p.z);
  std::vector<Kd::FT> w(c.weights.begin(), c.weights.end());
  r.gudhi.add(bench::measure([&] {
    if (c.weights.empty()) {
      Gudhi::alpha_complex::Alpha_complex<Kd, false> ac(pts);
      r.gudhi_pairs = gudhi_pairs(ac);
    } else {
      Gudhi::alpha_complex::Alpha_complex<Kd, true> ac(pts, w);
      r.gudhi_pairs = gudhi_pairs(ac);
    }
  }));
}

}  // namespace

int main(int argc, char** argv) {
  bool large = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--large") != 0) {
      std::fprintf(stderr, "usage: %s [--large]\n", argv[0]);
      return 2;
    }
    large = true;
  }
  const std::size_t small = 100'000, big = 1'000'000;
  // The point sets of bench_triangulation (same seeds).
  const std::vector<Case> cases = {
      {"random 1e5", testing::random_points(small, 1), {}, 3, true},
      {"random 1e6", testing::random_points(big, 2), {}, 1, large},
      // Unit density, weights (squared radii) in [0,1): about 8% hidden.
      {"weighted 1e5", testing::random_points(small, 3, std::cbrt(double(small))),
       testing::random_weights(small, 4, 0.0, 1.0), 3, true},
      // Degenerate: every cube's corners cospherical, sizes tied in long runs.
      {"grid 47^3", testing::grid_points(47), {}, 3, true},
  };

  std::printf("%-12s %7s %4s %7s %7s %7s %8s %8s %7s %7s %8s %8s %8s %8s %9s %10s %10s %11s %9s %9s %8s %8s\n", "set",
              "n", "reps", "tri s", "alpha s", "ours s", "CGAL s", "GUDHI s", "o/CGAL", "o/GUDHI", "CGALdt s",
              "o/CGALdt", "j2wall s", "j2/CGdt", "ours B/pt", "oursRSS/pt", "CGALRSS/pt", "GUDHIRSS/pt", "spectrum",
              "CGALspec", "pairs", "GUDHIprs");
  std::fflush(stdout);
  // Ours on every set first, then the peers: their heaps (CGAL's and
  // GUDHI's many small blocks) would otherwise change our RSS growth.
  std::vector<Result> results(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (int rep = 0; rep < cases[i].reps; ++rep) {
      run_ours(cases[i], results[i]);
      run_ours_on_threads(cases[i], results[i]);
    }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].peers) run_cgal(cases[i], results[i]), run_gudhi(cases[i], results[i]);
    run_cgal_triangulation(cases[i], results[i]);  // once, on every set
  }

  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const Result& r = results[i];
    const double n = double(c.points.size());
    const double ours = r.ours.median_seconds();
    std::printf("%-12s %7zu %4d %7.3f %7.3f %7.3f ", c.name.c_str(), c.points.size(), c.reps,
                bench::median(r.ours_triangulation), bench::median(r.ours_complex), ours);
    if (c.peers) {
      const double cgal = r.cgal.median_seconds(), gudhi = r.gudhi.median_seconds();
      std::printf("%8.3f %8.3f %7.3f %7.3f ", cgal, gudhi, ours / cgal, ours / gudhi);
    } else {
      std::printf("%8s %8s %7s %7s ", "-", "-", "-", "-");
    }
    const double cgal_triangulation = r.cgal_triangulation.median_seconds();
    const double threads = bench::median(r.ours_threads);
    std::printf("%8.3f %8.3f %8.3f %8.3f ", cgal_triangulation, ours / cgal_triangulation, threads,
                threads / cgal_triangulation);
    std::printf("%9.1f %10.1f ", r.memory_bytes / n, r.ours.peak_bytes / n);
    if (c.peers)
      std::printf("%10.1f %11.1f %9zu %9zu %8zu %8zu\n", r.cgal.peak_bytes / n, r.gudhi.peak_bytes / n, r.spectrum,
                  r.cgal_spectrum, r.pairs, r.gudhi_pairs);
    else
      std::printf("%10s %11s %9zu %9s %8zu %8s\n", "-", "-", r.spectrum, "-", r.pairs, "-");
  }
}
