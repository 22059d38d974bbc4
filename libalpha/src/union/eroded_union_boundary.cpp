// SPDX-License-Identifier: Apache-2.0
// ErodedUnion's constructor: the union's boundary found, its arcs on the
// circles of edges of K, its vertices, the covering neighbours of each
// sphere; nothing integrated yet (eroded_union_integrator.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "alpha/eroded_union.hpp"
#include "alpha/error.hpp"
#include "alpha/sizes.hpp"
#include "union/eroded_union_geometry.hpp"

namespace alpha {

using namespace eroded_union_detail;

ErodedUnion::ErodedUnion(const UnionOfBalls& balls, double r) : balls_(&balls), r_(r) {
  const AlphaComplex& ac = balls.complex();
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  if (!(r >= 0) || !std::isfinite(r)) fail("eroded union: the erosion radius must be a number >= 0", ErrorKind::Misuse);
  const std::size_t n = t.num_points();
  shell_factor_.assign(n, 0.0);
  contact_factor_.assign(n, 0.0);
  for (Index i = 0; i < n; ++i) {
    if (!balls.in_dual_complex_vertex(i) || balls.ball_areas()[i] == 0) continue;
    const double radius = std::sqrt(t.weight(i));
    if (radius < r)
      fail("eroded union: ball " + std::to_string(i) + " of radius " + std::to_string(radius) +
           " on the boundary is smaller than the erosion radius " + std::to_string(r), ErrorKind::Misuse);
    const double inner = radius - r;
    shell_factor_[i] = (radius - inner) * (radius * radius + radius * inner + inner * inner) / (3 * radius * radius);
    contact_factor_[i] = inner * inner / (radius * radius);
    max_radius_ = std::max(max_radius_, radius);
  }
  tolerance_ = 1e-9 * std::max(max_radius_, r);
  const double power_tolerance = 2 * tolerance_ * max_radius_;

  // Covers: a ball that does not meet sphere i covers none of its points
  // (the test's tolerance is far above the rounding of a point on it).
  cover_start_.assign(n + 1, 0);
  for (Index i = 0; i < n; ++i) {
    cover_start_[i] = covers_.size();
    if (balls.ball_areas()[i] == 0) continue;
    const double radius = std::sqrt(t.weight(i));
    for (Index e : s.vertex_edges(i)) {
      const auto& v = s.edge(e);
      const Index m = v[0] == i ? v[1] : v[0];
      const double radius_m = std::sqrt(t.weight(m));
      if (norm(t.point(m) - t.point(i)) < radius + radius_m + tolerance_)
        covers_.push_back({t.point(m), t.weight(m) - 2 * tolerance_ * radius_m});
    }
  }
  cover_start_[n] = covers_.size();

  // Arcs: each circle of an edge of K, less the balls of its ring.
  arc_start_.assign(s.num_edges() + 1, 0);
  std::vector<Arc> set, scratch;
  for (Index e = 0; e < s.num_edges(); ++e) {
    arc_start_[e] = arcs_.size();
    if (r == 0 || !balls.in_dual_complex_edge(e)) continue;
    const auto& v = s.edge(e);
    const Circle c = circle_of(t, v);
    if (c.rho <= tolerance_) continue;  // touching balls: no arc worth a piece
    set.assign(1, {0, kTwoPi});
    for (Index f : s.edge_triangles(e)) {
      for (Index k : s.triangle(f)) {
        if (k == v[0] || k == v[1]) continue;
        // On the circle, |x - p_k|^2 >= R_k^2 reads A cos phi + B sin phi <= C.
        const Vec3 g = c.o - t.point(k);
        const double a = -2 * c.rho * dot(g, c.e1), b = -2 * c.rho * dot(g, c.e2);
        keep_below(set, a, b, dot(g, g) + c.rho * c.rho - t.weight(k), scratch);
        if (set.empty()) break;
      }
      if (set.empty()) break;
    }
    arcs_.insert(arcs_.end(), set.begin(), set.end());
    for (const Arc& a : set)
      arc_ends_.push_back({std::cos(a.begin), std::sin(a.begin), std::cos(a.begin + a.length), std::sin(a.begin + a.length)});
    const auto bound = arc_bound(set, arc_ends_.data() + arc_start_[e], c);
    arc_bounds_.insert(arc_bounds_.end(), set.size(), bound);
  }
  arc_start_[s.num_edges()] = arcs_.size();
  circle_start_.assign(n + 1, 0);
  for (Index i = 0; i < n; ++i) {
    circle_start_[i] = circle_edges_.size();
    for (Index e : s.vertex_edges(i))
      if (s.edge(e)[0] == i && arc_start_[e] != arc_start_[e + 1]) circle_edges_.push_back(e);
  }
  circle_start_[n] = circle_edges_.size();

  // Vertices: the two points where the spheres of a triangle of K meet,
  // kept when no apex of its two cells covers them (on its Voronoi edge).
  const SizeKernel kernel = ac.size_kernel();
  vertex_start_.assign(s.num_triangles() + 1, 0);
  for (Index f = 0; f < s.num_triangles(); ++f) {
    vertex_start_[f] = vertices_.size();
    if (r == 0 || !balls.in_dual_complex_triangle(f)) continue;
    const auto v = s.triangle(f);
    const Vec3 p0 = t.point(v[0]), normal = cross(t.point(v[1]) - p0, t.point(v[2]) - p0);
    const double nn = dot(normal, normal);
    if (nn == 0) continue;
    // The point of the plane with equal power to the three balls (the
    // triangle's orthocentre); the spheres meet above and below it.
    const Vec3 z0 = kernel.center(Simplex(v[0], v[1], v[2]));
    // Three spheres meeting (almost) in their centers' plane: a flat cone,
    // and the two points within rounding of each other.
    const double h_sq = t.weight(v[0]) - dot(z0 - p0, z0 - p0);
    if (h_sq <= 1e6 * tolerance_ * tolerance_) continue;
    const double h = std::sqrt(h_sq / nn);
    const auto cells = s.triangle_cells(f);
    for (const double side : {1.0, -1.0}) {
      const Vec3 z = z0 + (side * h) * normal;
      bool covered = false;
      Index cell = kNone;
      double best = -1;
      for (Index cc : cells) {
        double height = 0;  // of the apex above the plane, on z's side; 0 for the infinite vertex
        if (!t.is_infinite(cc)) {
          const Index apex = t.cell(cc).v[0] + t.cell(cc).v[1] + t.cell(cc).v[2] + t.cell(cc).v[3] - v[0] - v[1] - v[2];
          const Vec3 d = z - t.point(apex);
          covered = covered || dot(d, d) < t.weight(apex) - power_tolerance;
          height = side * dot(t.point(apex) - z0, normal);
        }
        if (cell == kNone || height > best) cell = cc, best = height;
      }
      if (!covered) vertices_.push_back({z, f, cell});
    }
  }
  vertex_start_[s.num_triangles()] = vertices_.size();

  // Cells of the largest radius: a gather's cube (its radius plus that
  // radius) spans about four a side, which visits a third of the balls that
  // cells of the cube's size would.
  ball_grid_ = PointGrid(max_radius_ + tolerance_);
  for (Index i = 0; i < n; ++i)
    if (balls.in_dual_complex_vertex(i)) ball_grid_.add(t.point(i), i);
  ball_grid_.finish();
  vertex_grid_ = PointGrid(2 * r + tolerance_);
  for (std::size_t v = 0; v < vertices_.size(); ++v) vertex_grid_.add(vertices_[v].p, Index(v));
  vertex_grid_.finish();
}

}  // namespace alpha
