// SPDX-License-Identifier: Apache-2.0
// ErodedUnion::patch_area: a sphere's patch on the union's boundary inside
// a cell's cone at the sphere's centre, in closed form. The cells' shares
// give a patch's shell this area's part of it: the shell under the patch
// split by the same cones as the rest of the layer (share_cell), a region
// of space, where a fractional share of the patch's area was not.
#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "union/eroded_union_integrator.hpp"

namespace alpha {
namespace {

// Signed area of the geodesic triangle of unit vectors (a, b, c): positive
// when counterclockwise seen from outside (Van Oosterom & Strackee).
double spherical_triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 2 * std::atan2(dot(a, cross(b, c)), 1 + dot(a, b) + dot(b, c) + dot(c, a));
}

// The area of the part of the unit sphere where g.n <= h for every (g, h)
// of `halfspaces`, all of whose points n have m.n > 0 (m unit). Stokes'
// theorem on the form (1 - n.m) dphi, phi the longitude about m (its
// derivative is the area element; singular only at -m, outside the part)
// around the part's boundary, arcs of the halfspaces' circles, the part on
// their left: an arc from a to b about the circle's centre c adds the loop
// (m, a, the arc, b), i.e. the geodesic triangle (m, a, b) plus the cap's
// sector from c less the triangle (c, a, b). Arcs are cut to quarter
// turns, so that no triangle has two opposite corners. bounds[k]: whether
// circle k can bound the part (one known to hold none of its boundary is
// not clipped: its arcs would all be cut away).
double sphere_part_area(std::span<const std::pair<Vec3, double>> halfspaces, std::span<const char> bounds,
                        const Vec3& m) {
  Sum area;
  thread_local std::vector<Arc> set, scratch;  // kept from call to call: no allocation per cell
  for (std::size_t k = 0; k < halfspaces.size(); ++k) {
    const auto& [g, h] = halfspaces[k];
    const double length = norm(g);
    if (h >= length) continue;  // the whole sphere: no circle
    if (h <= -length) return 0;
    if (!bounds[k]) continue;
    // The part's side of the circle is the cap c.n >= cos_radius about
    // c = -g / |g|; the arcs go round c counterclockwise (turn 1). The cap
    // of the opposite centre (turn -1) when that is the smaller.
    Vec3 c = (-1 / length) * g;
    double cos_radius = -h / length, turn = 1;
    if (cos_radius < 0) {
      c = -1.0 * c;
      cos_radius = -cos_radius;
      turn = -1;
    }
    const Circle frame = circle_of_axis(c);
    const double sin_radius = std::sqrt((1 - cos_radius) * (1 + cos_radius));
    set.assign(1, {0, kTwoPi});
    for (std::size_t j = 0; j < halfspaces.size() && !set.empty(); ++j) {
      if (j == k) continue;
      const auto& [gj, hj] = halfspaces[j];
      keep_below(set, sin_radius * dot(gj, frame.e1), sin_radius * dot(gj, frame.e2), hj - cos_radius * dot(gj, c),
                 scratch);
    }
    for (const Arc& a : set) {
      const int parts = int(std::ceil(a.length / (kPi / 2)));
      for (int p = 0; p < parts; ++p) {
        double from = a.begin + a.length * p / parts, to = a.begin + a.length * (p + 1) / parts;
        if (turn < 0) std::swap(from, to);
        const Vec3 x = cos_radius * c + sin_radius * frame.radial(from);
        const Vec3 y = cos_radius * c + sin_radius * frame.radial(to);
        area.add(spherical_triangle_area(m, x, y) + (to - from) * (1 - cos_radius) - spherical_triangle_area(c, x, y));
      }
    }
  }
  return area.value();
}

}  // namespace

double ErodedUnion::patch_area(Index c, int k) const {
  const Triangulation& t = balls_->complex().triangulation();
  const Simplices& s = balls_->complex().simplices();
  if (t.is_infinite(c)) return 0;
  const Index i = t.cell(c).v[k];
  if (balls_->ball_areas()[i] == 0) return 0;
  const Vec3 pi = t.point(i);
  const double wi = t.weight(i), radius = std::sqrt(wi);
  // The cone: its faces first (they cut most circles away at once).
  std::array<Vec3, 3> u;
  for (int n = 1; n < 4; ++n) {
    const Vec3 d = t.point(t.cell(c).v[(k + n) % 4]) - pi;
    u[n - 1] = (1 / norm(d)) * d;
  }
  // The cone's directions n lie within the angle acos(cos_cone) of m
  // (the normal of the plane of u, the same dot with each u[n]).
  Vec3 m = cross(u[1] - u[0], u[2] - u[0]);
  m = (dot(m, u[0]) < 0 ? -1 / norm(m) : 1 / norm(m)) * m;
  const double cos_cone = dot(m, u[0]), sin_cone = std::sqrt((1 - cos_cone) * (1 + cos_cone));
  // Whether the directions within acos(cos_a) of v / |v| all lie outside
  // that reach of m (by a margin far above rounding).
  const auto apart = [&](const Vec3& v, double length, double cos_a) {
    const double sin_a = std::sqrt((1 - cos_a) * (1 + cos_a));
    const double cos_reach = cos_a * cos_cone - sin_a * sin_cone;  // cos(a + cone), when both sum below pi
    return cos_a + cos_cone > 0 && dot(v, m) < length * (cos_reach - 1e-9);
  };
  // Whether the circle of edge e can bound the patch in the cone: not when
  // the union's arcs on it (kept when r > 0) are none, or all outside the
  // cone's reach (their bounding ball's points on the sphere lie within
  // acos(cos_b) of its centre's direction).
  const auto can_bound = [&](Index e) {
    if (r_ == 0) return true;
    if (arc_start_[e] == arc_start_[e + 1]) return false;
    const auto& [centre, b] = arc_bounds_[arc_start_[e]];
    const Vec3 d = centre - pi;
    const double length = norm(d);
    if (!(length > 0)) return true;
    const double cos_b = (wi + length * length - b * b) / (2 * radius * length);
    return cos_b <= -1 || !apart(d, length, std::min(cos_b, 1.0));
  };
  thread_local std::vector<std::pair<Vec3, double>> halfspaces;  // kept from call to call
  thread_local std::vector<char> bounds;
  halfspaces.clear();
  bounds.assign(3, 1);
  for (int n = 0; n < 3; ++n) {
    Vec3 inward = cross(u[(n + 1) % 3], u[(n + 2) % 3]);  // towards u[n]
    if (dot(inward, u[n]) < 0) inward = -1.0 * inward;
    halfspaces.push_back({-1.0 * inward, 0.0});
  }
  // The patch: p_i + R n outside each neighbour's ball, of those whose
  // cap on the sphere (directions within acos(h / |g|) of g) comes within
  // the cone's reach of m (the others cover none of it).
  for (Index e : s.vertex_edges(i)) {
    const Index j = s.edge(e)[0] == i ? s.edge(e)[1] : s.edge(e)[0];
    const Vec3 d = t.point(j) - pi;
    const Vec3 g = 2 * radius * d;
    const double h = wi + dot(d, d) - t.weight(j), length = norm(g);
    if (h >= length || apart(g, length, std::max(h / length, -1.0))) continue;
    halfspaces.push_back({g, h});
    bounds.push_back(can_bound(e));
  }
  return wi * sphere_part_area(halfspaces, bounds, m);
}

}  // namespace alpha
