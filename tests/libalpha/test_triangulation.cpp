// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "alpha/error.hpp"
#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"
#include "alpha/validation.hpp"
#include "point_sets.hpp"

using namespace alpha;

namespace {

// No input point (vertex, hidden or duplicate) lies strictly inside any
// finite cell's orthosphere: the definition of a regular triangulation.
std::size_t brute_force_violations(const Triangulation& t) {
  Kernel k = t.kernel();
  std::size_t bad = 0;
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (t.is_infinite(c)) continue;
    const auto& v = t.cell(c).v;
    for (Index p = 0; p < t.num_points(); ++p)
      if (k.power_side_exact(v[0], v[1], v[2], v[3], p) > 0) ++bad;
  }
  return bad;
}

// Euler characteristic of the triangulation closed by the infinite vertex
// (a 3-sphere): V - E + F - C = 0.
long euler_characteristic(const Triangulation& t) {
  std::set<std::pair<Index, Index>> edges;
  for (const Cell& c : t.cells())
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(c.v[i], c.v[j]));
  const long cells = long(t.num_cells());
  return long(t.num_vertices() + 1) - long(edges.size()) + 2 * cells - cells;
}

double finite_volume(const Triangulation& t) {
  double vol = 0;
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (t.is_infinite(c)) continue;
    const auto& v = t.cell(c).v;
    const Vec3 &a = t.point(v[0]), &b = t.point(v[1]), &cc = t.point(v[2]), &d = t.point(v[3]);
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = cc.x - a.x, vy = cc.y - a.y,
                 vz = cc.z - a.z, wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
    vol += (ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6;
  }
  return vol;
}

void require_valid(const Triangulation& t) {
  const ValidationReport r = validate(t);
  INFO((r.problems.empty() ? std::string() : r.problems.front()));
  REQUIRE(r.valid);
  REQUIRE(brute_force_violations(t) == 0);
  REQUIRE(euler_characteristic(t) == 0);
}

// Cells as sets of point coordinates: independent of ids and cell order.
std::set<std::array<std::array<double, 3>, 4>> cell_shapes(const Triangulation& t) {
  std::set<std::array<std::array<double, 3>, 4>> shapes;
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (t.is_infinite(c)) continue;
    std::array<std::array<double, 3>, 4> s;
    for (int k = 0; k < 4; ++k) {
      const Vec3& p = t.point(t.cell(c).v[k]);
      s[k] = {p.x, p.y, p.z};
    }
    std::sort(s.begin(), s.end());
    shapes.insert(s);
  }
  return shapes;
}

}  // namespace

TEST_CASE("Delaunay of random points is empty-sphere and valid", "[triangulation]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const Triangulation t(testing::random_points(250, seed));
    CHECK(t.num_vertices() == 250);
    CHECK(t.num_hidden() == 0);
    require_valid(t);
  }
}

TEST_CASE("Integer grids are triangulated exactly despite cospherical cubes", "[triangulation][degenerate]") {
  for (double spacing : {1.0, 0.5, 0.1}) {
    const Triangulation t(testing::grid_points(6, spacing));
    CHECK(t.num_vertices() == 216);
    require_valid(t);
    // Cells tile the hull exactly: their volumes add up to the cube's.
    CHECK(finite_volume(t) == Approx(std::pow(5 * spacing, 3)).epsilon(1e-12));
    CHECK(t.predicate_stats().power.perturbed > 0);
  }
}

TEST_CASE("Cospherical points: all on one sphere", "[triangulation][degenerate]") {
  const auto pts = testing::sphere_points(50);  // 3^2+4^2+5^2 and others
  REQUIRE(pts.size() > 30);
  const Triangulation t(pts);
  CHECK(t.num_vertices() == pts.size());
  require_valid(t);
}

TEST_CASE("Duplicates are merged and counted", "[triangulation][degenerate]") {
  auto pts = testing::random_points(100, 7);
  const auto copy = pts;
  pts.insert(pts.end(), copy.begin(), copy.begin() + 40);
  pts.insert(pts.end(), copy.begin(), copy.begin() + 10);
  const Triangulation t(pts);
  CHECK(t.num_vertices() == 100);
  CHECK(t.num_duplicates() == 50);
  CHECK(t.representative(100) == 0);
  CHECK(t.status(149) == PointStatus::duplicate);
  require_valid(t);
}

TEST_CASE("Weighted points: regular triangulation with hidden points", "[triangulation][weighted]") {
  for (std::uint64_t seed : {11, 12}) {
    const auto pts = testing::random_points(300, seed, 10.0);
    const auto w = testing::random_weights(300, seed + 100, 0.0, 4.0);
    const Triangulation t(pts, w);
    CHECK(t.num_hidden() > 0);
    CHECK(t.num_vertices() + t.num_hidden() == 300);
    require_valid(t);
  }
}

TEST_CASE("Weighted grid with equal weights equals the unweighted grid", "[triangulation][weighted][degenerate]") {
  const auto pts = testing::grid_points(5);
  const Triangulation plain(pts), weighted(pts, std::vector<double>(pts.size(), 0.25));
  require_valid(weighted);
  CHECK(cell_shapes(plain) == cell_shapes(weighted));
}

TEST_CASE("Weighted grid hides interior points and nothing on the hull", "[triangulation][weighted][degenerate]") {
  // A 5x5x5 unit grid, the hull points weighted 1.5, the interior ones in a
  // checkerboard of 1.5 and 0. A weight-0 point whose six neighbours weigh
  // 1.5 is hidden: each bisector plane lies 0.25 behind it. A hull point
  // among equal weights keeps the region beyond its face: never hidden.
  const auto pts = testing::grid_points(5);
  std::vector<double> w(pts.size());
  std::size_t light = 0;
  const auto on_hull = [](const Vec3& p) {
    return std::min({p.x, p.y, p.z}) == 0 || std::max({p.x, p.y, p.z}) == 4;
  };
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Vec3& p = pts[i];
    const bool odd = int(p.x + p.y + p.z) % 2 == 1;
    w[i] = !on_hull(p) && odd ? 0.0 : 1.5;
    light += w[i] == 0;
  }
  REQUIRE(light == 14);
  const Triangulation t(pts, w);
  require_valid(t);
  CHECK(brute_force_violations(t) == 0);
  CHECK(t.num_hidden() == light);
  for (Index i = 0; i < t.num_points(); ++i) {
    INFO("point " << i);
    CHECK((t.status(i) == PointStatus::hidden) == (w[i] == 0));
    if (on_hull(pts[i])) CHECK(t.status(i) == PointStatus::vertex);
  }
}

TEST_CASE("Result does not depend on input order for generic points", "[triangulation]") {
  auto pts = testing::random_points(300, 21);
  const Triangulation a(pts);
  std::reverse(pts.begin(), pts.end());
  std::rotate(pts.begin(), pts.begin() + 37, pts.end());
  const Triangulation b(pts);
  CHECK(cell_shapes(a) == cell_shapes(b));
}

TEST_CASE("Affine dimension: exact, and 3 exactly when a triangulation exists", "[triangulation][degenerate]") {
  using V = std::vector<Vec3>;
  CHECK(affine_dimension(V{}) == -1);
  CHECK(affine_dimension(V{{1, 2, 3}, {1, 2, 3}}) == 0);
  CHECK(affine_dimension(V{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}) == 1);
  // Far off the origin, in a tilted plane: 1e8 + small offsets round to no
  // float filter's comfort, the exact stage decides.
  V plane;
  for (int i = 0; i < 50; ++i) {
    const double u = i % 7, v = i / 7;
    plane.push_back({1e8 + u, 1e8 + v, 1e8 + u + v});
  }
  CHECK(affine_dimension(plane) == 2);
  plane.push_back({1e8 + 3, 1e8 + 2, 1e8 + 5 + std::ldexp(1.0, -20)});  // just off the plane
  CHECK(affine_dimension(plane) == 3);
  CHECK_NOTHROW(Triangulation(plane));
  CHECK(affine_dimension(testing::grid_points(3)) == 3);
}

TEST_CASE("Unusable input gives a clear error", "[triangulation][errors]") {
  using V = std::vector<Vec3>;
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), Catch::Contains("at least 4 distinct"));
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}}),
                    Catch::Contains("at least 4 distinct"));
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {5, 5, 5}}),
                    Catch::Contains("collinear"));
  V plane;
  for (int i = 0; i < 50; ++i) plane.push_back({double(i % 7), double(i / 7), 0.0});
  CHECK_THROWS_WITH(Triangulation(plane), Catch::Contains("coplanar"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}),
                    Catch::Contains("not a finite number"));
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1e300}}), Catch::Contains("out of range"));
  // Tiny sets: the scale below which sizes underflow, and just above it.
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {1e-101, 0, 0}, {0, 1e-101, 0}, {0, 0, 1e-101}}),
                    Catch::Contains("span only"));
  CHECK(Triangulation(V{{0, 0, 0}, {1e-99, 0, 0}, {0, 1e-99, 0}, {0, 0, 1e-99}}).num_finite_cells() == 1);
  // A tiny coordinate in a set of ordinary extent is fine.
  CHECK(Triangulation(V{{1e-300, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}).num_finite_cells() == 1);
  CHECK_THROWS_WITH(Triangulation(V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1.0}),
                    Catch::Contains("weights"));
}

TEST_CASE("Edges and triangles: counts, incidences and Euler characteristic", "[simplices]") {
  // Random, a grid (cospherical cubes), points on one sphere, duplicates,
  // weighted with hidden points.
  std::vector<Vec3> duplicated = testing::grid_points(3);
  for (const Vec3& p : testing::grid_points(3)) duplicated.push_back(p);
  for (int kind = 0; kind < 5; ++kind) {
    const Triangulation t = kind == 0   ? Triangulation(testing::random_points(300, 5))
                            : kind == 1 ? Triangulation(testing::grid_points(5))
                            : kind == 2 ? Triangulation(testing::sphere_points(50))
                            : kind == 3 ? Triangulation(duplicated)
                                        : Triangulation(testing::random_points(300, 6, 10.0),
                                                        testing::random_weights(300, 7, 0.0, 4.0));
    INFO("kind " << kind);
    if (kind == 3) CHECK(t.num_duplicates() == 27);
    if (kind == 4) CHECK(t.num_hidden() > 0);
    const Simplices s(t);
    // Finite complex of a convex ball: V - E + F - C = 1; hull surface: V_h - E_h + F_h = 2.
    const long v = long(t.num_vertices()), e = long(s.num_edges()), f = long(s.num_triangles()),
               c = long(t.num_finite_cells());
    CHECK(v - e + f - c == 1);
    // Each finite cell has 4 triangles; each interior triangle 2 finite cells.
    CHECK(4 * c == 2 * (f - long(s.num_hull_triangles())) + long(s.num_hull_triangles()));
    const SimplexCounts counts = count_simplices(t);
    CHECK(counts.edges == s.num_edges());
    CHECK(counts.triangles == s.num_triangles());
    CHECK(counts.hull_triangles == s.num_hull_triangles());
    for (Index x = 0; x < s.num_triangles(); ++x) {
      const auto& tri = s.triangle(x);
      for (int k = 0; k < 3; ++k) {
        const auto& edge = s.edge(s.triangle_edges(x)[k]);
        // Edge k is opposite vertex k.
        CHECK(std::find(edge.begin(), edge.end(), tri[k]) == edge.end());
        CHECK(s.find_edge(edge[0], edge[1]) == s.triangle_edges(x)[k]);
      }
      for (Index cell : s.triangle_cells(x)) {
        int hits = 0;
        for (int i = 0; i < 4; ++i) hits += s.cell_triangle(cell, i) == x;
        CHECK(hits == 1);
      }
    }
    std::size_t incidences = 0;
    for (Index x = 0; x < s.num_edges(); ++x) incidences += s.edge_triangles(x).size();
    CHECK(incidences == 3 * s.num_triangles());
    // An edge's triangles (found by turning around it) are exactly those
    // having it among their edges.
    std::vector<std::vector<Index>> by_edge(s.num_edges());
    for (Index x = 0; x < s.num_triangles(); ++x)
      for (Index y : s.triangle_edges(x)) by_edge[y].push_back(x);
    std::size_t wrong = 0;
    for (Index x = 0; x < s.num_edges(); ++x) {
      std::vector<Index> ring(s.edge_triangles(x).begin(), s.edge_triangles(x).end());
      std::sort(ring.begin(), ring.end());
      wrong += ring != by_edge[x];
    }
    CHECK(wrong == 0);
  }
}
