// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "alpha/predicates.hpp"

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

TEST_CASE("Perturbed power test is antisymmetric in the 5-point sense", "[predicates][degenerate]") {
  // For cospherical points the perturbed answers of two cells sharing a
  // facet against each other's far vertex must disagree in a consistent
  // way: exactly one diagonal of a cospherical square pyramid is chosen.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 0, 1}, {0, 1, 1}};
  Kernel k(p.data(), nullptr);
  int conflicts = 0, total = 0;
  for (Index a = 0; a < 8; ++a)
    for (Index b = a + 1; b < 8; ++b)
      for (Index c = b + 1; c < 8; ++c)
        for (Index d = c + 1; d < 8; ++d) {
          int o = k.orient3d(a, b, c, d);
          if (o == 0) continue;
          Index aa = a, bb = b;
          if (o < 0) std::swap(aa, bb);
          for (Index e = 0; e < 8; ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            ++total;
            conflicts += k.power_conflict(aa, bb, c, d, e);
          }
        }
  // All 8 corners are cospherical: every answer is decided by perturbation,
  // and never all the same way.
  CHECK(k.stats().power.perturbed == std::uint64_t(total));
  CHECK(conflicts > 0);
  CHECK(conflicts < total);
}

TEST_CASE("Filter, 128-bit and GMP paths agree", "[predicates]") {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> small(-5, 5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<Vec3> p(5);
    std::vector<double> w(5);
    const bool grid = trial % 2 == 0;  // small integers: 128-bit path on ties
    for (int i = 0; i < 5; ++i) {
      p[i] = grid ? Vec3{double(small(rng)), double(small(rng)), double(small(rng))} : Vec3{u(rng), u(rng), u(rng)};
      w[i] = grid ? double(small(rng)) : u(rng) * 0.1;
    }
    Kernel k(p.data(), w.data());
    if (k.orient3d(0, 1, 2, 3) <= 0) continue;
    // The exact side agrees with a long-double evaluation whenever that is clearly nonzero.
    long double r[4][4];
    for (int i = 0; i < 4; ++i) {
      long double x = p[i].x - p[4].x, y = p[i].y - p[4].y, z = p[i].z - p[4].z;
      r[i][0] = x, r[i][1] = y, r[i][2] = z, r[i][3] = x * x + y * y + z * z - (w[i] - w[4]);
    }
    auto d3 = [&](int a, int b, int c) {
      return r[a][0] * (r[b][1] * r[c][2] - r[b][2] * r[c][1]) - r[a][1] * (r[b][0] * r[c][2] - r[b][2] * r[c][0]) +
             r[a][2] * (r[b][0] * r[c][1] - r[b][1] * r[c][0]);
    };
    const long double det = -r[0][3] * d3(1, 2, 3) + r[1][3] * d3(0, 2, 3) - r[2][3] * d3(0, 1, 3) + r[3][3] * d3(0, 1, 2);
    const int side = k.power_side_exact(0, 1, 2, 3, 4);
    if (std::fabs(double(det)) > 1e-9) CHECK(side == (det < 0 ? 1 : -1));
    if (grid && det == 0) CHECK(side == 0);
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
