// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

#include "alpha/error.hpp"
#include "numerics/exact_size.hpp"  // libalpha/src: GMP
#include "alpha/sizes.hpp"
#include "point_sets.hpp"

using namespace alpha;

namespace {

// Independent oracle: the smallest orthogonal sphere from the Gram system
// 2 (u_i . u_j) lambda_j = |u_i|^2 - w_i + w_0, x = sum lambda_j u_j, solved
// by Gaussian elimination in rationals. Nothing here is shared with the
// library's cross-product formulas. Empty for a degenerate simplex.
struct Sphere {
  mpq_class c[3];
  mpq_class r2;
};

struct Input {
  std::vector<Vec3> pts;
  std::vector<double> w;  // empty: unweighted
  SizeKernel kernel() const { return SizeKernel(pts.data(), w.empty() ? nullptr : w.data()); }
  mpq_class coord(Index i, int a) const { return mpq_class(a == 0 ? pts[i].x : a == 1 ? pts[i].y : pts[i].z); }
  mpq_class weight(Index i) const { return w.empty() ? mpq_class(0) : mpq_class(w[i]); }
};

std::optional<Sphere> oracle(const Input& in, const Simplex& s) {
  const int k = s.n - 1;
  mpq_class u[3][3], m[3][4];
  for (int i = 0; i < k; ++i)
    for (int a = 0; a < 3; ++a) u[i][a] = in.coord(s.v[i + 1], a) - in.coord(s.v[0], a);
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) m[i][j] = 2 * (u[i][0] * u[j][0] + u[i][1] * u[j][1] + u[i][2] * u[j][2]);
    m[i][k] = m[i][i] / 2 - in.weight(s.v[i + 1]) + in.weight(s.v[0]);
  }
  for (int col = 0; col < k; ++col) {
    int piv = col;
    while (piv < k && m[piv][col] == 0) ++piv;
    if (piv == k) return std::nullopt;
    for (int j = 0; j <= k; ++j) std::swap(m[col][j], m[piv][j]);
    for (int r = 0; r < k; ++r) {
      if (r == col || m[r][col] == 0) continue;
      const mpq_class f = m[r][col] / m[col][col];
      for (int j = col; j <= k; ++j) m[r][j] -= f * m[col][j];
    }
  }
  Sphere sp;
  mpq_class x[3];
  for (int j = 0; j < k; ++j) {
    const mpq_class lambda = m[j][k] / m[j][j];
    for (int a = 0; a < 3; ++a) x[a] += lambda * u[j][a];
  }
  for (int a = 0; a < 3; ++a) sp.c[a] = in.coord(s.v[0], a) + x[a];
  sp.r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - in.weight(s.v[0]);
  return sp;
}

// Power distance of point q to a sphere.
mpq_class power(const Input& in, const Sphere& sp, Index q) {
  mpq_class d = -sp.r2 - in.weight(q);
  for (int a = 0; a < 3; ++a) d += (in.coord(q, a) - sp.c[a]) * (in.coord(q, a) - sp.c[a]);
  return d;
}

int sign(const mpq_class& q) { return sgn(q); }

Simplex random_simplex(std::mt19937_64& rng, std::size_t n, int vertices) {
  std::uniform_int_distribution<Index> pick(0, Index(n - 1));
  Simplex s;
  s.n = vertices;
  for (int i = 0; i < vertices; ++i) {
    bool fresh;
    do {
      s.v[i] = pick(rng);
      fresh = true;
      for (int j = 0; j < i; ++j) fresh = fresh && s.v[j] != s.v[i];
    } while (!fresh);
  }
  return s;
}

// Random non-degenerate simplices of 1..4 vertices with their exact sizes.
void random_simplices(const Input& in, std::size_t count, std::uint64_t seed, std::vector<Simplex>& out,
                      std::vector<mpq_class>& sizes) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> dim(1, 4);
  while (out.size() < count) {
    const Simplex s = random_simplex(rng, in.pts.size(), dim(rng));
    if (auto sp = oracle(in, s)) out.push_back(s), sizes.push_back(sp->r2);
  }
}

// The filtered interval contains the exact size, exact_size() is exact and
// rounded_size() is the nearest double.
void check_size(SizeKernel& k, const Input& in, const Simplex& s, const mpq_class& exact) {
  const Size f = k.size(s);
  CHECK(exact_size(k, s) == exact);
  if (std::isfinite(f.error)) CHECK(abs(mpq_class(f.value) - exact) <= mpq_class(f.error));
  const double r = k.rounded_size(s);
  const mpq_class dr = abs(mpq_class(r) - exact);
  CHECK(dr <= abs(mpq_class(std::nextafter(r, HUGE_VAL)) - exact));
  CHECK(dr <= abs(mpq_class(std::nextafter(r, -HUGE_VAL)) - exact));
  (void)in;
}

// All pairs: compare() and compare_exact() against the exact order, sizes
// against alpha values.
void check_all_pairs(SizeKernel& k, const std::vector<Simplex>& s, const std::vector<mpq_class>& exact) {
  std::size_t wrong = 0;
  std::vector<ExactSize> fractions;
  for (const Simplex& x : s) fractions.push_back(exact_fraction(k, x));
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (k.compare(s[i], s[j]) != sign(exact[i] - exact[j])) ++wrong;
      if (compare_exact(fractions[i], fractions[j]) != sign(exact[i] - exact[j])) ++wrong;
    }
    for (std::size_t j = i; j < std::min(s.size(), i + 5); ++j) {
      const double alpha = exact[j].get_d();  // exact size when that is a double
      if (k.compare(s[i], alpha) != sign(exact[i] - mpq_class(alpha))) ++wrong;
    }
  }
  CHECK(wrong == 0);
}

// `count` random simplices of `in`: each size against its exact rational,
// and every pair's order.
void check_random_simplices(SizeKernel& k, const Input& in, std::size_t count, std::uint64_t seed) {
  std::vector<Simplex> s;
  std::vector<mpq_class> exact;
  random_simplices(in, count, seed, s, exact);
  for (std::size_t i = 0; i < s.size(); ++i) check_size(k, in, s[i], exact[i]);
  check_all_pairs(k, s, exact);
}

Input hand_built() {
  Input in;
  in.pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}};
  return in;
}

}  // namespace

TEST_CASE("sizes of hand-built simplices have their known exact values", "[sizes]") {
  Input in = hand_built();
  SizeKernel k = in.kernel();
  // Unit edge: r^2 = 1/4.
  CHECK(exact_size(k, {0, 1}) == mpq_class(1, 4));
  CHECK(k.rounded_size({0, 1}) == 0.25);
  // Equilateral triangles of side s = sqrt(2) and 3 sqrt(2): s^2 / 3.
  CHECK(exact_size(k, {1, 2, 3}) == mpq_class(2, 3));
  CHECK(exact_size(k, {7, 8, 9}) == mpq_class(6));
  CHECK(k.rounded_size({1, 2, 3}) == 2.0 / 3.0);
  // Regular tetrahedron in the unit cube: the cube's circumsphere, 3/4.
  CHECK(exact_size(k, {0, 4, 5, 6}) == mpq_class(3, 4));
  CHECK(k.compare({0, 4, 5, 6}, 0.75) == 0);
  CHECK(k.compare({0, 4, 5, 6}, std::nextafter(0.75, 1.0)) == -1);
  CHECK(k.compare({0, 4, 5, 6}, std::nextafter(0.75, 0.0)) == 1);
  // Unweighted vertex: 0.
  CHECK(exact_size(k, Simplex(3)) == 0);
  // Centers.
  const Vec3 ce = k.center({0, 1}), ct = k.center({1, 2, 3}), cc = k.center({0, 4, 5, 6});
  CHECK(ce.x == Approx(0.5));
  CHECK(std::fabs(ce.y) + std::fabs(ce.z) < 1e-15);
  CHECK(ct.x == Approx(1.0 / 3));
  CHECK(ct.y == Approx(1.0 / 3));
  CHECK(ct.z == Approx(1.0 / 3));
  CHECK(cc.x == Approx(0.5));
  CHECK(cc.y == Approx(0.5));
  CHECK(cc.z == Approx(0.5));

  SECTION("weighted") {
    Input wi;
    wi.pts = {{0, 0, 0}, {2, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
    wi.w = {1, 0, 1, 1, 0.5};
    SizeKernel kw = wi.kernel();
    // w0 = 1, w1 = 0 at distance 2: center t = (4 + w0 - w1) / 4 = 5/4,
    // r^2 = t^2 - w0 = 9/16.
    CHECK(exact_size(kw, {0, 1}) == mpq_class(9, 16));
    CHECK(exact_size(kw, {1, 0}) == mpq_class(9, 16));
    CHECK(kw.center({0, 1}).x == Approx(1.25));
    CHECK(kw.center({1, 0}).x == Approx(1.25));
    // Balls of weight 1 at distance 1 overlap deeply: 1/4 - 1 = -3/4.
    CHECK(exact_size(kw, {2, 3}) == mpq_class(-3, 4));
    CHECK(kw.compare({2, 3}, -0.75) == 0);
    CHECK(kw.compare({2, 3}, 0.0) == -1);
    CHECK(kw.compare({2, 3}, {0, 1}) == -1);
    // A vertex: -w.
    CHECK(exact_size(kw, Simplex(4)) == mpq_class(-1, 2));
    CHECK(kw.size(Simplex(4)).value == -0.5);
    CHECK(kw.size(Simplex(4)).error == 0);
    CHECK(kw.compare(Simplex(4), -0.5) == 0);
    CHECK(kw.compare(Simplex(0), Simplex(2)) == 0);
    // A weighted triangle against the oracle.
    const auto sp = oracle(wi, {0, 1, 4});
    REQUIRE(sp);
    CHECK(exact_size(kw, {0, 1, 4}) == sp->r2);
  }
}

TEST_CASE("sizes do not depend on the order of the vertices", "[sizes]") {
  Input in;
  in.pts = testing::random_points(4, 11);
  in.w = testing::random_weights(4, 12, 0, 0.1);
  SizeKernel k = in.kernel();
  const Size a = k.size({0, 1, 2, 3});
  for (const Simplex& s : {Simplex(3, 2, 1, 0), Simplex(1, 3, 0, 2), Simplex(2, 0, 3, 1)}) {
    CHECK(k.size(s).value == a.value);
    CHECK(k.size(s).error == a.error);
    CHECK(k.compare(s, {0, 1, 2, 3}) == 0);
  }
  CHECK(k.compare({2, 0, 1}, {1, 2, 0}) == 0);
}

TEST_CASE("filtered comparisons agree with exact rationals on random simplices", "[sizes]") {
  for (const bool weighted : {false, true}) {
    INFO("weighted " << weighted);
    Input in;
    in.pts = testing::random_points(300, weighted ? 21 : 22, 10.0);
    if (weighted) in.w = testing::random_weights(300, 23, -0.5, 2.0);
    SizeKernel k = in.kernel();
    check_random_simplices(k, in, 400, weighted ? 24 : 25);
    // Random sizes almost never tie: the filter decides nearly everything.
    CHECK(k.stats().compare.filtered > 0.99 * k.stats().compare.calls());
  }
}

TEST_CASE("ties on an integer grid compare exactly equal", "[sizes]") {
  // Unweighted, and with weights 1 and 2 (negative sizes): small integers,
  // the 128-bit path.
  for (const bool weighted : {false, true}) {
    INFO("weighted " << weighted);
    Input in;
    in.pts = testing::grid_points(4);
    if (weighted)
      for (std::size_t i = 0; i < in.pts.size(); ++i) in.w.push_back(1.0 + double(i % 2));
    SizeKernel k = in.kernel();
    check_random_simplices(k, in, 300, 31);
    CHECK(k.stats().compare.perturbed > 1000);  // exact ties, each returned as 0
  }
}

TEST_CASE("small fractions of integer input are the exact sizes", "[sizes]") {
  // Unweighted and with integer weights: N / D in doubles, equal to the
  // exact size and ordered as it; none for non-integer input.
  for (const bool weighted : {false, true}) {
    INFO("weighted " << weighted);
    Input in;
    in.pts = testing::grid_points(4);
    if (weighted)
      for (std::size_t i = 0; i < in.pts.size(); ++i) in.w.push_back(double(i % 3));
    REQUIRE(all_small_integers(in.pts.data(), in.w.empty() ? nullptr : in.w.data(), in.pts.size()));
    const SizeKernel k = in.kernel(), promised(in.pts.data(), in.w.empty() ? nullptr : in.w.data(), true);
    std::mt19937_64 rng(37);
    std::vector<std::pair<SmallFraction, mpq_class>> sizes;
    for (int trial = 0; trial < 400; ++trial) {
      const Simplex s = random_simplex(rng, in.pts.size(), 1 + int(trial % 4));
      if (!oracle(in, s)) continue;
      const std::optional<SmallFraction> f = small_fraction(k, s);
      REQUIRE(f);
      CHECK(f->den > 0);
      const std::optional<SmallFraction> g = small_fraction(promised, s);  // no check of the points
      REQUIRE(g);
      CHECK((g->num == f->num && g->den == f->den));
      mpq_class q(mpz_class(long(f->num)), mpz_class(long(f->den)));
      q.canonicalize();
      CHECK(q == exact_size(k, s));
      sizes.emplace_back(*f, exact_size(k, s));
    }
    int wrong = 0, ties = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) {
        const int c = compare_small(sizes[i].first, sizes[j].first);
        wrong += c != sign(sizes[i].second - sizes[j].second);
        ties += c == 0;
      }
    CHECK(wrong == 0);
    CHECK(ties > 0);
  }
  Input half;
  half.pts = testing::grid_points(3, 0.5);
  CHECK(!small_fraction(half.kernel(), {1, 2, 3}));
  CHECK(!all_small_integers(half.pts.data(), nullptr, half.pts.size()));
  const Vec3 large[2] = {{0, 0, 0}, {0x1p51, 0, 0}};  // an integer, but differences could round
  CHECK(!all_small_integers(large, nullptr, 2));
  const Vec3 unit[2] = {{0, 0, 0}, {1, 0, 0}};
  const double weights[2] = {1, 0.5};
  CHECK(all_small_integers(unit, weights, 1));
  CHECK(!all_small_integers(unit, weights, 2));
}

TEST_CASE("congruent triangles and cospherical tetrahedra share their size", "[sizes]") {
  // Images of one triangle under the 48 symmetries of the cube and a few
  // translations, on a dyadic grid off the origin (exact in doubles).
  const std::array<std::array<int, 3>, 3> tri{{{0, 0, 0}, {3, 1, 0}, {1, 2, 5}}};
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const double weight : {0.0, 0.3125}) {
    Input in;
    for (const auto& p : perms)
      for (int signs = 0; signs < 8; ++signs)
        for (int t = 0; t < 3; ++t)
          for (const auto& v : tri) {
            double c[3];
            for (int a = 0; a < 3; ++a) c[a] = ((signs >> a) & 1 ? -1 : 1) * v[p[a]] + 7 * t;
            in.pts.push_back({1024.125 + 0.375 * c[0], -3.5 + 0.375 * c[1], 7.75 + 0.375 * c[2]});
          }
    if (weight != 0) in.w.assign(in.pts.size(), weight);
    SizeKernel k = in.kernel();
    const Simplex first(0, 1, 2);
    int unequal = 0;
    for (Index i = 3; i < in.pts.size(); i += 3) unequal += k.compare(first, {i, i + 1, i + 2}) != 0;
    CHECK(unequal == 0);
    const auto sp = oracle(in, first);
    REQUIRE(sp);
    CHECK(exact_size(k, first) == sp->r2);
  }

  // Any 4 non-coplanar corners of a cube lie on its circumsphere.
  Input cube;
  for (int i = 0; i < 8; ++i) cube.pts.push_back({0.5 + 0.25 * (i & 1), 2.0 + 0.25 * ((i >> 1) & 1), -1.0 + 0.25 * (i >> 2)});
  SizeKernel k = cube.kernel();
  std::vector<Simplex> tets;
  for (Index a = 0; a < 8; ++a)
    for (Index b = a + 1; b < 8; ++b)
      for (Index c = b + 1; c < 8; ++c)
        for (Index d = c + 1; d < 8; ++d)
          if (oracle(cube, {a, b, c, d})) tets.push_back({a, b, c, d});
  CHECK(tets.size() == 58);  // 70 minus 6 faces and 6 diagonal planes
  int unequal = 0;
  for (const Simplex& t : tets) {
    unequal += k.compare(t, tets[0]) != 0;
    unequal += k.compare(t, 3 * 0.25 * 0.25 / 4) != 0;  // (side^2) 3/4
  }
  CHECK(unequal == 0);
}

TEST_CASE("sizes one ulp apart are ordered exactly", "[sizes]") {
  Input in;
  in.pts = testing::random_points(12, 41, 100.0);
  in.w = testing::random_weights(12, 42, 0, 5);
  // Copies of simplex {0,1,2} and {3..6} with one coordinate nudged by one ulp.
  for (int c = 0; c < 7; ++c) {
    for (int a = 0; a < 3; ++a)
      for (const double dir : {-HUGE_VAL, HUGE_VAL}) {
        Vec3 p = in.pts[c];
        double& x = a == 0 ? p.x : a == 1 ? p.y : p.z;
        x = std::nextafter(x, dir);
        in.pts.push_back(p);
        in.w.push_back(in.w[c]);
      }
  }
  SizeKernel k = in.kernel();
  std::vector<Simplex> s;
  std::vector<mpq_class> exact;
  auto add = [&](Simplex x) {
    const auto sp = oracle(in, x);
    REQUIRE(sp);
    s.push_back(x), exact.push_back(sp->r2);
  };
  add({0, 1}), add({0, 1, 2}), add({3, 4, 5, 6});
  for (Index i = 12; i < in.pts.size(); ++i) {
    const int c = int(i - 12) / 6;  // the original this point copies
    if (c < 2) add({i, Index(1 - c)});
    if (c < 3) {
      Simplex t(0, 1, 2);
      t.v[c] = i;
      add(t);
    } else {
      Simplex t(3, 4, 5, 6);
      t.v[c - 3] = i;
      add(t);
    }
  }
  check_all_pairs(k, s, exact);
  CHECK(k.stats().compare.exact > 0);
}

TEST_CASE("inputs outside the filter's range are compared exactly", "[sizes]") {
  for (const double scale : {0x1p-200, 0x1p300}) {
    Input in;
    in.pts = testing::random_points(40, 51);
    for (Vec3& p : in.pts) p = {p.x * scale, p.y * scale, p.z * scale};
    CHECK(!all_in_filter_range(in.pts.data(), nullptr, in.pts.size()));
    SizeKernel k = in.kernel();
    check_random_simplices(k, in, 40, 52);
  }
}

TEST_CASE("points promised in the filter's range give the sizes checked ones do", "[sizes]") {
  // The range's ends: coordinates 0 or of magnitude 2^-27 to 2^99, weights
  // 0 or 2^-107 to 2^199.
  const auto in_range = [](Vec3 p, double w) { return all_in_filter_range(&p, &w, 1); };
  CHECK(in_range({0, 0x1p-27, -0x1p99}, 0));
  CHECK(in_range({1, 1, 1}, 0x1p-107));
  CHECK(in_range({1, 1, 1}, 0x1p199));
  CHECK(!in_range({0x1p-28, 1, 1}, 0));
  CHECK(!in_range({1, -0x1p100, 1}, 0));
  CHECK(!in_range({1, 1, 1}, 0x1p-108));
  CHECK(!in_range({1, 1, 1}, 0x1p200));
  // Random weighted points near the lower end (differences down to 2^-79,
  // products near the filter's underflow limit) and at unit scale: the
  // promised kernel's sizes and attachments are the checking kernel's.
  for (const double scale : {0x1p-26, 1.0, 0x1p90}) {
    INFO("scale " << scale);
    Input in;
    in.pts = testing::random_points(60, 71);
    in.w = testing::random_weights(60, 72, 0, 0.05);
    for (Vec3& p : in.pts) p = {p.x * scale + 0x1p-27, p.y * scale + 0x1p-27, p.z * scale + 0x1p-27};
    for (double& w : in.w) w *= scale * scale;
    REQUIRE(all_in_filter_range(in.pts.data(), in.w.data(), in.pts.size()));
    SizeKernel checked = in.kernel(), promised(in.pts.data(), in.w.data(), false, true);
    std::mt19937_64 rng(73);
    int differ = 0, finite = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const Simplex s = random_simplex(rng, in.pts.size(), 1 + trial % 4);
      const Size a = checked.size(s), b = promised.size(s);
      differ += std::bit_cast<std::uint64_t>(a.value) != std::bit_cast<std::uint64_t>(b.value) ||
                std::bit_cast<std::uint64_t>(a.error) != std::bit_cast<std::uint64_t>(b.error);
      finite += std::isfinite(a.error);
      if (s.n < 4) differ += checked.attached(s, Index(trial % 60)) != promised.attached(s, Index(trial % 60));
    }
    CHECK(differ == 0);
    CHECK(finite > 300);
  }
}

namespace {

// The double nearest to q, ties to even, by rationals alone.
double nearest(const mpq_class& q) {
  const double t = q.get_d();  // truncated: t and its neighbour away from 0 bracket q
  const double away = std::nextafter(t, q > 0 ? HUGE_VAL : -HUGE_VAL);
  const int c = cmp(abs(q - mpq_class(t)), abs(mpq_class(away) - q));
  if (c != 0 || mpq_class(t) == q) return c <= 0 ? t : away;
  return (std::bit_cast<std::uint64_t>(t) & 1) == 0 ? t : away;
}
bool is_midpoint(const mpq_class& q) {
  const double t = q.get_d();
  return mpq_class(t) != q && 2 * q == mpq_class(t) + mpq_class(std::nextafter(t, q > 0 ? HUGE_VAL : -HUGE_VAL));
}

struct RoundingCounts {
  std::size_t checked = 0, decided = 0, ties = 0;
};

// rounded_size, its double-double path (where it decides) and its exact
// path all give the nearest double, bit for bit (a vertex of weight 0 has
// size -0: its exact value -w). Vertices do not count: only the exact path
// takes them.
void check_rounding(const SizeKernel& k, const Simplex& s, const mpq_class& exact, RoundingCounts& counts) {
  const std::uint64_t want = std::bit_cast<std::uint64_t>(s.n == 1 && exact == 0 ? -0.0 : nearest(exact));
  INFO("exact size " << exact.get_str() << ", vertices " << s.v[0] << " " << s.v[1] << " " << s.v[2] << " " << s.v[3]);
  CHECK(std::bit_cast<std::uint64_t>(rounded_exact(k, s)) == want);
  CHECK(std::bit_cast<std::uint64_t>(k.rounded_size(s)) == want);
  const std::optional<double> fast = rounded_filtered(k, s), portable = rounded_filtered(k, s, false);
  CHECK(fast.has_value() == portable.has_value());  // FMA or not, the same exact products
  if (fast) {
    CHECK(std::bit_cast<std::uint64_t>(*fast) == want);
    CHECK(std::bit_cast<std::uint64_t>(*portable) == want);
    ++counts.decided;
  }
  counts.ties += is_midpoint(exact);
  counts.checked += s.n > 1;
}

}  // namespace

TEST_CASE("rounded sizes: the double-double path rounds as the exact one", "[sizes]") {
  SECTION("edges whose sizes are ties or near ties, over magnitudes") {
    // An edge (0,0,0)-(a,b,c) has size (a^2+b^2+c^2)/4: integers of 27-28
    // bits make 54-57 bit squares, on or next to midpoints of doubles.
    std::mt19937_64 rng(61);
    std::uniform_int_distribution<std::int64_t> bits27(std::int64_t(94906266), (std::int64_t(1) << 27) - 1);
    std::uniform_int_distribution<std::int64_t> bits28(std::int64_t(1) << 27, (std::int64_t(1) << 28) - 1);
    for (const int e : {-150, -78, -30, 0, 40, 70, 200}) {  // -150 and 200: outside the filter's range
      INFO("scale 2^" << e);
      Input in;
      in.pts.push_back({0, 0, 0});
      for (int i = 0; i < 200; ++i) {
        const double a = std::ldexp(double(i % 2 ? bits27(rng) : bits28(rng)), e);
        const double b = i % 3 ? 0.0 : std::ldexp(double(bits27(rng)), e - 13);
        in.pts.push_back({a, b, i % 5 ? 0.0 : std::ldexp(double(bits27(rng)), e)});
      }
      in.pts.push_back({std::ldexp(double((std::int64_t(1) << 27) - 1), e), 0, 0});  // size a tie
      const SizeKernel k = in.kernel();
      RoundingCounts counts;
      for (Index i = 1; i < in.pts.size(); ++i) check_rounding(k, {0, i}, oracle(in, {0, i})->r2, counts);
      CHECK(counts.ties > 0);
      if (e > -100 && e < 100) CHECK(counts.decided > counts.checked / 2);  // all but ties and near ties
    }
  }
  SECTION("weighted edges, triangles and tetrahedra on grids: exact small rationals") {
    for (const double spacing : {1.0, 0x1p-40, 0x1p30}) {
      for (const bool weighted : {false, true}) {
        INFO("spacing " << spacing << " weighted " << weighted);
        Input in;
        in.pts = testing::grid_points(4, spacing);
        if (weighted)
          for (std::size_t i = 0; i < in.pts.size(); ++i) in.w.push_back(spacing * spacing * (0.25 + double(i % 3)));
        std::vector<Simplex> s;
        std::vector<mpq_class> exact;
        random_simplices(in, 400, 62, s, exact);
        const SizeKernel k = in.kernel();
        RoundingCounts counts;
        for (std::size_t i = 0; i < s.size(); ++i) check_rounding(k, s[i], exact[i], counts);
        CHECK(counts.decided > counts.checked / 2);
      }
    }
  }
  SECTION("random and nearly flat simplices") {
    Input in;
    in.pts = testing::random_points(300, 63, 10.0);
    in.w = testing::random_weights(300, 64, -0.5, 2.0);
    for (int i = 0; i < 20; ++i)  // slivers: a fourth point one ulp-ish off the plane of three
      in.pts.push_back({0.5 + 0.01 * i, 0.25, std::ldexp(1.0 + i, -40)}), in.w.push_back(0);
    std::vector<Simplex> s;
    std::vector<mpq_class> exact;
    random_simplices(in, 1500, 65, s, exact);
    for (const Index base : {Index(0), Index(1)})
      for (Index i = 300; i < in.pts.size(); ++i) {
        const Simplex t(base == 0 ? Index(300) : Index(301), Index(302), Index(303), i);
        if (i > 303 && oracle(in, t)) s.push_back(t), exact.push_back(oracle(in, t)->r2);
      }
    for (const bool weighted : {false, true}) {
      const SizeKernel k(in.pts.data(), weighted ? in.w.data() : nullptr);
      Input plain = in;
      if (!weighted) plain.w.clear();
      RoundingCounts counts;
      for (std::size_t i = 0; i < s.size(); ++i)
        if (const auto sp = oracle(plain, s[i])) check_rounding(k, s[i], sp->r2, counts);
      CHECK(counts.decided > 0.99 * double(counts.checked));
    }
  }
}

TEST_CASE("degenerate simplices have no size", "[sizes]") {
  Input in;
  in.pts = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 0}};
  SizeKernel k = in.kernel();
  CHECK_THROWS_AS(k.compare({0, 1, 2}, {0, 3}), Error);    // collinear
  CHECK_THROWS_AS(k.compare({0, 3, 4, 5}, 1.0), Error);    // coplanar
  CHECK_THROWS_AS(exact_size(k, {0, 6}), Error);            // same point twice
  CHECK_THROWS_AS(k.attached({0, 1, 2}, 3), Error);
  CHECK(!std::isfinite(k.size({0, 1, 2}).error));
}

TEST_CASE("attached: obtuse and acute triangles, points on the sphere", "[sizes]") {
  Input in;
  in.pts = {{0, 0, 0}, {4, 0, 0}, {1, 1, 0}, {2, 3, 0}, {2, 2, 0}, {0, 4, 0}, {2, 2, 1}, {2, 2, 3}, {4, 4, 0}, {2, 0, 2}};
  SizeKernel k = in.kernel();
  // The edge opposite the obtuse angle is attached by its vertex.
  CHECK(k.attached({0, 1}, 2));
  CHECK(!k.attached({0, 1}, 3));  // acute triangle
  CHECK(!k.attached({0, 1}, 4));  // right angle: on the sphere, not attached
  CHECK(!k.attached({1, 0}, 4));
  CHECK(!k.attached({0, 1}, 0));  // its own vertex: on the sphere
  // Triangle (0,0,0),(4,0,0),(0,4,0): center (2,2,0), r^2 = 8.
  CHECK(k.attached({0, 1, 5}, 6));
  CHECK(!k.attached({0, 1, 5}, 7));
  CHECK(!k.attached({5, 0, 1}, 8));  // on the sphere, in the plane
  CHECK(!k.attached({0, 1, 5}, 9));  // on the sphere, off the plane
  CHECK(k.stats().attached.perturbed == 5);

  SECTION("weighted vertices and edges") {
    Input w;
    w.pts = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
    w.w = {0, 2, 0, 0.5};
    SizeKernel kw = w.kernel();
    CHECK(kw.attached(Simplex(0), 1));   // 1 - 2 < 0
    CHECK(!kw.attached(Simplex(1), 0));  // 1 + 2 > 0
    CHECK(!kw.attached(Simplex(0), 3));  // 2 - 0.5 > 0
    // Edge {0,2}: center (1,0,0), r^2 = 1; q = (1,1,0) with w 0.5: 1 - 1 - 0.5 < 0.
    CHECK(kw.attached({0, 2}, 3));
    // Its weight exactly cancels the margin: 1 - 1 - 0 on the sphere when w = 0.
    w.w[3] = 0;
    CHECK(!kw.attached({0, 2}, 3));
  }
}

TEST_CASE("attached agrees with exact power distances", "[sizes]") {
  // Random weighted points; grids with dyadic weights (the 128-bit stage),
  // integer weights and none (integers decided in doubles; unweighted edges
  // have a test of their own).
  enum Set { random, dyadic_grid, integer_grid, plain_grid };
  for (const Set set : {random, dyadic_grid, integer_grid, plain_grid}) {
    INFO("set " << int(set));
    const bool grid = set != random;
    Input in;
    in.pts = grid ? testing::grid_points(4) : testing::random_points(200, 61);
    if (set == random) in.w = testing::random_weights(200, 62, 0, 0.05);
    if (set == dyadic_grid || set == integer_grid)
      for (std::size_t i = 0; i < in.pts.size(); ++i) in.w.push_back((set == dyadic_grid ? 0.25 : 1.0) * double(i % 3));
    SizeKernel k = in.kernel();
    std::mt19937_64 rng(63);
    std::uniform_int_distribution<int> dim(1, 3);
    std::uniform_int_distribution<Index> pick(0, Index(in.pts.size() - 1));
    int wrong = 0, on_sphere = 0, wrong_any = 0, any_attached = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      const Simplex s = random_simplex(rng, in.pts.size(), dim(rng));
      const auto sp = oracle(in, s);
      if (!sp) continue;
      const Index q = pick(rng);
      const mpq_class pi = power(in, *sp, q);
      on_sphere += pi == 0;
      wrong += k.attached(s, q) != (pi < 0);
      // attached_any: the same test for several points at once (one of them
      // a vertex of s, on the sphere).
      const std::array<Index, 3> qs{pick(rng), s.v[0], q};
      bool any = false;
      for (const Index x : qs) any = any || power(in, *sp, x) < 0;
      any_attached += any;
      wrong_any += k.attached_any(s, qs) != any;
      // size_unless_attached: nothing when attached, else size(s) bit for bit.
      const std::optional<Size> z = k.size_unless_attached(s, qs);
      const Size want = k.size(s);
      wrong_any += z.has_value() == any;
      if (z)
        wrong_any += std::bit_cast<std::uint64_t>(z->value) != std::bit_cast<std::uint64_t>(want.value) ||
                     std::bit_cast<std::uint64_t>(z->error) != std::bit_cast<std::uint64_t>(want.error);
    }
    CHECK(wrong == 0);
    CHECK(wrong_any == 0);
    CHECK(any_attached > 0);
    if (grid) CHECK(on_sphere > 0);
    // Integers leave the filter's ties to doubles: no exact stage ran.
    if (set == integer_grid || set == plain_grid) CHECK(k.stats().attached.exact == 0);
  }
}

TEST_CASE("size kernel throughput", "[.][sizes_bench]") {
  using Clock = std::chrono::steady_clock;
  auto ns_per = [](Clock::time_point t0, std::size_t n) {
    return std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / double(n);
  };
  // 4096 points stay in cache (arithmetic cost); 10^6 points scattered at
  // random add a cache miss per vertex (as a careless caller would pay).
  const std::size_t m = 1000000;
  for (const std::size_t n : {std::size_t(4096), std::size_t(1000000)}) {
    Input in;
    in.pts = testing::random_points(n, 71);
    std::mt19937_64 rng(72);
    for (const bool weighted : {false, true}) {
      if (weighted) in.w = testing::random_weights(n, 73, 0, 1e-4);
      SizeKernel k = in.kernel();
      for (int vertices = 2; vertices <= 4; ++vertices) {
        std::vector<Simplex> s(m);
        for (auto& x : s) x = random_simplex(rng, n, vertices);
        double sum = 0;
        auto t0 = Clock::now();
        for (const auto& x : s) sum += k.size(x).value;
        const double t_size = ns_per(t0, m);
        int acc = 0;
        t0 = Clock::now();
        for (std::size_t i = 0; i + 1 < m; ++i) acc += k.compare(s[i], s[i + 1]);
        const double t_cmp = ns_per(t0, m - 1);
        t0 = Clock::now();
        for (std::size_t i = 0; i < m; ++i) acc += k.compare(s[i], 1e-3);
        const double t_alpha = ns_per(t0, m);
        std::vector<Size> z(m);
        for (std::size_t i = 0; i < m; ++i) z[i] = k.size(s[i]);
        t0 = Clock::now();
        for (std::size_t i = 0; i + 1 < m; ++i) acc += k.compare(s[i], z[i], s[i + 1], z[i + 1]);
        const double t_pre = ns_per(t0, m - 1);
        std::printf("n=%zu %s %d vertices: size %.1f ns, compare %.1f ns, compare(alpha) %.1f ns, "
                    "compare(precomputed sizes) %.1f ns (%llu exact) [%g %d]\n",
                    n, weighted ? "weighted  " : "unweighted", vertices, t_size, t_cmp, t_alpha, t_pre,
                    static_cast<unsigned long long>(k.stats().compare.exact + k.stats().compare.perturbed), sum, acc);
      }
      std::vector<Simplex> s(m);
      std::vector<Index> q(m);
      for (std::size_t i = 0; i < m; ++i) s[i] = random_simplex(rng, n, 2 + int(i % 2)), q[i] = Index(rng() % n);
      int acc = 0;
      auto t0 = Clock::now();
      for (std::size_t i = 0; i < m; ++i) acc += k.attached(s[i], q[i]);
      std::printf("n=%zu %s attached (edges, triangles): %.1f ns (%llu exact) [%d]\n", n,
                  weighted ? "weighted  " : "unweighted", ns_per(t0, m),
                  static_cast<unsigned long long>(k.stats().attached.exact + k.stats().attached.perturbed), acc);
    }
  }
  // Exact paths: tied tetrahedra of a grid cube (128-bit) and one-ulp apart
  // triangles of random points (GMP).
  Input cube;
  for (int i = 0; i < 8; ++i) cube.pts.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  SizeKernel kc = cube.kernel();
  const std::size_t reps = 200000;
  int acc = 0;
  auto t0 = Clock::now();
  for (std::size_t i = 0; i < reps; ++i) acc += kc.compare({0, 3, 5, 6}, {1, 2, 4, 7});
  std::printf("exact tie, grid tetrahedra (128-bit): %.1f ns [%d]\n", ns_per(t0, reps), acc);
  Input near;
  near.pts = testing::random_points(3, 74);
  near.pts.push_back({std::nextafter(near.pts[0].x, 2.0), near.pts[0].y, near.pts[0].z});
  SizeKernel kn = near.kernel();
  t0 = Clock::now();
  for (std::size_t i = 0; i < reps / 10; ++i) acc += kn.compare({0, 1, 2}, {3, 1, 2});
  std::printf("exact, triangles one ulp apart (GMP): %.1f ns [%d]\n", ns_per(t0, reps / 10), acc);
  t0 = Clock::now();
  for (std::size_t i = 0; i < reps / 10; ++i) acc += exact_size(kn, {0, 1, 2}) > 0;
  std::printf("exact_size of a triangle (GMP): %.1f ns [%d]\n", ns_per(t0, reps / 10), acc);
}
