// SPDX-License-Identifier: Apache-2.0
// UnionOfBalls against closed forms, an independent numerical integration
// (slices along z: exact 2D union of discs, integrated by Gauss-Legendre
// between the heights where the slice's arrangement changes), and Monte
// Carlo estimates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "alpha/error.hpp"
#include "alpha/union_of_balls.hpp"
#include "ball_union.hpp"
#include "numerics/compensated_sum.hpp"
#include "point_sets.hpp"

using namespace alpha;

namespace {

constexpr double kPi = std::numbers::pi;

double dist2(const Vec3& a, const Vec3& b) { return dot(a - b, a - b); }

using testing::BallSet;
using Union = testing::BallUnion;

// ---- the slice oracle ------------------------------------------------------

std::vector<std::pair<double, double>> gauss_legendre(int n) {  // nodes on [-1, 1], weights
  std::vector<std::pair<double, double>> r;
  for (int i = 1; i <= n; ++i) {
    double x = std::cos(kPi * (i - 0.25) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    r.emplace_back(x, 2 / ((1 - x * x) * dp * dp));
  }
  return r;
}

struct Measures {
  double volume = 0;
  std::vector<double> area, volume_of;  // per ball
};

// One slice z = const: circles of the balls it cuts. Returns the area of the
// union of discs; adds to area_rate[i] r_i * (exposed angle of circle i) (the
// sphere's area per unit height, Archimedes) and to cell[i] the area of
// disc i inside its 2D power cell (the slice of B_i & P_i).
double slice(const BallSet& s, double z, std::vector<double>& area_rate, std::vector<double>& cell) {
  struct Circle {
    double x, y, rho2, rho;
    std::size_t ball;
  };
  std::vector<Circle> cs;
  for (std::size_t i = 0; i < s.centers.size(); ++i) {
    const double dz = z - s.centers[i].z, rho2 = s.radii[i] * s.radii[i] - dz * dz;
    if (rho2 > 0) cs.push_back({s.centers[i].x, s.centers[i].y, rho2, std::sqrt(rho2), i});
  }
  double total = 0;
  for (std::size_t a = 0; a < cs.size(); ++a) {
    const Circle& ci = cs[a];
    // Angular intervals of circle a covered by other discs.
    std::vector<std::pair<double, double>> covered;
    bool empty_cell = false;
    for (std::size_t b = 0; b < cs.size(); ++b) {
      if (b == a) continue;
      const Circle& cj = cs[b];
      const double dx = cj.x - ci.x, dy = cj.y - ci.y, d = std::hypot(dx, dy);
      if (d == 0) {
        if (cj.rho > ci.rho || (cj.rho == ci.rho && b < a)) covered.emplace_back(0, 2 * kPi), empty_cell = true;
        continue;
      }
      if (d >= ci.rho + cj.rho || d + cj.rho <= ci.rho) continue;
      if (d + ci.rho <= cj.rho) {
        covered.emplace_back(0, 2 * kPi);
        continue;
      }
      const double mid = std::atan2(dy, dx);
      const double half = std::acos(std::clamp((ci.rho2 + d * d - cj.rho2) / (2 * ci.rho * d), -1.0, 1.0));
      double lo = mid - half, hi = mid + half;
      if (lo < 0) lo += 2 * kPi, hi += 2 * kPi;
      if (hi > 2 * kPi) covered.emplace_back(lo, 2 * kPi), covered.emplace_back(0, hi - 2 * kPi);
      else covered.emplace_back(lo, hi);
    }
    std::sort(covered.begin(), covered.end());
    // Exposed arcs: the complement of the covered intervals in [0, 2 pi).
    std::vector<std::pair<double, double>> arcs;
    double at = 0;
    for (const auto& [lo, hi] : covered) {
      if (lo > at) arcs.emplace_back(at, lo);
      at = std::max(at, hi);
    }
    if (at < 2 * kPi) arcs.emplace_back(at, 2 * kPi);
    double exposed = 0, green = 0;  // green: the arcs' part of the shoelace integral (times 2)
    for (const auto& [t1, t2] : arcs) {
      exposed += t2 - t1;
      green += ci.rho2 * (t2 - t1) + ci.rho * (ci.x * (std::sin(t2) - std::sin(t1)) - ci.y * (std::cos(t2) - std::cos(t1)));
    }
    area_rate[ci.ball] += s.radii[ci.ball] * exposed;
    total += green / 2;
    if (empty_cell) continue;
    // The power cell's edges inside disc a: the radical line with each b,
    // clipped to the disc and to the other half-planes, traversed with the
    // cell on the left.
    double segments = 0;
    auto power = [&](const Circle& c, double x, double y) { return (x - c.x) * (x - c.x) + (y - c.y) * (y - c.y) - c.rho2; };
    for (std::size_t b = 0; b < cs.size(); ++b) {
      if (b == a) continue;
      const Circle& cj = cs[b];
      const double nx = cj.x - ci.x, ny = cj.y - ci.y, len = std::hypot(nx, ny);
      if (len == 0) continue;
      // Points x with 2 x.n = k lie on the radical line; foot point and direction.
      const double ux = nx / len, uy = ny / len;
      const double k = (cj.x * cj.x + cj.y * cj.y - cj.rho2) - (ci.x * ci.x + ci.y * ci.y - ci.rho2);
      const double off = k / (2 * len) - (ci.x * ux + ci.y * uy);  // signed distance from ci's center
      if (std::fabs(off) >= ci.rho) continue;
      const double fx = ci.x + off * ux, fy = ci.y + off * uy, tx = -uy, ty = ux;
      double s0 = -std::sqrt(ci.rho2 - off * off), s1 = -s0;
      for (std::size_t c = 0; c < cs.size() && s0 < s1; ++c) {
        if (c == a || c == b) continue;
        // pi_a - pi_c <= 0 along the line: linear in s.
        const double f0 = power(ci, fx, fy) - power(cs[c], fx, fy);
        const double slope = 2 * ((cs[c].x - ci.x) * tx + (cs[c].y - ci.y) * ty);
        if (slope == 0) {
          if (f0 > 0) s1 = s0;
        } else if (slope > 0) {
          s1 = std::min(s1, -f0 / slope);
        } else {
          s0 = std::max(s0, -f0 / slope);
        }
      }
      if (s0 >= s1) continue;
      const double px = fx + s0 * tx, py = fy + s0 * ty, qx = fx + s1 * tx, qy = fy + s1 * ty;
      segments += px * qy - py * qx;
    }
    cell[ci.ball] += (green + segments) / 2;
  }
  return total;
}

// Heights where the slice's arrangement changes: poles of the spheres,
// extremes of the circles where two spheres meet, triple points, and the
// orthogonal centers of four balls (vertices of the power diagram).
std::vector<double> breakpoints(const BallSet& s) {
  const std::size_t n = s.centers.size();
  std::vector<double> z;
  auto w = [&](std::size_t i) { return s.radii[i] * s.radii[i]; };
  for (std::size_t i = 0; i < n; ++i) z.push_back(s.centers[i].z - s.radii[i]), z.push_back(s.centers[i].z + s.radii[i]);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3 d = s.centers[j] - s.centers[i];
      const double dd = std::sqrt(dot(d, d)), h = (dd * dd + w(i) - w(j)) / (2 * dd), a2 = w(i) - h * h;
      if (a2 <= 0) continue;
      const double cz = s.centers[i].z + h * d.z / dd, spread = std::sqrt(a2 * (1 - d.z * d.z / (dd * dd)));
      z.push_back(cz - spread), z.push_back(cz + spread);
      for (std::size_t k = j + 1; k < n; ++k) {
        const Vec3 e = s.centers[k] - s.centers[i], nn = cross(d, e);
        const double n2 = dot(nn, nn);
        if (n2 == 0) continue;
        const double A = dot(d, d) + w(i) - w(j), B = dot(e, e) + w(i) - w(k);
        const Vec3 c1 = cross(e, nn), c2 = cross(nn, d);
        const Vec3 c{(A * c1.x + B * c2.x) / (2 * n2), (A * c1.y + B * c2.y) / (2 * n2), (A * c1.z + B * c2.z) / (2 * n2)};
        const double l2 = w(i) - dot(c, c);
        if (l2 < 0) continue;
        const double lz = std::sqrt(l2) * nn.z / std::sqrt(n2);
        z.push_back(s.centers[i].z + c.z - lz), z.push_back(s.centers[i].z + c.z + lz);
        for (std::size_t m = k + 1; m < n; ++m) {
          const Vec3 f = s.centers[m] - s.centers[i];
          const double det = dot(d, cross(e, f));
          if (det == 0) continue;
          const double C = dot(f, f) + w(i) - w(m);
          const Vec3 x1 = cross(e, f), x2 = cross(f, d), x3 = cross(d, e);
          const double cz4 = (A * x1.z + B * x2.z + C * x3.z) / (2 * det);
          z.push_back(s.centers[i].z + cz4);
        }
      }
    }
  std::sort(z.begin(), z.end());
  z.erase(std::unique(z.begin(), z.end(), [](double a, double b) { return b - a < 1e-13; }), z.end());
  return z;
}

// Volume, per-ball area and per-ball volume of the union by integration over
// z: between consecutive breakpoints the integrands are analytic up to
// algebraic singularities at the ends, which z = a + (b - a)(1 - cos t)/2
// removes; then Gauss-Legendre in t.
Measures integrate(const BallSet& s, int nodes = 64) {
  const std::size_t n = s.centers.size();
  Measures m;
  m.area.assign(n, 0);
  m.volume_of.assign(n, 0);
  const auto gl = gauss_legendre(nodes);
  const std::vector<double> z = breakpoints(s);
  std::vector<double> rate(n), cell(n);
  for (std::size_t k = 0; k + 1 < z.size(); ++k) {
    const double a = z[k], b = z[k + 1];
    for (const auto& [x, wx] : gl) {
      const double t = kPi / 2 * (1 + x), zz = a + (b - a) * (1 - std::cos(t)) / 2;
      const double jac = wx * kPi / 2 * (b - a) / 2 * std::sin(t);
      std::fill(rate.begin(), rate.end(), 0.0);
      std::fill(cell.begin(), cell.end(), 0.0);
      m.volume += jac * slice(s, zz, rate, cell);
      for (std::size_t i = 0; i < n; ++i) m.area[i] += jac * rate[i], m.volume_of[i] += jac * cell[i];
    }
  }
  return m;
}

double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}
double sum(std::span<const double> v) { return sum(std::vector<double>(v.begin(), v.end())); }

// Everything the union computes equals the oracle to rel (relative to the
// total), per ball too, and the per-ball values sum to the totals.
void check_against_oracle(const BallSet& s, double rel = 1e-9, bool pad = false) {
  const Union un(s, pad);
  const Measures m = integrate(s);
  const UnionOfBalls& u = *un.u;
  const double area = sum(m.area);
  INFO("oracle volume " << m.volume << " area " << area);
  CHECK(u.volume() == Approx(m.volume).epsilon(rel));
  CHECK(u.area() == Approx(area).epsilon(rel));
  CHECK(sum(u.ball_areas()) == Approx(u.area()).epsilon(1e-13));
  CHECK(sum(u.ball_volumes()) == Approx(u.volume()).epsilon(1e-13));
  for (std::size_t i = 0; i < s.centers.size(); ++i) {
    INFO("ball " << i);
    CHECK(u.ball_areas()[i] == Approx(m.area[i]).margin(rel * area));
    CHECK(u.ball_volumes()[i] == Approx(m.volume_of[i]).margin(rel * m.volume));
  }
}

BallSet random_balls(std::size_t n, std::uint64_t seed, double box, double rmin, double rmax) {
  BallSet s;
  s.centers = testing::random_points(n, seed, box);
  std::mt19937_64 rng(seed + 1);
  std::uniform_real_distribution<double> r(rmin, rmax);
  for (std::size_t i = 0; i < n; ++i) s.radii.push_back(r(rng));
  return s;
}

}  // namespace

TEST_CASE("union of balls: one ball, and balls of radius 0", "[union]") {
  const Union un({{{1, 2, 3}}, {1.5}}, true);
  CHECK(un.u->volume() == Approx(4.0 / 3 * kPi * 1.5 * 1.5 * 1.5).epsilon(1e-15));
  CHECK(un.u->area() == Approx(4 * kPi * 1.5 * 1.5).epsilon(1e-15));
  CHECK(un.ball_area(0) == un.u->area());
  for (std::size_t i = 1; i < 5; ++i) {
    CHECK(un.ball_area(i) == 0);
    CHECK(un.ball_volume(i) == 0);
  }
  // An unweighted triangulation is a union of points.
  const Triangulation t(testing::random_points(20, 3));
  const AlphaComplex ac(t);
  const UnionOfBalls u(ac);
  CHECK(u.volume() == 0);
  CHECK(u.area() == 0);
}

TEST_CASE("union of balls: two balls against the lens formulas", "[union]") {
  const double r1 = 1.3, r2 = 0.9;
  for (double d : {0.5, 1.0, 1.7, 2.15, 2.2, 3.0}) {
    INFO("d = " << d);
    const Union un({{{0, 0, 0}, {d, 0, 0}}, {r1, r2}}, true);
    const double v1 = 4 * kPi / 3 * r1 * r1 * r1, v2 = 4 * kPi / 3 * r2 * r2 * r2;
    double lens = 0, cap1 = 0, cap2 = 0, t1 = 0, t2 = 0;
    if (d < r1 + r2) {
      lens = kPi * std::pow(r1 + r2 - d, 2) * (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) /
             (12 * d);
      t1 = r1 - (d * d + r1 * r1 - r2 * r2) / (2 * d);  // heights of the caps beyond the radical plane
      t2 = r2 - (d * d + r2 * r2 - r1 * r1) / (2 * d);
      cap1 = kPi * t1 * t1 * (3 * r1 - t1) / 3;
      cap2 = kPi * t2 * t2 * (3 * r2 - t2) / 3;
    }
    CHECK(un.u->volume() == Approx(v1 + v2 - lens).epsilon(1e-14));
    CHECK(cap1 + cap2 == Approx(lens).epsilon(1e-12));
    // The sphere outside the other ball: minus the cap inside it.
    CHECK(un.ball_area(0) == Approx(4 * kPi * r1 * r1 - 2 * kPi * r1 * t1).epsilon(1e-14));
    CHECK(un.ball_area(1) == Approx(4 * kPi * r2 * r2 - 2 * kPi * r2 * t2).epsilon(1e-14));
    // Ball inside its power cell: minus its cap beyond the radical plane.
    CHECK(un.ball_volume(0) == Approx(v1 - cap1).epsilon(1e-14));
    CHECK(un.ball_volume(1) == Approx(v2 - cap2).epsilon(1e-14));
  }
}

TEST_CASE("union of balls: a ball inside another, tangent balls", "[union][degenerate]") {
  // Inside: the inner ball adds nothing, whether or not it is a vertex.
  for (double d : {0.0, 0.3, 0.5}) {
    INFO("d = " << d);
    const Union un({{{0, 0, 0}, {d, 0, 0}}, {1.5, 1.0}}, true);
    CHECK(un.u->volume() == Approx(4 * kPi / 3 * 1.5 * 1.5 * 1.5).epsilon(1e-14));
    CHECK(un.u->area() == Approx(4 * kPi * 1.5 * 1.5).epsilon(1e-14));
    CHECK(un.ball_area(1) == Approx(0).margin(1e-13));
    CHECK(un.ball_volume(1) == Approx(0).margin(1e-13));
  }
  // Externally tangent (the edge enters K exactly at 0): two whole balls.
  const Union tangent({{{0, 0, 0}, {2, 0, 0}}, {1, 1}}, true);
  CHECK(tangent.u->volume() == Approx(8 * kPi / 3).epsilon(1e-15));
  CHECK(tangent.u->area() == Approx(8 * kPi).epsilon(1e-15));
}

TEST_CASE("union of balls: hidden and duplicate points add nothing", "[union][degenerate]") {
  // Four balls of radius 2 on a tetrahedron cover the origin's small ball,
  // whose power cell is empty: hidden. A duplicate of a center with a
  // smaller radius is merged.
  BallSet base{{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {2, 2, 2, 2}};
  const Union plain(base);
  BallSet more = base;
  more.centers.push_back({0, 0, 0});
  more.radii.push_back(0.5);
  more.centers.push_back({1, -1, -1});
  more.radii.push_back(1.0);
  const Union un(more);
  REQUIRE(un.t().status(4) == PointStatus::hidden);
  REQUIRE(un.t().status(5) == PointStatus::duplicate);
  CHECK(un.u->volume() == Approx(plain.u->volume()).epsilon(1e-14));
  CHECK(un.u->area() == Approx(plain.u->area()).epsilon(1e-14));
  for (std::size_t i : {4, 5}) {
    CHECK(un.ball_area(i) == 0);
    CHECK(un.ball_volume(i) == 0);
  }
  check_against_oracle(base);
}

TEST_CASE("union of balls: three balls against numerical integration", "[union]") {
  // Triple points exist, the line of triple points misses a disc, and an
  // obtuse triangle whose orthogonal center lies outside it.
  check_against_oracle({{{0, 0, 0}, {1.6, 0, 0}, {0.5, 1.4, 0.2}}, {1.0, 1.1, 0.9}}, 1e-10, true);
  check_against_oracle({{{0, 0, 0}, {1.2, 0, 0}, {0.6, 0.9, 0.3}}, {1.0, 1.0, 1.0}}, 1e-10, true);
  check_against_oracle({{{0, 0, 0}, {3.0, 0, 0}, {1.5, 0.4, 0}}, {1.6, 1.6, 0.7}}, 1e-10, true);
  check_against_oracle({{{0, 0, 0}, {1.0, 0.1, 0}, {0.3, 0.2, 0.9}}, {1.4, 0.5, 0.6}}, 1e-10, true);
}

TEST_CASE("union of balls: four balls, the quadruple term", "[union]") {
  // Orthogonal center inside and outside the tetrahedron of centers.
  check_against_oracle({{{0, 0, 0}, {1.3, 0, 0}, {0.6, 1.1, 0}, {0.5, 0.4, 1.2}}, {1.0, 0.9, 1.1, 0.8}}, 1e-10, true);
  check_against_oracle({{{0, 0, 0}, {2.0, 0, 0}, {1.0, 0.5, 0}, {1.0, 0.2, 0.4}}, {1.3, 1.3, 0.9, 0.8}}, 1e-10, true);
}

TEST_CASE("union of balls: random balls against numerical integration", "[union]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    INFO("seed " << seed);
    check_against_oracle(random_balls(16, seed, 3.0, 0.4, 1.2));
  }
}

TEST_CASE("union of balls: degenerate grids against numerical integration", "[union][degenerate]") {
  // A 3x3x2 unit grid with equal radii: at w = 0.25 neighbours touch; at
  // 0.5 the four balls of a unit square meet at its center (triangles of
  // size 0); at 0.75 the eight balls of a cube meet at its center
  // (cospherical tetrahedra of size 0); in between, every kind of term.
  BallSet s;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k) s.centers.push_back({double(i), double(j), double(k)});
  for (double w : {0.2, 0.25, 0.36, 0.5, 0.5625, 0.75, 0.81, 1.21}) {
    INFO("w = " << w);
    s.radii.assign(s.centers.size(), std::sqrt(w));
    check_against_oracle(s);
  }
}

TEST_CASE("union of balls: far points make balls on a line or a plane a union, and add nothing", "[union][degenerate]") {
  // Three unit balls on a line, 1 apart: the end balls are tangent at the
  // middle one's centre, so only neighbours overlap, in lenses of caps of
  // height 1/2: area 3 * 4 pi - 4 pi, volume 3 * 4/3 pi - 2 * 5 pi / 12.
  const Union line({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {1, 1, 1}}, true);
  CHECK(line.u->area() == Approx(8 * kPi).epsilon(1e-13));
  CHECK(line.u->volume() == Approx(19 * kPi / 6).epsilon(1e-13));
  // A flat 3x3 grid (cospherical squares): every kind of term, in one plane.
  BallSet flat;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) flat.centers.push_back({1.1 * i, 1.1 * j, 0});
  flat.radii.assign(flat.centers.size(), 0.8);
  check_against_oracle(flat, 1e-9, true);
  // Around a set that needs none, they leave every ball's measures as they
  // were, and lie farther from each ball than its radius.
  const BallSet b = random_balls(40, 7, 4.0, 0.4, 1.5);
  const Union plain(b), padded(b, true);
  CHECK(padded.u->area() == Approx(plain.u->area()).epsilon(1e-13));
  CHECK(padded.u->volume() == Approx(plain.u->volume()).epsilon(1e-13));
  for (std::size_t i = 0; i < b.centers.size(); ++i) {
    CHECK(padded.ball_area(i) == Approx(plain.ball_area(i)).margin(1e-12));
    for (std::size_t k = b.centers.size(); k < b.centers.size() + 4; ++k)
      CHECK(norm(padded.t().point(k) - b.centers[i]) > 2 * b.radii[i]);
  }
  std::vector<Vec3> p{{0, 0, 0}};
  std::vector<double> w;
  CHECK_THROWS_WITH(add_far_points(p, w), Catch::Contains("one weight per point"));
}

TEST_CASE("union of balls: random balls against Monte Carlo", "[union]") {
  const BallSet s = random_balls(40, 7, 4.0, 0.5, 1.3);
  const Union un(s);
  std::mt19937_64 rng(11);
  const std::size_t n = s.centers.size();
  auto inside = [&](const Vec3& x, std::size_t skip) {
    for (std::size_t j = 0; j < n; ++j)
      if (j != skip && dist2(x, s.centers[j]) < s.radii[j] * s.radii[j]) return true;
    return false;
  };
  // Volume: uniform samples in the bounding box.
  {
    std::uniform_real_distribution<double> u(-1.3, 5.3);
    const double box = std::pow(6.6, 3);
    const int samples = 1000000;
    int hits = 0;
    for (int k = 0; k < samples; ++k) hits += inside({u(rng), u(rng), u(rng)}, n);
    const double p = double(hits) / samples, se = box * std::sqrt(p * (1 - p) / samples);
    CHECK(std::fabs(un.u->volume() - box * p) < 4.5 * se);
  }
  // Area: uniform samples on each sphere, exposed when outside the others.
  {
    std::normal_distribution<double> g;
    const int per_sphere = 40000;
    double estimate = 0, variance = 0;
    for (std::size_t i = 0; i < n; ++i) {
      int exposed = 0;
      for (int k = 0; k < per_sphere; ++k) {
        Vec3 d{g(rng), g(rng), g(rng)};
        const double l = std::sqrt(dot(d, d)), r = s.radii[i];
        exposed += !inside({s.centers[i].x + r * d.x / l, s.centers[i].y + r * d.y / l, s.centers[i].z + r * d.z / l}, i);
      }
      const double full = 4 * kPi * s.radii[i] * s.radii[i], p = double(exposed) / per_sphere;
      estimate += full * p;
      variance += full * full * p * (1 - p) / per_sphere;
      CHECK(std::fabs(un.ball_area(i) - full * p) < 4.5 * std::sqrt(full * full * p * (1 - p) / per_sphere) + 1e-12);
    }
    CHECK(std::fabs(un.u->area() - estimate) < 4.5 * std::sqrt(variance));
  }
}

TEST_CASE("union of balls: each sphere's area is the volume's derivative in its radius", "[union]") {
  // dV/dr_i = A_i (Edelsbrunner 1995): central differences, per ball.
  const BallSet s = random_balls(25, 4, 3.5, 0.5, 1.3);
  const Union un(s);
  const double h = 1e-5;
  for (std::size_t i = 0; i < s.centers.size(); ++i) {
    BallSet up = s, down = s;
    up.radii[i] += h, down.radii[i] -= h;
    const double derivative = (Union(up).u->volume() - Union(down).u->volume()) / (2 * h);
    INFO("ball " << i);
    CHECK(un.ball_area(i) == Approx(derivative).margin(1e-7 * un.u->area()));
  }
}

TEST_CASE("union of balls: invariant under translation", "[union]") {
  BallSet s = random_balls(200, 5, 8.0, 0.6, 1.8);
  const Union a(s);
  for (Vec3& p : s.centers) p = {p.x + 1000.25, p.y - 700.5, p.z + 333.125};
  const Union b(s);
  CHECK(b.u->volume() == Approx(a.u->volume()).epsilon(1e-11));
  CHECK(b.u->area() == Approx(a.u->area()).epsilon(1e-11));
}

TEST_CASE("union of balls: negative weights are rejected", "[union]") {
  const Triangulation t(testing::random_points(10, 1), testing::random_weights(10, 2, -1, 1));
  const AlphaComplex ac(t);
  CHECK_THROWS_AS(UnionOfBalls(ac), Error);
}

TEST_CASE("union of balls: cells share the union exactly when it lies inside the hull", "[union][cells]") {
  // Small random balls well inside a cube whose corners have radius 0.
  BallSet s = random_balls(60, 9, 4.0, 0.3, 0.9);
  for (double x : {-3.0, 7.0})
    for (double y : {-3.0, 7.0})
      for (double z : {-3.0, 7.0}) s.centers.push_back({x, y, z}), s.radii.push_back(0);
  const Union un(s);
  const Triangulation& t = un.t();
  double volume = 0, area = 0;
  for (Index c = 0; c < t.num_cells(); ++c) {
    const CellCover cc = un.u->cell_cover(c);
    if (t.is_infinite(c)) {
      CHECK(cc.volume == 0);
      CHECK(cc.area == 0);
    }
    volume += cc.volume, area += cc.area;
  }
  CHECK(volume == Approx(un.u->volume()).epsilon(1e-12));
  CHECK(area == Approx(un.u->area()).epsilon(1e-12));
}

namespace {

// Monte Carlo: the fraction of the cells' volume inside the balls,
// uniform samples (a cell by volume, then barycentric).
double covered_fraction(const Triangulation& t, const BallSet& s, const std::vector<Index>& cells, int samples,
                        std::uint64_t seed) {
  std::vector<double> cumulative;
  double volume = 0;
  for (Index c : cells) {
    const auto& v = t.cell(c).v;
    cumulative.push_back(volume += alpha::tetrahedron_volume(t.point(v[0]), t.point(v[1]), t.point(v[2]), t.point(v[3])));
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, volume);
  std::exponential_distribution<double> e;
  int hits = 0;
  for (int k = 0; k < samples; ++k) {
    const auto& v = t.cell(cells[std::lower_bound(cumulative.begin(), cumulative.end(), u(rng)) - cumulative.begin()]).v;
    double b[4], total = 0;
    for (double& x : b) total += x = e(rng);
    Vec3 x{};
    for (int i = 0; i < 4; ++i) x = x + (b[i] / total) * t.point(v[i]);
    bool in = false;
    for (std::size_t i = 0; i < s.centers.size() && !in; ++i) in = dist2(x, s.centers[i]) < s.radii[i] * s.radii[i];
    hits += in;
  }
  return double(hits) / samples;
}

}  // namespace

TEST_CASE("union of balls: the cells of a void hold exactly its covered part", "[union][cells]") {
  // Voids: sets of cells not in K, joined through triangles not in K,
  // closed by triangles of K. Their parts sum to the union's volume inside
  // them (Monte Carlo), and no cell's part exceeds its volume.
  const BallSet s = random_balls(300, 1, 8.0, 0.6, 1.2);
  const Union un(s);
  const Triangulation& t = un.t();
  const Simplices& sx = un.ac().simplices();
  std::vector<int> component(t.num_cells(), -1);
  std::vector<std::vector<Index>> voids;
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (component[c] >= 0 || t.is_infinite(c) || un.u->in_dual_complex_cell(c)) continue;
    std::vector<Index> cells{c}, stack{c};
    component[c] = int(voids.size());
    bool open = false;
    while (!stack.empty()) {
      const Index x = stack.back();
      stack.pop_back();
      for (int k = 0; k < 4; ++k) {
        const Index y = t.cell(x).n[k];
        if (un.u->in_dual_complex_triangle(sx.cell_triangle(x, k))) continue;
        if (t.is_infinite(y)) open = true;
        if (t.is_infinite(y) || component[y] >= 0) continue;
        component[y] = component[c];
        cells.push_back(y), stack.push_back(y);
      }
    }
    voids.push_back(open ? std::vector<Index>{} : cells);
  }
  std::size_t checked = 0;
  for (const auto& cells : voids) {
    if (cells.empty()) continue;
    ++checked;
    double volume = 0, share = 0;
    for (Index c : cells) {
      const auto& v = t.cell(c).v;
      const double vc = alpha::tetrahedron_volume(t.point(v[0]), t.point(v[1]), t.point(v[2]), t.point(v[3]));
      const double sc = un.u->cell_cover(c).volume;
      CHECK(sc <= vc * (1 + 1e-12));
      CHECK(sc >= 0);
      volume += vc, share += sc;
    }
    const int samples = 200000;
    const double p = covered_fraction(t, s, cells, samples, 3 + checked), se = volume * std::sqrt(p * (1 - p) / samples);
    INFO("void of " << cells.size() << " cells, volume " << volume);
    // (+ 5 / samples: a void nearly covered may get no empty sample.)
    CHECK(std::fabs(share - volume * p) < 4.5 * se + 5.0 / samples * volume);
    CHECK(share <= volume);
  }
  CHECK(checked >= 3);
}

TEST_CASE("union of balls: a cell's share is its covered part when the pieces stay inside", "[union][cells]") {
  // A regular tetrahedron of edge 1 with balls of radius 0.6 at its
  // vertices: its triangles are in K, it is not (circumradius^2 3/8 >
  // 0.36). No ball reaches the opposite facet (height 0.816), no lens the
  // other facets. With radius 0.62 the balls cover the whole tetrahedron,
  // which is then in K.
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}, {0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3)}};
  const double vol = alpha::tetrahedron_volume(p[0], p[1], p[2], p[3]);
  auto finite_cell = [](const Triangulation& t) {
    for (Index c = 0; c < t.num_cells(); ++c)
      if (!t.is_infinite(c)) return c;
    return kNone;
  };
  const Union full({p, {0.62, 0.62, 0.62, 0.62}});
  const Index c = finite_cell(full.t());
  CHECK(full.u->in_dual_complex_cell(c));
  CHECK(full.u->cell_cover(c).volume == Approx(vol).epsilon(1e-13));

  const double r = 0.6;
  const Union un({p, {r, r, r, r}});
  const Index cell = finite_cell(un.t());
  CHECK(!un.u->in_dual_complex_cell(cell));
  for (Index f = 0; f < un.ac().simplices().num_triangles(); ++f) CHECK(un.u->in_dual_complex_triangle(f));
  const CellCover cc = un.u->cell_cover(cell);
  // Monte Carlo over the tetrahedron (uniform barycentric coordinates).
  std::mt19937_64 rng(5);
  std::exponential_distribution<double> e;
  const int samples = 1000000;
  int hits = 0;
  for (int k = 0; k < samples; ++k) {
    double b[4], total = 0;
    for (double& x : b) total += x = e(rng);
    Vec3 x{};
    for (int i = 0; i < 4; ++i) x = {x.x + b[i] / total * p[i].x, x.y + b[i] / total * p[i].y, x.z + b[i] / total * p[i].z};
    bool in = false;
    for (const Vec3& q : p) in = in || dist2(x, q) < r * r;
    hits += in;
  }
  const double q = double(hits) / samples;
  CHECK(std::fabs(cc.volume - vol * q) < 4.5 * vol * std::sqrt(q * (1 - q) / samples));
  // The union's boundary inside the cell: uniform samples on each sphere,
  // kept when inside the tetrahedron and outside the other balls.
  auto inside_cell = [&](const Vec3& x) {
    for (int k = 0; k < 4; ++k) {
      const Vec3& a = p[(k + 1) % 4];
      const Vec3 n = cross(p[(k + 2) % 4] - a, p[(k + 3) % 4] - a);
      if ((dot(n, x - a) > 0) != (dot(n, p[k] - a) > 0)) return false;
    }
    return true;
  };
  std::normal_distribution<double> g;
  const int per_sphere = 250000;
  int exposed = 0;
  for (const Vec3& c : p)
    for (int k = 0; k < per_sphere; ++k) {
      const Vec3 d{g(rng), g(rng), g(rng)};
      const double l = std::sqrt(dot(d, d));
      const Vec3 x{c.x + r * d.x / l, c.y + r * d.y / l, c.z + r * d.z / l};
      bool covered = false;
      for (const Vec3& o : p) covered = covered || (&o != &c && dist2(x, o) < r * r);
      exposed += !covered && inside_cell(x);
    }
  const double sphere = 4 * kPi * r * r, f = double(exposed) / (4.0 * per_sphere);
  CHECK(std::fabs(cc.area - 4 * sphere * f) < 4.5 * 4 * sphere * std::sqrt(f * (1 - f) / (4.0 * per_sphere)));
}


TEST_CASE("union of balls: a cell's part is its covered part, balls crossing its facets", "[union][cells]") {
  // Large balls on few points: sectors and lenses reach through the facets
  // into the next cells (where a fractional split of the union is off).
  const BallSet s = random_balls(40, 21, 6.0, 1.2, 2.4);
  const Union un(s, true);
  const Triangulation& t = un.t();
  int checked = 0;
  for (Index c = 0; c < t.num_cells() && checked < 12; c += 7) {
    if (t.is_infinite(c)) continue;
    const auto& v = t.cell(c).v;
    const double volume = alpha::tetrahedron_volume(t.point(v[0]), t.point(v[1]), t.point(v[2]), t.point(v[3]));
    if (volume < 0.5) continue;
    ++checked;
    const int samples = 100000;
    const double p = covered_fraction(t, s, {c}, samples, c);
    INFO("cell " << c << " volume " << volume << " covered " << p);
    CHECK(std::fabs(un.u->cell_cover(c).volume - volume * p) < 4.5 * volume * std::sqrt(p * (1 - p) / samples) + 1e-12);
  }
  CHECK(checked == 12);
}

TEST_CASE("union of balls: cells' parts sum to the union on degenerate sets", "[union][cells][degenerate]") {
  // Cospherical and coplanar centres (an integer grid, points on a sphere)
  // with equal radii where 4 and 8 balls meet in one point, and duplicates;
  // the far points keep the union inside the hull.
  std::vector<BallSet> sets;
  for (const double r : {0.5, std::sqrt(0.5), std::sqrt(0.75), 0.9}) {
    BallSet grid{testing::grid_points(3), {}};
    grid.radii.assign(grid.centers.size(), r);
    sets.push_back(grid);
  }
  BallSet sphere{testing::sphere_points(9), {}};
  sphere.radii.assign(sphere.centers.size(), 1.6);
  sphere.centers.push_back(sphere.centers.front()), sphere.radii.push_back(1.6);  // a duplicate
  sets.push_back(sphere);
  for (const BallSet& s : sets) {
    const Union un(s, true);
    const Triangulation& t = un.t();
    Sum volume, area;
    std::vector<Index> some;
    for (Index c = 0; c < t.num_cells(); ++c) {
      const CellCover cc = un.u->cell_cover(c);
      volume.add(cc.volume), area.add(cc.area);
      if (!t.is_infinite(c) && c % 5 == 0) some.push_back(c);
    }
    INFO(s.centers.size() << " balls of radius " << s.radii[0]);
    CHECK(volume.value() == Approx(un.u->volume()).epsilon(1e-12));
    CHECK(area.value() == Approx(un.u->area()).epsilon(1e-12));
    // A set of cells, as a pocket is: its parts against Monte Carlo.
    double part = 0, whole = 0;
    for (Index c : some) {
      const auto& v = t.cell(c).v;
      part += un.u->cell_cover(c).volume;
      whole += alpha::tetrahedron_volume(t.point(v[0]), t.point(v[1]), t.point(v[2]), t.point(v[3]));
    }
    const int samples = 100000;
    const double p = covered_fraction(t, s, some, samples, 4);
    CHECK(std::fabs(part - whole * p) < 4.5 * whole * std::sqrt(p * (1 - p) / samples) + 1e-12);
  }
}

TEST_CASE("union of balls: balls far from unit size measure as at unit size", "[union][degenerate]") {
  // Radii near 1e-99: the terms' fourth and sixth powers of lengths leave
  // the doubles' range unless the sums change unit (they lost 1 % of the
  // volume). The same balls scaled by 2^-330, an exact change of unit.
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> coordinate(0, 3), radius(0.5, 1.5);
  testing::BallSet unit_size;
  for (int i = 0; i < 30; ++i) {
    unit_size.centers.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
    unit_size.radii.push_back(radius(rng));
  }
  testing::BallSet tiny = unit_size;
  for (auto& c : tiny.centers) c = std::ldexp(1.0, -330) * c;
  for (double& r : tiny.radii) r = std::ldexp(r, -330);
  const Union one(unit_size), small(tiny);
  REQUIRE(one.u->volume() > 0);
  CHECK(std::ldexp(small.u->volume(), 990) == Approx(one.u->volume()).epsilon(1e-12));
  CHECK(std::ldexp(small.u->area(), 660) == Approx(one.u->area()).epsilon(1e-12));
}
