// SPDX-License-Identifier: Apache-2.0
// ConvexPolyhedron and ball_in_polyhedron against closed forms (caps,
// octants, the whole ball), additivity (a polyhedron split by a plane:
// the two parts' measures sum to the whole's) and Monte Carlo.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "union/ball_in_polyhedron.hpp"
#include "union/convex_polyhedron.hpp"

using namespace alpha;

namespace {

constexpr double kPi = std::numbers::pi;

// A tetrahedron around the cube [-s, s]^3, clipped to it.
ConvexPolyhedron cube(double s) {
  ConvexPolyhedron q({-9 * s, -9 * s, -9 * s}, {30 * s, -9 * s, -9 * s}, {-9 * s, 30 * s, -9 * s}, {-9 * s, -9 * s, 30 * s});
  for (const Vec3& n : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    q.clip(n, s);
    q.clip(-1.0 * n, s);
  }
  return q;
}

double polyhedron_volume(const ConvexPolyhedron& q) { return ball_in_polyhedron(q, 1e9).volume; }

bool inside(const ConvexPolyhedron& q, const Vec3& x) {
  for (std::size_t f = 0; f < q.num_faces(); ++f)
    if (dot(q.normal(f), x - q.vertex(q.loop(f)[0])) > 0) return false;
  return true;
}

}  // namespace

TEST_CASE("ball in polyhedron: closed forms", "[ball_polyhedron]") {
  const double r = 1.3;
  const ConvexPolyhedron big = cube(10);
  CHECK(big.num_faces() == 6);
  CHECK(polyhedron_volume(big) == Approx(8000).epsilon(1e-12));
  BallPart b = ball_in_polyhedron(big, r);
  CHECK(b.volume == Approx(4 * kPi / 3 * r * r * r).epsilon(1e-13));
  CHECK(b.area == Approx(4 * kPi * r * r).epsilon(1e-13));

  // A cap of height c (the plane at r - c from the centre).
  for (const double c : {0.1, 0.9, 1.3, 2.0}) {
    ConvexPolyhedron q = big;
    q.clip({0, 0, -1}, c - r);
    b = ball_in_polyhedron(q, r);
    CHECK(b.volume == Approx(kPi * c * c * (3 * r - c) / 3).epsilon(1e-13));
    CHECK(b.area == Approx(2 * kPi * r * c).epsilon(1e-13));
  }
  // The centre on a vertex, an edge, a face of a box larger than the ball.
  ConvexPolyhedron octant = big, quarter = big, half = big;
  for (const Vec3& n : {Vec3{-1, 0, 0}, Vec3{0, -1, 0}, Vec3{0, 0, -1}}) octant.clip(n, 0);
  quarter.clip({-1, 0, 0}, 0), quarter.clip({0, -1, 0}, 0);
  half.clip({0, 0, 1}, 0);
  CHECK(ball_in_polyhedron(octant, r).volume == Approx(kPi / 6 * r * r * r).epsilon(1e-13));
  CHECK(ball_in_polyhedron(octant, r).area == Approx(kPi / 2 * r * r).epsilon(1e-13));
  CHECK(ball_in_polyhedron(quarter, r).volume == Approx(kPi / 3 * r * r * r).epsilon(1e-13));
  CHECK(ball_in_polyhedron(half, r).area == Approx(2 * kPi * r * r).epsilon(1e-13));
  // Clipping by a plane that misses it, or holds a face, changes nothing;
  // one beyond it empties it.
  ConvexPolyhedron same = octant;
  same.clip({0, 0, -1}, 0);
  same.clip({1, 1, 1}, 100);
  CHECK(same.num_faces() == octant.num_faces());
  same.clip({1, 1, 1}, -1);
  CHECK(same.empty());
}

TEST_CASE("ball in polyhedron: the two sides of a plane sum to the whole", "[ball_polyhedron]") {
  // Random tetrahedra, cut by random planes (some through a vertex or the
  // ball's centre), balls about random centres inside and outside.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  auto point = [&] { return Vec3{u(rng), u(rng), u(rng)}; };
  int parts = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 a = point(), b = point(), c = point(), d = point();
    if (std::fabs(dot(b - a, cross(c - a, d - a))) < 0.1) continue;
    ConvexPolyhedron q(a, b, c, d);
    for (int k = 0; k < 3; ++k) {
      const Vec3 n = point();
      q.clip(n, dot(n, point()) / 2);
    }
    if (q.empty()) continue;
    const Vec3 n = point();
    const double offset = trial % 3 == 0 ? dot(n, q.vertex(q.loop(0)[0])) : trial % 3 == 1 ? 0.0 : u(rng);
    ConvexPolyhedron below = q, above = q;
    below.clip(n, offset);
    above.clip(-1.0 * n, -offset);
    const double r = 0.2 + std::fabs(u(rng));
    const BallPart whole = ball_in_polyhedron(q, r), lo = ball_in_polyhedron(below, r), hi = ball_in_polyhedron(above, r);
    CHECK(lo.volume + hi.volume == Approx(whole.volume).margin(1e-12));
    CHECK(lo.area + hi.area == Approx(whole.area).margin(1e-12));
    CHECK(polyhedron_volume(below) + polyhedron_volume(above) == Approx(polyhedron_volume(q)).epsilon(1e-12));
    parts += !below.empty() && !above.empty();
  }
  CHECK(parts > 60);
}

TEST_CASE("ball in polyhedron: Monte Carlo", "[ball_polyhedron]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 6; ++trial) {
    const Vec3 n0{u(rng), u(rng), u(rng)}, n1{u(rng), u(rng), u(rng)};
    const double o0 = 0.3 * std::fabs(u(rng)), o1 = 0.3 * std::fabs(u(rng));
    const Vec3 centre{u(rng), u(rng), u(rng)};
    const double r = 0.8 + 0.5 * std::fabs(u(rng));
    // The same polyhedron about the origin (q) and about the ball's centre.
    auto clipped = [&](const Vec3& shift) {
      ConvexPolyhedron p(Vec3{-1.5, -1, -1} - shift, Vec3{2, -1.2, -0.8} - shift, Vec3{-0.5, 1.8, -1} - shift,
                         Vec3{0.2, 0.3, 1.9} - shift);
      p.clip(n0, o0 - dot(n0, shift));
      p.clip(n1, o1 - dot(n1, shift));
      return p;
    };
    const ConvexPolyhedron q = clipped({}), moved = clipped(centre);
    const BallPart b = ball_in_polyhedron(moved, r);
    const int samples = 400000;
    int in_volume = 0, on_sphere = 0;
    for (int k = 0; k < samples; ++k) {
      Vec3 x;
      do x = {u(rng), u(rng), u(rng)};
      while (dot(x, x) > 1);
      in_volume += inside(q, centre + r * x);
      const Vec3 d{g(rng), g(rng), g(rng)};
      on_sphere += inside(q, centre + (r / norm(d)) * d);
    }
    const double ball = 4 * kPi / 3 * r * r * r, sphere = 4 * kPi * r * r;
    const double pv = double(in_volume) / samples, pa = double(on_sphere) / samples;
    INFO("trial " << trial);
    CHECK(std::fabs(b.volume - ball * pv) <= 4.5 * ball * std::sqrt(pv * (1 - pv) / samples) + 1e-12);
    CHECK(std::fabs(b.area - sphere * pa) <= 4.5 * sphere * std::sqrt(pa * (1 - pa) / samples) + 1e-12);
  }
}
