// SPDX-License-Identifier: Apache-2.0
// ErodedUnion (the solvent-excluded body of a union of balls) against
// closed forms and a Monte Carlo estimate from an independent nearest-point
// test (depth_oracle.hpp); its area against the derivative of its volume
// in r; its per-cell and per-ball shares against its totals; the per-ball
// shares against Monte Carlo by power cell and their own r-derivative.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "alpha/error.hpp"
#include "alpha/eroded_union.hpp"
#include "ball_union.hpp"
#include "depth_oracle.hpp"
#include "point_sets.hpp"

using namespace alpha;
using testing::random_points;
using testing::random_weights;

namespace {

constexpr double kPi = std::numbers::pi;

using Balls = testing::BallSet;

// Every union here is padded: its balls stay inside the convex hull.
struct Union : testing::BallUnion {
  explicit Union(const Balls& b) : testing::BallUnion(b, true) {}
};

struct Measured {
  double volume, area;
};

Measured eroded(const Union& u, double r) {
  const ErodedUnion e(*u.u, r);
  const LayerShare layer = e.layer();
  return {u.u->volume() - layer.volume, layer.area};
}

// A tight random cluster: probe positions closer than 2r everywhere.
Balls cluster(std::size_t n, std::uint64_t seed, double spread, double lo, double hi) {
  Balls b;
  b.centers = random_points(n, seed, spread);
  for (double w : random_weights(n, seed + 1, lo * lo, hi * hi)) b.radii.push_back(std::sqrt(w));
  return b;
}

}  // namespace

TEST_CASE("eroded union: one ball shrinks by r", "[eroded]") {
  const Union u(Balls{{{1, 2, 3}}, {3.2}});
  for (const double r : {0.0, 1.4, 3.2}) {
    const Measured m = eroded(u, r);
    const double inner = 3.2 - r;
    CHECK(m.volume == Approx(4 * kPi / 3 * inner * inner * inner).margin(1e-12));
    CHECK(m.area == Approx(4 * kPi * inner * inner).margin(1e-12));
  }
}

TEST_CASE("eroded union: Monte Carlo on random sets, smooth and singular", "[eroded]") {
  struct Case {
    Balls balls;
    double r;
  };
  std::vector<Case> cases;
  cases.push_back({{{{0, 0, 0}, {3, 0, 0}}, {2.5, 2.5}}, 1.0});    // torus, rho 1.66 > r
  cases.push_back({{{{0, 0, 0}, {4.4, 0, 0}}, {2.5, 2.5}}, 1.4});  // spindle torus, rho 1.19 < r
  cases.push_back({cluster(5, 11, 2.5, 2.4, 3.4), 1.4});
  cases.push_back({cluster(8, 12, 3.5, 2.4, 3.4), 1.4});
  cases.push_back({cluster(10, 13, 5.0, 2.4, 3.4), 2.0});
  for (const auto& [balls, r] : cases) {
    const Union u(balls);
    const Measured m = eroded(u, r);
    const auto [mc, sigma] = testing::DepthOracle(balls.centers, balls.radii, r).volume_deeper(r, 200000, 7);
    INFO("balls " << balls.centers.size() << " r " << r << " volume " << m.volume << " MC " << mc << " +- " << sigma);
    CHECK(std::fabs(m.volume - mc) <= 4.5 * sigma);
    // The area is minus the derivative of the volume in r (co-area formula;
    // the union stays fixed).
    const double h = 1e-4;
    const double derivative = (eroded(u, r + h).volume - eroded(u, r - h).volume) / (2 * h);
    INFO("area " << m.area << " -dV/dr " << -derivative);
    CHECK(m.area == Approx(-derivative).epsilon(1e-7));
  }
}

TEST_CASE("eroded union: degenerate input, against Monte Carlo", "[eroded]") {
  // A cube's 8 corners, spheres through its center (8 meet in one point:
  // several triangles give that vertex), and through the face centers.
  Balls cube;
  for (const Vec3& p : testing::grid_points(2, 2.0)) cube.centers.push_back(p);
  for (const double radius : {std::sqrt(3.0), std::sqrt(2.0), 1.9}) {
    cube.radii.assign(8, radius);
    const Union u(cube);
    const Measured m = eroded(u, 1.0);
    const auto [mc, sigma] = testing::DepthOracle(cube.centers, cube.radii, 1.0).volume_deeper(1.0, 200000, 3);
    INFO("radius " << radius << " volume " << m.volume << " MC " << mc << " +- " << sigma);
    CHECK(std::fabs(m.volume - mc) <= 4.5 * sigma);
    const double h = 1e-4;
    CHECK(m.area == Approx(-(eroded(u, 1 + h).volume - eroded(u, 1 - h).volume) / (2 * h)).epsilon(1e-5));
  }
  // Coplanar centers, duplicated.
  Balls flat{{{0, 0, 0}, {2.5, 0, 0}, {0, 2.5, 0}, {2.5, 2.5, 0}, {1.25, 1.25, 0}, {1.25, 1.25, 0}},
             {2, 2, 2, 2, 1.5, 1.5}};
  const Union u(flat);
  const auto [mc, sigma] = testing::DepthOracle(flat.centers, flat.radii, 1.2).volume_deeper(1.2, 200000, 5);
  CHECK(std::fabs(eroded(u, 1.2).volume - mc) <= 4.5 * sigma);
}

TEST_CASE("eroded union: the cells' shares sum to the totals", "[eroded]") {
  for (const auto& [balls, r] : {std::pair{cluster(40, 21, 9.0, 1.6, 3.4), 1.4}, std::pair{cluster(12, 22, 3.0, 2.4, 3.4), 1.4}}) {
    const Union u(balls);
    const ErodedUnion e(*u.u, r);
    const LayerShare whole = e.layer();
    double volume = 0, area = 0;
    for (Index c = 0; c < u.t().num_cells(); ++c) {
      const LayerShare share = e.cell_share(c);
      volume += share.volume;
      area += share.area;
    }
    CHECK(volume == Approx(whole.volume).epsilon(1e-12));
    CHECK(area == Approx(whole.area).epsilon(1e-12));
    // cells_share (scratch space kept from cell to cell) adds the same
    // shares in the same order: bit for bit the same sum.
    std::vector<Index> all(u.t().num_cells());
    std::iota(all.begin(), all.end(), Index(0));
    const LayerShare together = e.cells_share(all);
    CHECK(together.volume == volume);
    CHECK(together.area == area);
  }
}

TEST_CASE("eroded union: a patch's area in a cell's cone, against its sphere's area and Monte Carlo", "[eroded]") {
  const Balls balls = cluster(40, 21, 9.0, 1.6, 3.4);
  const Union u(balls);
  const ErodedUnion e(*u.u, 1.4);
  const Triangulation& t = u.t();
  // The cones about a centre fill space: the parts add up to the sphere's
  // area on the boundary (UnionOfBalls' inclusion-exclusion over K).
  std::vector<double> sum(t.num_points(), 0.0);
  for (Index c = 0; c < t.num_cells(); ++c)
    if (!t.is_infinite(c))
      for (int k = 0; k < 4; ++k) sum[t.cell(c).v[k]] += e.patch_area(c, k);
  for (std::size_t i = 0; i < balls.radii.size(); ++i) {
    INFO("ball " << i);
    CHECK(sum[i] == Approx(u.ball_area(i)).epsilon(1e-11).margin(1e-11 * balls.radii[i] * balls.radii[i]));
  }
  // The circles left out by their union arcs (kept when r > 0) bound no
  // part: the same areas, bit for bit, as with every circle clipped (r = 0
  // keeps no arcs).
  const ErodedUnion uneroded(*u.u, 0.0);
  for (Index c = 0; c < t.num_cells(); ++c)
    for (int k = 0; k < 4; ++k) {
      INFO("cell " << c << " vertex " << k);
      CHECK(e.patch_area(c, k) == uneroded.patch_area(c, k));
    }
  // Per cone: directions n in it (a nonnegative combination of the edges,
  // by Cramer's rule) whose point p + R n is in no other ball.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  int tested = 0;
  for (Index c = 0; c < t.num_cells() && tested < 6; ++c) {
    if (t.is_infinite(c)) continue;
    for (int k = 0; k < 4; ++k) {
      const Index i = t.cell(c).v[k];
      if (i >= balls.radii.size()) continue;  // a far point
      const double radius = balls.radii[i], whole = 4 * kPi * radius * radius, area = e.patch_area(c, k);
      if (!(area > 0.05 * whole)) continue;
      std::array<Vec3, 3> edge;
      for (int n = 1; n < 4; ++n) edge[n - 1] = t.point(t.cell(c).v[(k + n) % 4]) - balls.centers[i];
      const double det = dot(edge[0], cross(edge[1], edge[2]));
      const int samples = 100000;
      int hits = 0;
      for (int s = 0; s < samples; ++s) {
        Vec3 n{normal(rng), normal(rng), normal(rng)};
        n = (1 / norm(n)) * n;
        if (dot(n, cross(edge[1], edge[2])) * det < 0 || dot(edge[0], cross(n, edge[2])) * det < 0 ||
            dot(edge[0], cross(edge[1], n)) * det < 0)
          continue;
        const Vec3 x = balls.centers[i] + radius * n;
        bool covered = false;
        for (std::size_t m = 0; m < balls.radii.size() && !covered; ++m)
          covered = m != i && norm(x - balls.centers[m]) < balls.radii[m];
        hits += !covered;
      }
      const double f = double(hits) / samples, sigma = whole * std::sqrt(f * (1 - f) / samples);
      INFO("cell " << c << " vertex " << k << ": " << area << " against " << whole * f << " +- " << sigma);
      CHECK(std::fabs(area - whole * f) <= 4.5 * sigma);
      ++tested;
    }
  }
  CHECK(tested == 6);
}

TEST_CASE("eroded union: share_cell is the cell whose cone holds the nearest point, from any hint", "[eroded]") {
  // Against every cell around the feature (a sphere's ball vertex, a
  // circle's edge): the point lies on the inner side of each facet
  // through the feature. Unpadded, some balls reach beyond the hull: their
  // outer directions are infinite cells'.
  for (const bool pad : {false, true}) {
    const Balls balls = cluster(40, 41, 8.0, 1.6, 3.4);
    const testing::BallUnion u(balls, pad);
    const ErodedUnion e(*u.u, 1.4);
    const Triangulation& t = u.t();
    const Simplices& s = u.ac().simplices();
    const auto holders = [&](const ErodedUnion::Nearest& n) {
      std::vector<Index> feature{n.which};
      if (n.on == ErodedUnion::Nearest::On::circle) feature = {s.edge(n.which)[0], s.edge(n.which)[1]};
      std::vector<Index> out;
      for (Index c = 0; c < t.num_cells(); ++c) {
        if (t.is_infinite(c)) continue;
        const auto& v = t.cell(c).v;
        const auto is_feature = [&](Index x) { return std::find(feature.begin(), feature.end(), x) != feature.end(); };
        if (std::count_if(v.begin(), v.end(), is_feature) != std::ptrdiff_t(feature.size())) continue;
        bool inside = true;
        for (int k = 0; k < 4 && inside; ++k) {
          if (is_feature(v[k])) continue;
          std::vector<Vec3> f;
          for (int j = 0; j < 4; ++j)
            if (j != k) f.push_back(t.point(v[j]));
          const Vec3 normal = cross(f[1] - f[0], f[2] - f[0]);
          inside = dot(normal, n.point - f[0]) * dot(normal, t.point(v[k]) - f[0]) >= 0;
        }
        if (inside) out.push_back(c);
      }
      return out;
    };
    std::size_t checked = 0, infinite = 0;
    Index previous = kNone;
    for (const Vec3& x : random_points(3000, 43, 12.0)) {
      const ErodedUnion::Nearest n = e.nearby(x, 1.4).nearest(x, 1.4);
      if (n.on != ErodedUnion::Nearest::On::sphere && n.on != ErodedUnion::Nearest::On::circle) continue;
      const std::vector<Index> expected = holders(n);
      for (const Index hint : {kNone, previous, Index(checked % t.num_cells())}) {
        const Index c = e.share_cell(x, n, hint);
        INFO("pad " << pad << " hint " << hint << " cell " << c);
        if (expected.empty())
          CHECK(t.is_infinite(c));
        else
          CHECK(std::find(expected.begin(), expected.end(), c) != expected.end());
        previous = c;
      }
      ++checked;
      infinite += expected.empty();
    }
    CHECK(checked > 300);
    if (!pad) CHECK(infinite > 0);  // directions beyond the hull were asked too
  }
}

TEST_CASE("eroded union: r = 0 is the union, bad r refused", "[eroded]") {
  const Balls balls = cluster(10, 31, 4.0, 1.5, 3.0);
  const Union u(balls);
  const Measured m = eroded(u, 0);
  CHECK(m.volume == Approx(u.u->volume()).epsilon(1e-14));
  CHECK(m.area == Approx(u.u->area()).epsilon(1e-12));
  CHECK_THROWS_AS(ErodedUnion(*u.u, -1), Error);
  CHECK_THROWS_AS(ErodedUnion(*u.u, std::nan("")), Error);
  CHECK_THROWS_AS(ErodedUnion(*u.u, 3.5), Error);  // larger than every ball
}

namespace {

// Per ball: the eroded body's volume in its power cell (ball_volumes less
// the layer's part) and its surface's area there.
struct PerBall {
  LayerShare total;
  std::vector<double> volume, area;
};

PerBall per_ball(const Union& u, double r, std::size_t n) {
  const ErodedUnion e(*u.u, r);
  std::vector<LayerShare> shares;
  PerBall out{e.layer(shares), {}, {}};
  for (std::size_t i = 0; i < n; ++i) {
    out.volume.push_back(u.u->ball_volumes()[i] - shares[i].volume);
    out.area.push_back(shares[i].area);
  }
  for (std::size_t i = n; i < shares.size(); ++i) {  // the padding's far points get nothing
    CHECK(shares[i].volume == 0);
    CHECK(shares[i].area == 0);
  }
  return out;
}

double sum(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  return s;
}

}  // namespace

TEST_CASE("eroded union: per ball, the shares sum to the totals, which layer() gives alone", "[eroded]") {
  std::vector<std::pair<Balls, double>> cases{{cluster(40, 21, 9.0, 1.6, 3.4), 1.4},
                                              {cluster(12, 22, 3.0, 2.4, 3.4), 1.4},
                                              {cluster(10, 13, 5.0, 2.4, 3.4), 2.0}};
  Balls cube;  // degenerate: 8 spheres through one point; coplanar and duplicate centres
  for (const Vec3& p : testing::grid_points(2, 2.0)) cube.centers.push_back(p);
  cube.radii.assign(8, std::sqrt(3.0));
  cases.push_back({cube, 1.0});
  cases.push_back({{{{0, 0, 0}, {2.5, 0, 0}, {0, 2.5, 0}, {2.5, 2.5, 0}, {1.25, 1.25, 0}, {1.25, 1.25, 0}},
                    {2, 2, 2, 2, 1.5, 1.5}},
                   1.2});
  for (const auto& [balls, r] : cases) {
    const Union u(balls);
    const PerBall p = per_ball(u, r, balls.radii.size());
    const LayerShare alone = ErodedUnion(*u.u, r).layer();
    CHECK(p.total.volume == alone.volume);  // bit for bit: the per-ball split does not touch the totals
    CHECK(p.total.area == alone.area);
    CHECK(sum(p.volume) == Approx(u.u->volume() - alone.volume).epsilon(1e-12));
    CHECK(sum(p.area) == Approx(alone.area).epsilon(1e-12));
    for (std::size_t i = 0; i < p.volume.size(); ++i) {
      INFO("ball " << i << " volume " << p.volume[i] << " area " << p.area[i]);
      // Near 0 (a ball buried but for a sliver), the quadrature's error.
      CHECK(p.volume[i] >= -5e-3);
      CHECK(p.area[i] >= -1e-3);
    }
  }
}

TEST_CASE("eroded union: per ball, closed forms and symmetry", "[eroded]") {
  {  // one ball: the eroded body is the ball of radius R - r
    const Union u(Balls{{{1, 2, 3}}, {3.2}});
    const PerBall p = per_ball(u, 1.4, 1);
    CHECK(p.volume[0] == Approx(4 * kPi / 3 * 1.8 * 1.8 * 1.8).epsilon(1e-13));
    CHECK(p.area[0] == Approx(4 * kPi * 1.8 * 1.8).epsilon(1e-13));
  }
  // Two equal balls, a torus (rho > r) and a spindle torus (rho < r): the
  // radical plane is the mirror plane, the shares are equal.
  for (const double d : {3.0, 4.4}) {
    const Union u(Balls{{{0, 0, 0}, {d, 0, 0}}, {2.5, 2.5}});
    const PerBall p = per_ball(u, 1.4, 2);
    CHECK(p.volume[0] == Approx(p.volume[1]).epsilon(1e-12));
    CHECK(p.area[0] == Approx(p.area[1]).epsilon(1e-12));
  }
  // Four equal balls on a regular tetrahedron's corners: equal shares.
  const double a = 2.2;
  const Union u(Balls{{{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}}, {3.3, 3.3, 3.3, 3.3}});
  const PerBall p = per_ball(u, 1.4, 4);
  for (int i = 1; i < 4; ++i) {
    CHECK(p.volume[i] == Approx(p.volume[0]).epsilon(1e-9));
    CHECK(p.area[i] == Approx(p.area[0]).epsilon(1e-9));
  }
}

TEST_CASE("eroded union: per ball, against Monte Carlo by power cell and the area against -dV/dr", "[eroded]") {
  std::vector<std::pair<Balls, double>> cases{
      {{{{0, 0, 0}, {4.4, 0, 0}}, {2.0, 2.9}}, 1.4},  // unequal spindle torus
      {cluster(5, 11, 2.5, 2.4, 3.4), 1.4},
      {cluster(8, 12, 3.5, 2.4, 3.4), 1.4},
      // a small ball's centre outside its power cell (as an O next to a C)
      {{{{0, 0, 0}, {1.3, 0, 0}, {2.5, 1.4, 0}, {2.2, -0.4, 1.5}}, {2.8, 3.3, 3.0, 3.2}}, 1.4}};
  for (const auto& [balls, r] : cases) {
    const Union u(balls);
    const std::size_t n = balls.radii.size();
    const PerBall p = per_ball(u, r, n);
    const auto [mc, sigma] = testing::DepthOracle(balls.centers, balls.radii, r).cell_volumes_deeper(r, 400000, 17);
    const double h = 1e-4;
    const PerBall inner = per_ball(u, r + h, n), outer = per_ball(u, r - h, n);
    for (std::size_t i = 0; i < n; ++i) {
      INFO("balls " << n << " ball " << i << " volume " << p.volume[i] << " MC " << mc[i] << " +- " << sigma[i]);
      CHECK(std::fabs(p.volume[i] - mc[i]) <= 4.5 * sigma[i] + 5e-3);
      const double derivative = (inner.volume[i] - outer.volume[i]) / (2 * h);
      INFO("area " << p.area[i] << " -dV/dr " << -derivative);
      CHECK(p.area[i] == Approx(-derivative).epsilon(1e-3).margin(1e-3));
    }
  }
}
