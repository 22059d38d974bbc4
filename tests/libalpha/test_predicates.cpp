// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gmpxx.h>

#include "alpha/predicates.hpp"
#include "point_sets.hpp"

using namespace alpha;

TEST_CASE("orient3d: sign convention and exact zero", "[predicates]") {
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.5, 0.5, 0}};
  Kernel k(p.data(), nullptr);
  CHECK(k.orient3d(0, 1, 2, 3) == 1);
  CHECK(k.orient3d(0, 1, 2, 4) == -1);
  CHECK(k.orient3d(1, 0, 2, 3) == -1);
  CHECK(k.orient3d(0, 1, 2, 5) == 0);
  CHECK(k.stats().orient.perturbed == 1);  // the zero needed exact arithmetic
}

TEST_CASE("orient3d stays exact where doubles fail", "[predicates]") {
  // Points on a line through non-dyadic coordinates, nudged by one ulp:
  // naive evaluation gets the sign wrong or zero; exact must agree with
  // the sign of the nudge.
  const double a = 0.1, b = 0.7;
  for (int s : {-1, 1}) {
    const double z = std::nextafter(0.0, s);
    std::vector<Vec3> p{{a, a, 0}, {b, a, 0}, {a, b, 0}, {0.3, 0.3, z}};
    Kernel k(p.data(), nullptr);
    CHECK(k.orient3d(0, 1, 2, 3) == s);
  }
  // Near-coplanar with large offsets: 1e8 + tiny.
  std::vector<Vec3> q{{1e8, 1e8, 1e8}, {1e8 + 1, 1e8, 1e8}, {1e8, 1e8 + 1, 1e8}, {1e8 + 0.5, 1e8 + 0.5, 1e8 + 1.5e-8}};
  Kernel k(q.data(), nullptr);
  CHECK(k.orient3d(0, 1, 2, 3) == 1);
}

TEST_CASE("power test: in, out, on the sphere, and weights", "[predicates]") {
  // Unit-cube corners: (1,1,1) is on the circumsphere of the first four.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0.5}, {2, 2, 2}, {1, 1, 1}};
  Kernel k(p.data(), nullptr);
  CHECK(k.power_conflict(0, 1, 2, 3, 4));
  CHECK_FALSE(k.power_conflict(0, 1, 2, 3, 5));
  CHECK(k.power_side_exact(0, 1, 2, 3, 6) == 0);
  // Perturbation: point 6 has the largest index, so its raised weight wins.
  CHECK(k.power_conflict(0, 1, 2, 3, 6));
  // With a large weight, a far point conflicts; with a negative one, a near point does not.
  std::vector<double> w{0, 0, 0, 0, -1, 20, 0};
  Kernel kw(p.data(), w.data());
  CHECK_FALSE(kw.power_conflict(0, 1, 2, 3, 4));
  CHECK(kw.power_conflict(0, 1, 2, 3, 5));
}

namespace {

// p conflicts with the cell (a,b,c,d) put in positive order; o = orient3d(a,b,c,d) != 0.
bool conflict(Kernel& k, int o, Index a, Index b, Index c, Index d, Index p) {
  return o > 0 ? k.power_conflict(a, b, c, d, p) : k.power_conflict(b, a, c, d, p);
}

// The perturbed power test is the sign of one 5-point lifted determinant:
// for the facet (b,c,d) and points a, e off its plane, e conflicts with the
// cell (a,b,c,d) exactly when a conflicts with (e,b,c,d) if a and e lie on
// opposite sides (the facet is locally regular or not, seen from either
// cell), and exactly when a does not if they lie on the same side. An even
// permutation of the cell's vertices changes nothing. Returns the number
// of 5-point tests made.
int check_five_point_symmetry(Kernel& k, Index n) {
  int tests = 0;
  for (Index b = 0; b < n; ++b)
    for (Index c = b + 1; c < n; ++c)
      for (Index d = c + 1; d < n; ++d)
        for (Index a = 0; a < n; ++a) {
          if (a == b || a == c || a == d) continue;
          const int oa = k.orient3d(a, b, c, d);
          if (oa == 0) continue;
          for (Index e = a + 1; e < n; ++e) {
            if (e == b || e == c || e == d) continue;
            const int oe = k.orient3d(e, b, c, d);
            if (oe == 0) continue;
            const bool from_a = conflict(k, oa, a, b, c, d, e), from_e = conflict(k, oe, e, b, c, d, a);
            INFO("cell " << a << ' ' << b << ' ' << c << ' ' << d << " and " << e);
            CHECK(from_a == (oa != oe ? from_e : !from_e));
            CHECK(from_a == conflict(k, oa, b, c, a, d, e));
            ++tests;
          }
        }
  return tests;
}

// Sign of the lifted determinant of rows (q_i - p, |q_i - p|^2 - (w_i - w_p)),
// in rationals: conflict when negative. An oracle independent of the
// library's dyadic arithmetic.
int lifted_sign(const std::vector<Vec3>& q, const std::vector<double>& w, const std::array<Index, 4>& v, Index p) {
  mpq_class r[4][4];
  for (int i = 0; i < 4; ++i) {
    const Vec3 &a = q[v[i]], &b = q[p];
    r[i][0] = mpq_class(a.x) - mpq_class(b.x), r[i][1] = mpq_class(a.y) - mpq_class(b.y);
    r[i][2] = mpq_class(a.z) - mpq_class(b.z);
    r[i][3] = r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2] - (mpq_class(w[v[i]]) - mpq_class(w[p]));
  }
  const auto d3 = [&](int a, int b, int c) -> mpq_class {
    return r[a][0] * (r[b][1] * r[c][2] - r[b][2] * r[c][1]) - r[a][1] * (r[b][0] * r[c][2] - r[b][2] * r[c][0]) +
           r[a][2] * (r[b][0] * r[c][1] - r[b][1] * r[c][0]);
  };
  const mpq_class det = -r[0][3] * d3(1, 2, 3) + r[1][3] * d3(0, 2, 3) - r[2][3] * d3(0, 1, 3) + r[3][3] * d3(0, 1, 2);
  return sgn(det);
}

}  // namespace

TEST_CASE("Perturbed power test is antisymmetric in the 5-point sense", "[predicates][degenerate]") {
  // The 8 corners of a cube are cospherical: every power test ties and is
  // decided by the perturbation.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 0, 1}, {0, 1, 1}};
  Kernel k(p.data(), nullptr);
  CHECK(check_five_point_symmetry(k, 8) > 100);
  CHECK(k.stats().power.perturbed == k.stats().power.calls());
  // Integer points on a sphere, one of them lighter: ties, decided from the
  // doubles (in_doubles), from the 128-bit stage (scaled by 2^-3) and from
  // GMP (also moved far off the origin).
  std::vector<Vec3> s = testing::sphere_points(9);
  s.resize(12);
  std::vector<double> w(s.size(), 3.0);
  w[5] = 2.0;
  REQUIRE(Kernel::exact_in_doubles(s, w));
  std::vector<Vec3> s128(s), sgmp(s);
  std::vector<double> w_scaled(w);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s128[i] = {s[i].x / 8 + 0.5, s[i].y / 8, s[i].z / 8};
    sgmp[i] = {s[i].x / 8 + 3e6, s[i].y / 8 - 3e6, s[i].z / 8};
    w_scaled[i] = w[i] / 64;
  }
  Kernel kd(s.data(), w.data(), nullptr, true), k128(s128.data(), w_scaled.data()), kgmp(sgmp.data(), w_scaled.data());
  for (Kernel* kk : {&kd, &k128, &kgmp}) {
    CHECK(check_five_point_symmetry(*kk, Index(s.size())) > 1000);
    CHECK(kk->stats().power.perturbed > 1000);
  }
}

TEST_CASE("Filter, 128-bit and GMP paths agree", "[predicates][degenerate]") {
  // Each trial: random doubles (the filter decides), or five points of an
  // integer sphere, one moved by at most a unit, with weights 0 or equal
  // (ties are common), or five points of that sphere scaled by 2^19 + 1
  // (coordinates of 22 bits) with the tested point's weight moved by 1 (a
  // nonzero value far below the filter's error bound). Each configuration is
  // tested as it is, scaled by 2^-3 (weights by 2^-6) and moved by 1/2, and
  // moved by 3e6 instead: small integers go to the integer stage, the 128-bit
  // stage and GMP; the wide ones to the 128-bit stage, GMP and the 128-bit
  // stage. Scaling and moving keep every sign, so all answers, ties included,
  // must be equal, and equal to a determinant in rationals wherever it is
  // nonzero.
  const std::vector<Vec3> sphere = testing::sphere_points(50);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::size_t> pick(0, sphere.size() - 1);
  std::uniform_int_distribution<int> nudge(-1, 1), small_weight(0, 3), sign(0, 1);
  std::uniform_real_distribution<double> u(-1, 1);
  int ties = 0, checked = 0;
  StageCounts real_counts, scaled_counts[3];
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<Vec3> p(5);
    std::vector<double> w(5);
    const int kind = trial % 4;  // random doubles; small integers with weights 0, equal; wide integers
    const double equal = small_weight(rng), scale = kind == 3 ? 0x1p19 + 1 : 1;
    for (int i = 0; i < 5; ++i) {
      if (kind == 0) {
        p[i] = {u(rng), u(rng), u(rng)}, w[i] = u(rng) * 0.1;
      } else {
        const Vec3& q = sphere[pick(rng)];
        p[i] = {q.x * scale, q.y * scale, q.z * scale};
        w[i] = kind == 1 ? 0.0 : equal;
      }
    }
    if (kind == 1 || kind == 2) p[4].x += nudge(rng);
    if (kind == 3) w[4] += sign(rng) ? 1 : -1;
    Kernel k(p.data(), w.data());
    std::array<Index, 4> v{0, 1, 2, 3};
    const int o = k.orient3d(0, 1, 2, 3);
    if (o == 0) continue;
    if (o < 0) std::swap(v[0], v[1]);
    const int det = lifted_sign(p, w, v, 4);
    ++checked;
    INFO("trial " << trial << " lifted sign " << det);
    CHECK(k.power_side_exact(v[0], v[1], v[2], v[3], 4) == -det);
    const bool answer = k.power_conflict(v, 4);
    if (det != 0) CHECK(answer == (det < 0));
    if (kind == 0) {
      real_counts += k.stats().power;
      continue;
    }
    ties += det == 0;
    std::vector<Vec3> s128(5), sgmp(5);
    std::vector<double> ws(5);
    for (int i = 0; i < 5; ++i) {
      s128[i] = {p[i].x / 8 + 0.5, p[i].y / 8, p[i].z / 8 - 0.5};
      sgmp[i] = {p[i].x / 8 + 3e6, p[i].y / 8, p[i].z / 8 - 3e6};
      ws[i] = w[i] / 64;
    }
    Kernel k128(s128.data(), ws.data()), kgmp(sgmp.data(), ws.data());
    if (kind != 3) {
      REQUIRE(Kernel::exact_in_doubles(p, w));
      Kernel kd(p.data(), w.data(), nullptr, true);
      CHECK(kd.power_conflict(v, 4) == answer);
    }
    CHECK(k128.power_conflict(v, 4) == answer);
    CHECK(kgmp.power_conflict(v, 4) == answer);
    CHECK(k128.power_side_exact(v[0], v[1], v[2], v[3], 4) == -det);
    CHECK(kgmp.power_side_exact(v[0], v[1], v[2], v[3], 4) == -det);
    scaled_counts[0] += k.stats().power, scaled_counts[1] += k128.stats().power, scaled_counts[2] += kgmp.stats().power;
  }
  // Every stage was reached: the filter on random doubles, the exact and
  // perturbed stages of each form.
  CHECK(checked > 1500);
  CHECK(ties > 100);
  CHECK(real_counts.filtered > 400);
  for (const StageCounts& c : scaled_counts) {
    CHECK(c.exact > 100);
    CHECK(c.perturbed == std::uint64_t(ties));
  }
}

TEST_CASE("Hull conflict: outside, inside, and coplanar inside the circle", "[predicates][degenerate]") {
  // Facet (0,1,2) in z = 0 oriented with +z outside.
  std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 1}, {0.5, 0.5, -1}, {0.5, 0.5, 0}, {5, 5, 0}};
  Kernel k(p.data(), nullptr);
  REQUIRE(k.orient3d(0, 1, 2, 3) == 1);
  CHECK(k.hull_conflict(0, 1, 2, 3));
  CHECK_FALSE(k.hull_conflict(0, 1, 2, 4));
  CHECK(k.hull_conflict(0, 1, 2, 5));        // coplanar, inside the circumcircle
  CHECK_FALSE(k.hull_conflict(0, 1, 2, 6));  // coplanar, far outside it
}

TEST_CASE("Integer input decided in doubles agrees with the dyadic stages", "[predicates][degenerate]") {
  // The same configurations scaled by 2^-3 (weights by 2^-6) are not
  // integers and go through the dyadic stages; scaling by a power of two
  // keeps every sign, so every answer, perturbed ones included, must match.
  // Coordinates up to 600 also exercise the 2^9 bound of the double stage.
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> near(-3, 3), far(-600, 600);
  int perturbed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<Vec3> p(5), scaled(5);
    std::vector<double> w(5), scaled_w(5);
    const bool wide = trial % 5 == 0;
    for (int i = 0; i < 5; ++i) {
      auto c = [&] { return double(wide ? far(rng) : near(rng)); };
      p[i] = {c(), c(), c()};
      w[i] = trial % 2 ? double(near(rng)) : 0.0;
      scaled[i] = {p[i].x / 8, p[i].y / 8, p[i].z / 8};
      scaled_w[i] = w[i] / 64;
    }
    Kernel k(p.data(), w.data()), ks(scaled.data(), scaled_w.data());
    // p = point 0, below the cell's points in the perturbation order, so
    // that a tie is decided by the cell's cofactors.
    const int o = k.orient3d(1, 2, 3, 4);
    REQUIRE(o == ks.orient3d(1, 2, 3, 4));
    if (o == 0) continue;
    const Index a = o > 0 ? 1 : 2, b = o > 0 ? 2 : 1;
    CHECK(k.power_side_exact(a, b, 3, 4, 0) == ks.power_side_exact(a, b, 3, 4, 0));
    CHECK(k.power_conflict(a, b, 3, 4, 0) == ks.power_conflict(a, b, 3, 4, 0));
    perturbed += int(k.stats().power.perturbed);
    CHECK(k.stats().power.perturbed == ks.stats().power.perturbed);
  }
  CHECK(perturbed > 20);  // ties were common enough to test the perturbation
}

TEST_CASE("Small integers: the filters' doubles are exact, ties included", "[predicates][degenerate]") {
  const auto in_doubles = [](std::vector<Vec3> p, std::vector<double> w) { return Kernel::exact_in_doubles(p, w); };
  CHECK(in_doubles({{-7, 3, 1e6}, {504, 514, 1e6 + 511}}, {}));
  CHECK_FALSE(in_doubles({{-7, 3, 0}, {505, 3, 0}}, {}));  // x spans 512
  CHECK_FALSE(in_doubles({{0, 0, 0}, {1, 0.5, 0}}, {}));
  CHECK(in_doubles({{0, 0, 0}, {1, 1, 1}}, {-3, 0x1p19 - 4}));
  CHECK_FALSE(in_doubles({{0, 0, 0}, {1, 1, 1}}, {-3, 0x1p19 - 3}));  // weights span 2^19
  CHECK_FALSE(in_doubles({{0, 0, 0}, {1, 1, 1}}, {0, 0.25}));

  // Integer points on a sphere of radius about 255 about an integer centre
  // far from the origin: every power test of five ties at values near
  // 2^50, and the perturbation decides it from the filter's minors; moved
  // by one unit, the sign is that of a sum of such values. Weights 0, equal
  // (ties again) or anywhere in [0, 2^19). Each answer must equal that of
  // the same points scaled by 2^-3, which are not integers and go through
  // the filter and the exact stages.
  std::mt19937_64 rng(5);
  int ties = 0, decided = 0;
  for (const int r2 : {65025, 64993, 63001}) {  // 255^2 and two sums of three squares below it
    std::vector<Vec3> sphere;
    const int r = int(std::sqrt(double(r2)));
    for (int x = -r; x <= r; ++x)
      for (int y = -r; y <= r; ++y) {
        const int rest = r2 - x * x - y * y, z = int(std::lround(std::sqrt(double(std::max(rest, 0)))));
        if (rest >= 0 && z * z == rest) {
          sphere.push_back({x + 1e6, y - 3e5, z + 7.0});
          if (z > 0) sphere.push_back({x + 1e6, y - 3e5, -z + 7.0});
        }
      }
    REQUIRE(sphere.size() > 100);
    std::uniform_int_distribution<std::size_t> pick(0, sphere.size() - 1);
    std::uniform_int_distribution<int> nudge(-1, 1), weight(0, (1 << 19) - 1);
    for (int trial = 0; trial < 2000; ++trial) {
      std::vector<Vec3> p(5), scaled(5);
      std::vector<double> w(5), scaled_w(5);
      const int kind = trial % 3;  // weights 0, all equal, random
      const double equal = double(weight(rng));
      for (int i = 0; i < 5; ++i) {
        p[i] = sphere[pick(rng)];
        w[i] = kind == 0 ? 0.0 : kind == 1 ? equal : double(weight(rng));
      }
      p[0].x += nudge(rng);
      for (int i = 0; i < 5; ++i) {
        scaled[i] = {p[i].x / 8, p[i].y / 8, p[i].z / 8};
        scaled_w[i] = w[i] / 64;
      }
      REQUIRE(Kernel::exact_in_doubles(p, w));
      Kernel k(p.data(), w.data(), nullptr, true), ks(scaled.data(), scaled_w.data());
      // The cell's vertices and the tested point in a random order, so that
      // the perturbation asks for every cofactor in turn.
      std::array<Index, 5> id{0, 1, 2, 3, 4};
      std::shuffle(id.begin(), id.end(), rng);
      const int o = k.orient3d(id[0], id[1], id[2], id[3]);
      REQUIRE(o == ks.orient3d(id[0], id[1], id[2], id[3]));
      if (o == 0) continue;
      if (o < 0) std::swap(id[0], id[1]);
      REQUIRE(k.power_conflict(id[0], id[1], id[2], id[3], id[4]) ==
              ks.power_conflict(id[0], id[1], id[2], id[3], id[4]));
      CHECK(k.orient3d(id[0], id[1], id[2], id[4]) == ks.orient3d(id[0], id[1], id[2], id[4]));
      ties += int(k.stats().power.perturbed);
      decided += int(k.stats().power.filtered);
      CHECK(k.stats().power.perturbed == ks.stats().power.perturbed);
    }
  }
  CHECK(ties > 500);
  CHECK(decided > 500);
}
