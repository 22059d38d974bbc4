// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <span>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "numerics/exact_size.hpp"  // libalpha/src: GMP
#include "point_sets.hpp"

using namespace alpha;

namespace {

using C = Classification;

// Points of the closed complex at a level: every present simplex has its
// faces present (the complex is closed), and the Euler characteristic of
// the present simplices equals b0 - b1 + b2.
void check_level(const AlphaComplex& a, Index level) {
  const Simplices& s = a.simplices();
  const Triangulation& t = a.triangulation();
  auto present = [&](const Interval& i) { return AlphaComplex::classify(i, level) != C::exterior; };
  long chi = 0;
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex) chi += present(a.vertex_interval(v));
  for (Index e = 0; e < s.num_edges(); ++e) {
    if (!present(a.edge_interval(e))) continue;
    --chi;
    for (Index v : s.edge(e)) REQUIRE(present(a.vertex_interval(v)));
  }
  for (Index f = 0; f < s.num_triangles(); ++f) {
    if (!present(a.triangle_interval(f))) continue;
    ++chi;
    for (Index e : s.triangle_edges(f)) REQUIRE(present(a.edge_interval(e)));
  }
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (a.classify_cell(c, level) != C::interior) continue;
    --chi;
    for (int i = 0; i < 4; ++i) REQUIRE(present(a.triangle_interval(s.cell_triangle(c, i))));
  }
  const auto b = a.betti(level);
  CHECK(chi == long(b[0]) - long(b[1]) + long(b[2]));
}

// (rank, simplex) of every simplex entering at its own size, by rank.
std::vector<std::pair<Index, Simplex>> ranked_entries(const Triangulation& t, const AlphaComplex& a) {
  std::vector<std::pair<Index, Simplex>> entries;
  const Simplices& s = a.simplices();
  for (Index c = 0; c < t.num_cells(); ++c)
    if (!t.is_infinite(c)) entries.emplace_back(a.cell_entry(c), Simplex(t.cell(c).v[0], t.cell(c).v[1], t.cell(c).v[2], t.cell(c).v[3]));
  for (Index f = 0; f < s.num_triangles(); ++f)
    if (!a.triangle_interval(f).attached)
      entries.emplace_back(a.triangle_interval(f).entry, Simplex(s.triangle(f)[0], s.triangle(f)[1], s.triangle(f)[2]));
  for (Index e = 0; e < s.num_edges(); ++e)
    if (!a.edge_interval(e).attached) entries.emplace_back(a.edge_interval(e).entry, Simplex(s.edge(e)[0], s.edge(e)[1]));
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex && !a.vertex_interval(v).attached)
      entries.emplace_back(a.vertex_interval(v).entry, Simplex(v));
  std::stable_sort(entries.begin(), entries.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  return entries;
}

// Consecutive entries whose ranks disagree with their exact sizes (equal
// ranks for different sizes, or increasing ranks for sizes not
// increasing); `ties` counts the pairs of equal rank.
std::size_t misordered(const Triangulation& t, const std::vector<std::pair<Index, Simplex>>& entries,
                       std::size_t& ties) {
  SizeKernel exact(t.points().data(), t.weighted() ? t.weights().data() : nullptr);
  std::size_t wrong = 0;
  for (std::size_t k = 1; k < entries.size(); ++k) {
    const int c = sgn(exact_size(exact, entries[k - 1].second) - exact_size(exact, entries[k].second));
    const bool same_rank = entries[k - 1].first == entries[k].first;
    wrong += same_rank ? c != 0 : c >= 0;
    ties += same_rank;
  }
  return wrong;
}

}  // namespace

TEST_CASE("Regular tetrahedron: known sizes and classification", "[alpha]") {
  // Edge length 2*sqrt(2): edge 2, triangle 8/3, tetrahedron 3.
  const Triangulation t(std::vector<Vec3>{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}});
  const AlphaComplex a(t);
  REQUIRE(a.spectrum_size() == 4);
  CHECK(a.spectrum_value(0) == 0.0);
  CHECK(a.spectrum_value(1) == 2.0);
  CHECK(a.spectrum_value(2) == Approx(8.0 / 3.0));
  CHECK(a.spectrum_value(3) == 3.0);
  CHECK(a.level(1.99) == 1);
  CHECK(a.level(2.0) == 2);  // a value equal to alpha counts as present
  CHECK(a.level(HUGE_VAL) == 4);
  CHECK(a.level(-HUGE_VAL) == 0);
  CHECK_THROWS_AS(a.level(std::nan("")), Error);
  const auto at = [&](double alpha_sq) { return a.counts(a.level(alpha_sq)); };
  CHECK(at(-1)[0][int(C::exterior)] == 4);
  CHECK(at(0)[0][int(C::singular)] == 4);
  CHECK(at(2)[1][int(C::singular)] == 6);
  CHECK(at(2)[0][int(C::regular)] == 4);
  CHECK(at(2.7)[2][int(C::singular)] == 4);
  CHECK(at(3)[3][int(C::interior)] == 1);
  CHECK(at(3)[2][int(C::regular)] == 4);  // hull triangles never become interior
  CHECK(a.volume(a.level(3)) == Approx(8.0 / 3.0));
  CHECK(a.optimal_level() == 2);
}

TEST_CASE("Attached flags match brute force over all points; intervals are nested", "[alpha]") {
  for (std::uint64_t seed : {1, 2}) {
    const bool weighted = seed == 2;
    const auto pts = testing::random_points(120, seed, 10.0);
    const Triangulation t = weighted ? Triangulation(pts, testing::random_weights(120, seed, 0.0, 3.0)) : Triangulation(pts);
    const AlphaComplex a(t);
    const Simplices& s = a.simplices();
    SizeKernel k(t.points().data(), t.weighted() ? t.weights().data() : nullptr);
    // Attached: some input point lies strictly inside the smallest orthosphere
    // (for a regular triangulation only the cofaces' vertices can).
    auto brute_attached = [&](const Simplex& x) {
      for (Index q = 0; q < t.num_points(); ++q) {
        if (t.status(q) != PointStatus::vertex || std::find(x.v.begin(), x.v.begin() + x.n, q) != x.v.begin() + x.n)
          continue;
        if (k.attached(x, q)) return true;
      }
      return false;
    };
    for (Index f = 0; f < s.num_triangles(); ++f) {
      const auto& v = s.triangle(f);
      CHECK(a.triangle_interval(f).attached == brute_attached(Simplex(v[0], v[1], v[2])));
      for (Index e : s.triangle_edges(f)) CHECK(a.edge_interval(e).entry <= a.triangle_interval(f).entry);
      for (Index c : s.triangle_cells(f)) CHECK(a.triangle_interval(f).entry <= a.cell_entry(c));
    }
    for (Index e = 0; e < s.num_edges(); ++e) {
      CHECK(a.edge_interval(e).attached == brute_attached(Simplex(s.edge(e)[0], s.edge(e)[1])));
      for (Index v : s.edge(e)) CHECK(a.vertex_interval(v).entry <= a.edge_interval(e).entry);
    }
    for (Index lvl = 0; lvl <= a.spectrum_size(); lvl += 7) check_level(a, lvl);
    // The seed's bound on the number of distinct alpha shapes.
    const std::size_t n = t.num_vertices();
    CHECK(a.spectrum_size() <= 2 * n * n - 5 * n);
  }
}

TEST_CASE("Integer grid: exact ties, known Betti numbers and volume", "[alpha][degenerate]") {
  const int n = 4;
  const Triangulation t(testing::grid_points(n));
  const AlphaComplex a(t);
  // Critical values of a unit grid: 0, 1/4 (edges), 1/2 (face diagonals and
  // squares), 3/4 (cubes); ties are exact.
  REQUIRE(a.spectrum_size() == 4);
  CHECK(a.spectrum_value(1) == 0.25);
  CHECK(a.spectrum_value(2) == 0.5);
  CHECK(a.spectrum_value(3) == 0.75);
  CHECK(a.betti(a.level(0)) == std::array<std::size_t, 3>{64, 0, 0});
  // Unit edges only: a cubical graph with 1 component and E - V + 1 cycles.
  const std::size_t edges = 3 * n * n * (n - 1);
  CHECK(a.betti(a.level(0.25)) == std::array<std::size_t, 3>{1, edges - 64 + 1, 0});
  // Squares filled: the unit cubes are hollow (27 voids).
  CHECK(a.betti(a.level(0.5)) == std::array<std::size_t, 3>{1, 0, 27});
  CHECK(a.betti(a.level(0.75)) == std::array<std::size_t, 3>{1, 0, 0});
  CHECK(a.volume(a.level(0.75)) == Approx(27.0).epsilon(1e-12));
  CHECK(a.volume(a.level(0.5)) == 0.0);
  for (Index lvl = 0; lvl <= a.spectrum_size(); ++lvl) check_level(a, lvl);
}

TEST_CASE("Integer grid: exact sizes ranked as the same grid scaled by 2^-3", "[alpha][degenerate]") {
  // Integer weights 0-3 on a 6^3 grid: sizes that doubles hold exactly
  // (rank runs taken as one value without exact comparisons) and sizes
  // they do not (thirds, fifths: compared exactly). Scaled by 2^-3, the
  // points are not integers and every run is compared exactly; the ranks,
  // the spectrum (scaled by 2^-6) and the pairs must be the same.
  std::vector<Vec3> pts = testing::grid_points(6), scaled;
  std::vector<double> w, scaled_w;
  std::mt19937_64 rng(3);
  for (const Vec3& p : pts) {
    w.push_back(double(rng() % 4));
    scaled.push_back({p.x / 8, p.y / 8, p.z / 8});
    scaled_w.push_back(w.back() / 64);
  }
  const Triangulation t(pts, w), ts(scaled, scaled_w);
  const AlphaComplex a(t), as(ts);
  REQUIRE(a.spectrum_size() == as.spectrum_size());
  CHECK(a.spectrum_size() > 20);
  for (Index r = 0; r < a.spectrum_size(); ++r) CHECK(a.spectrum_value(r) / 64 == as.spectrum_value(r));
  const auto same = [](const Interval& x, const Interval& y) {
    return x.entry == y.entry && x.mu_low == y.mu_low && x.mu_high == y.mu_high && x.attached == y.attached;
  };
  const Simplices& s = a.simplices();
  REQUIRE(s.num_triangles() == as.simplices().num_triangles());
  for (Index v = 0; v < t.num_points(); ++v)
    if (t.status(v) == PointStatus::vertex) CHECK(same(a.vertex_interval(v), as.vertex_interval(v)));
  for (Index e = 0; e < s.num_edges(); ++e) CHECK(same(a.edge_interval(e), as.edge_interval(e)));
  for (Index f = 0; f < s.num_triangles(); ++f) CHECK(same(a.triangle_interval(f), as.triangle_interval(f)));
  for (Index c = 0; c < t.num_cells(); ++c) CHECK(a.cell_entry(c) == as.cell_entry(c));
  const auto& pairs = a.persistence();
  const auto& scaled_pairs = as.persistence();
  REQUIRE(pairs.size() == scaled_pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k)
    CHECK((pairs[k].dim == scaled_pairs[k].dim && pairs[k].birth == scaled_pairs[k].birth &&
           pairs[k].death == scaled_pairs[k].death));
  std::size_t ties = 0;
  CHECK(misordered(t, ranked_entries(t, a), ties) == 0);
  CHECK(ties > 100);
  // A size without error is the exact size (GMP), and some are not.
  const SizeKernel k(t.points().data(), t.weights().data(), true);  // promised: small integers
  std::size_t exact = 0, inexact = 0;
  const auto check = [&](const Simplex& x) {
    const Size z = k.size(x);
    if (z.error != 0) return void(++inexact);
    ++exact;
    CHECK(mpq_class(z.value) == exact_size(k, x));
  };
  for (Index e = 0; e < s.num_edges(); ++e) check(Simplex(s.edge(e)[0], s.edge(e)[1]));
  for (Index f = 0; f < s.num_triangles(); ++f) check(Simplex(s.triangle(f)[0], s.triangle(f)[1], s.triangle(f)[2]));
  for (Index c = 0; c < t.num_cells(); ++c)
    if (!t.is_infinite(c)) check(Simplex(t.cell(c).v));
  CHECK(exact > 1000);
  CHECK(inexact > 100);
}

TEST_CASE("Dense ball sample: volume near the hull's at large alpha", "[alpha]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> pts;
  while (pts.size() < 4000) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    if (p.x * p.x + p.y * p.y + p.z * p.z <= 1) pts.push_back(p);
  }
  const Triangulation t(pts);
  const AlphaComplex a(t);
  const double hull = a.volume(Index(a.spectrum_size()));
  CHECK(a.volume(a.level(1.0)) == Approx(hull).epsilon(0.01));
  CHECK(a.betti(a.level(1.0)) == std::array<std::size_t, 3>{1, 0, 0});
  // The boundary mesh is closed: every edge in exactly two boundary triangles.
  const ShapeBoundary b = a.boundary(a.level(1.0));
  std::map<std::pair<Index, Index>, int> uses;
  for (const auto& f : b.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(f[k], f[(k + 1) % 3])];
  for (const auto& [edge, count] : uses) CHECK(count == 2);
  // Outward orientation: the divergence theorem gives back the volume.
  double signed_volume = 0;
  for (const auto& f : b.triangles) {
    const Vec3 &p = t.point(f[0]), &q = t.point(f[1]), &r = t.point(f[2]);
    signed_volume += (p.x * (q.y * r.z - q.z * r.y) - p.y * (q.x * r.z - q.z * r.x) + p.z * (q.x * r.y - q.y * r.x)) / 6;
  }
  CHECK(signed_volume == Approx(a.volume(a.level(1.0))).epsilon(1e-9));
}

TEST_CASE("Translated copies: long runs of near-equal sizes ranked exactly", "[alpha][degenerate]") {
  // Ten copies of a weighted cluster shifted by non-dyadic steps: the
  // copies' sizes agree to rounding, so the spectrum sort meets long runs
  // of overlapping values, equal or one ulp apart.
  const auto base = testing::random_points(30, 71, 3.0);
  const auto base_w = testing::random_weights(30, 72, 0.5, 2.0);
  std::vector<Vec3> pts;
  std::vector<double> w;
  for (int k = 0; k < 10; ++k)
    for (std::size_t i = 0; i < base.size(); ++i)
      pts.push_back({base[i].x + 3.1 * k, base[i].y + 0.7 * k, base[i].z}), w.push_back(base_w[i]);
  const Triangulation t(pts, w);
  const AlphaComplex a(t);
  std::size_t ties = 0;
  const auto entries = ranked_entries(t, a);
  CHECK(misordered(t, entries, ties) == 0);
  CHECK(ties > 0);
  SizeKernel exact(t.points().data(), t.weights().data());
  for (std::size_t k = 0; k < entries.size(); k += 97)
    CHECK(a.spectrum_value(entries[k].first) == exact.rounded_size(entries[k].second));
}

TEST_CASE("spectrum_values: each rank's spectrum_value, in any order and count", "[alpha][degenerate]") {
  // Weighted random points with hidden ones, and a grid (sizes tied in
  // long runs); the ranks shuffled, repeated, and in lists that end on,
  // before and after a block boundary.
  const auto random_pts = testing::random_points(400, 91, 4.0);
  const Triangulation weighted(random_pts, testing::random_weights(400, 92, 0.0, 3.0));
  const Triangulation grid(testing::grid_points(6));
  for (const Triangulation* t : {&weighted, &grid}) {
    const AlphaComplex a(*t);
    std::vector<Index> all(a.spectrum_size());
    for (Index r = 0; r < all.size(); ++r) all[r] = r;
    std::mt19937 rng(7);
    std::shuffle(all.begin(), all.end(), rng);
    for (int k = 0; k < 300; ++k) all.push_back(all[rng() % all.size()]);
    for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(255), std::size_t(256),
                                std::size_t(257), std::size_t(273), all.size()}) {
      const auto ranks = std::span(all).first(std::min(n, all.size()));
      std::vector<double> values(ranks.size(), std::nan(""));
      a.spectrum_values(ranks, values);
      for (std::size_t k = 0; k < ranks.size(); ++k) REQUIRE(values[k] == a.spectrum_value(ranks[k]));
    }
  }
}

TEST_CASE("A sliver's imprecise size is ranked exactly among precise ones", "[alpha][degenerate]") {
  // A nearly flat tetrahedron (its filtered size ~2000 ulps above the
  // exact one, with a wide error bound) and two far edges whose sizes lie
  // just above and just below that: sorted by value alone, the sliver's
  // interval reached back across an interval already closed, and the edge
  // of larger size was ranked first.
  const std::vector<Vec3> pts = {{-0.76859044977057356, 0.63974113555520828, -1.7357512548090528e-05},
                                 {-0.60085408362482773, -0.79935872434806676, -1.921500346124842e-05},
                                 {0.6401426774751493, 0.76825604616881926, 1.1413511825205039e-05},
                                 {-0.13155001838175856, -0.99130953423426682, -1.0652141302078966e-05},
                                 {0, 0, 1000},
                                 {2.0000004023914655, 0, 1000},
                                 {0, 0, -1000},
                                 {0, 2.0000004023915987, -1000}};
  const Triangulation t(pts);
  const AlphaComplex a(t);
  std::size_t ties = 0;
  CHECK(misordered(t, ranked_entries(t, a), ties) == 0);
  // At an alpha between the sliver's size and the near edge's, the edge
  // is absent: five components.
  const Index level = a.level(1.0000004023913729);
  CHECK(a.betti(level)[0] == 5);
  check_level(a, level);

  // The same with weights: two far points whose negative weights put
  // their sizes two and four ulps above the sliver's exact size.
  std::vector<Vec3> wp = {{0.15038448672194007, 0.5864153099179068, 0.94616932282758803},
                          {0.32493886338758476, 0.59709837036983482, 0.14722445530130315},
                          {0.71059105019631019, 0.57733749302056236, 0.79450413894879346},
                          {0.76007816161368758, 0.59468159239424534, 0.35725968031022043}};
  const double r = SizeKernel(wp.data(), nullptr).rounded_size(Simplex(0, 1, 2, 3));
  const double x1 = std::nextafter(std::nextafter(r, 100.0), 100.0);
  const double x2 = std::nextafter(std::nextafter(x1, 100.0), 100.0);
  wp.push_back({1000, 0, 0});
  wp.push_back({0, 1000, 0});
  const Triangulation tw(wp, {0, 0, 0, 0, -x1, -x2});
  const AlphaComplex aw(tw);
  ties = 0;
  CHECK(misordered(tw, ranked_entries(tw, aw), ties) == 0);
}
