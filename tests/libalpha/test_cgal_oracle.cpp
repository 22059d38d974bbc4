// SPDX-License-Identifier: Apache-2.0
// CGAL as an independent oracle: on generic inputs (random doubles) the
// Delaunay / regular triangulation is unique, so ours must match CGAL's
// simplex for simplex. On a degenerate grid only invariants are compared.
#include <catch2/catch.hpp>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"
#include "point_sets.hpp"

using alpha::Index;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
// Each CGAL vertex carries the index of its input point.
using DelaunayTds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<Index, K>,
                                                         CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, DelaunayTds>;
using RegularTds = CGAL::Triangulation_data_structure_3<
    CGAL::Triangulation_vertex_base_with_info_3<Index, K, CGAL::Regular_triangulation_vertex_base_3<K>>,
    CGAL::Regular_triangulation_cell_base_3<K>>;
using Regular = CGAL::Regular_triangulation_3<K, RegularTds>;

// A triangulation as sorted lists of simplices, each a sorted tuple of input
// indices: comparable whatever the ids, orientation or storage order.
struct Complex {
  std::vector<Index> vertices;
  std::vector<std::array<Index, 2>> edges;
  std::vector<std::array<Index, 3>> triangles, hull;
  std::vector<std::array<Index, 4>> cells;

  void sort_all() {
    std::sort(vertices.begin(), vertices.end());
    std::sort(edges.begin(), edges.end());
    std::sort(triangles.begin(), triangles.end());
    std::sort(hull.begin(), hull.end());
    std::sort(cells.begin(), cells.end());
  }
};

template <std::size_t N>
std::array<Index, N> sorted(std::array<Index, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

Complex our_complex(const alpha::Triangulation& t) {
  const alpha::Simplices s(t);
  Complex c;
  for (Index i = 0; i < t.num_points(); ++i)
    if (t.status(i) == alpha::PointStatus::vertex) c.vertices.push_back(i);
  for (Index e = 0; e < s.num_edges(); ++e) c.edges.push_back(sorted(s.edge(e)));
  for (Index f = 0; f < s.num_triangles(); ++f) {
    c.triangles.push_back(sorted(s.triangle(f)));
    if (s.on_hull(f)) c.hull.push_back(c.triangles.back());
  }
  for (Index i = 0; i < t.num_cells(); ++i)
    if (!t.is_infinite(i)) c.cells.push_back(sorted(t.cell(i).v));
  c.sort_all();
  return c;
}

// Works for both Delaunay and Regular (same Triangulation_3 interface).
template <class T>
Complex cgal_complex(const T& t) {
  Complex c;
  for (auto v : t.finite_vertex_handles()) c.vertices.push_back(v->info());
  for (const auto& e : t.finite_edges())
    c.edges.push_back(sorted<2>({e.first->vertex(e.second)->info(), e.first->vertex(e.third)->info()}));
  for (const auto& [cell, opposite] : t.finite_facets()) {
    std::array<Index, 3> tri;
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != opposite) tri[m++] = cell->vertex(k)->info();
    c.triangles.push_back(sorted(tri));
    if (t.is_infinite(cell) || t.is_infinite(cell->neighbor(opposite))) c.hull.push_back(c.triangles.back());
  }
  for (auto cell : t.finite_cell_handles()) {
    std::array<Index, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = cell->vertex(k)->info();
    c.cells.push_back(sorted(q));
  }
  c.sort_all();
  return c;
}

// Size of the symmetric difference of two sorted lists (0 iff equal). Counted
// rather than compared with == so a failure does not print 30000 tuples.
template <class T>
std::size_t mismatches(const std::vector<T>& a, const std::vector<T>& b) {
  std::vector<T> diff;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff));
  return diff.size();
}

void check_same(const Complex& ours, const Complex& cgal) {
  CHECK(ours.vertices.size() == cgal.vertices.size());
  CHECK(ours.edges.size() == cgal.edges.size());
  CHECK(ours.triangles.size() == cgal.triangles.size());
  CHECK(ours.hull.size() == cgal.hull.size());
  CHECK(ours.cells.size() == cgal.cells.size());
  CHECK(mismatches(ours.vertices, cgal.vertices) == 0);
  CHECK(mismatches(ours.edges, cgal.edges) == 0);
  CHECK(mismatches(ours.triangles, cgal.triangles) == 0);
  CHECK(mismatches(ours.hull, cgal.hull) == 0);
  CHECK(mismatches(ours.cells, cgal.cells) == 0);
}

K::Point_3 to_cgal(const alpha::Vec3& p) { return {p.x, p.y, p.z}; }

double tet_volume(const alpha::Vec3& a, const alpha::Vec3& b, const alpha::Vec3& c, const alpha::Vec3& d) {
  return CGAL::volume(to_cgal(a), to_cgal(b), to_cgal(c), to_cgal(d));
}

}  // namespace

TEST_CASE("Delaunay of random points equals CGAL's", "[cgal]") {
  for (std::size_t n : {50, 500, 5000}) {
    const auto pts = testing::random_points(n, 1000 + n);
    std::vector<std::pair<K::Point_3, Index>> input;
    for (Index i = 0; i < n; ++i) input.emplace_back(to_cgal(pts[i]), i);
    const Delaunay cgal(input.begin(), input.end());
    const alpha::Triangulation ours(pts);

    INFO("n = " << n);
    REQUIRE(cgal.number_of_vertices() == n);
    check_same(our_complex(ours), cgal_complex(cgal));
  }
}

TEST_CASE("Regular triangulation of weighted random points equals CGAL's", "[cgal][weighted]") {
  for (std::size_t n : {50, 500, 5000}) {
    // About one point per unit volume and weights (squared radii) up to 1:
    // balls overlap enough that a fair share of the points are hidden.
    const auto pts = testing::random_points(n, 2000 + n, std::cbrt(double(n)));
    const auto w = testing::random_weights(n, 3000 + n, 0.0, 1.0);
    std::vector<std::pair<K::Weighted_point_3, Index>> input;
    for (Index i = 0; i < n; ++i) input.emplace_back(K::Weighted_point_3(to_cgal(pts[i]), w[i]), i);
    const Regular cgal(input.begin(), input.end());
    const alpha::Triangulation ours(pts, w);

    INFO("n = " << n);
    REQUIRE(ours.num_hidden() > 0);  // otherwise hiding would go untested
    CHECK(ours.num_hidden() == n - cgal.number_of_vertices());
    check_same(our_complex(ours), cgal_complex(cgal));
  }
}

TEST_CASE("Degenerate grid: same vertices, hull and volume as CGAL", "[cgal][degenerate]") {
  // Cospherical cubes: neither triangulation is unique, but both must use
  // every point and tile the same cube.
  const auto pts = testing::grid_points(8);
  std::vector<K::Point_3> input;
  for (const auto& p : pts) input.push_back(to_cgal(p));
  const Delaunay cgal(input.begin(), input.end());
  const alpha::Triangulation ours(pts);

  double cgal_volume = 0, our_volume = 0;
  for (auto c : cgal.finite_cell_handles()) cgal_volume += cgal.tetrahedron(c).volume();
  for (Index c = 0; c < ours.num_cells(); ++c) {
    if (ours.is_infinite(c)) continue;
    const auto& v = ours.cell(c).v;
    our_volume += tet_volume(ours.point(v[0]), ours.point(v[1]), ours.point(v[2]), ours.point(v[3]));
  }

  CHECK(ours.num_vertices() == cgal.number_of_vertices());
  CHECK(ours.num_vertices() == pts.size());
  CHECK(our_volume == Approx(cgal_volume).epsilon(1e-12));
  CHECK(our_volume == Approx(7.0 * 7.0 * 7.0).epsilon(1e-12));
  // Each 7x7 face splits into 98 triangles however its squares are cut;
  // CGAL joins every hull triangle to one infinite cell.
  const std::size_t cgal_hull = cgal.number_of_cells() - cgal.number_of_finite_cells();
  CHECK(cgal_hull == 6 * 98);
  CHECK(alpha::Simplices(ours).num_hull_triangles() == cgal_hull);
}
