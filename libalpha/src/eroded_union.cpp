// SPDX-License-Identifier: Apache-2.0
#include "alpha/eroded_union.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "alpha/error.hpp"
#include "alpha/sizes.hpp"
#include "eroded_union_integrator.hpp"

namespace alpha {

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

LayerShare ErodedUnion::layer() const { return measure(nullptr); }

LayerShare ErodedUnion::layer(std::vector<LayerShare>& per_ball) const {
  per_ball.assign(shell_factor_.size(), {});
  return measure(&per_ball);
}

LayerShare ErodedUnion::measure(std::vector<LayerShare>* per_ball) const {
  const AlphaComplex& ac = balls_->complex();
  const Simplices& s = ac.simplices();
  const Integrator in(*this);
  LayerSum sum;
  for (std::size_t i = 0; i < shell_factor_.size(); ++i) {
    sum.add({shell_factor_[i] * balls_->ball_areas()[i], contact_factor_[i] * balls_->ball_areas()[i]});
    if (per_ball) in.shell_shares(Index(i), *per_ball);
  }
  for (Index e = 0; e < s.num_edges(); ++e)
    if (arc_start_[e] != arc_start_[e + 1]) sum.add(in.all_arcs(e, per_ball));
  for (std::size_t v = 0; v < vertices_.size(); ++v) sum.add(in.cone(v, per_ball));
  return sum.value();
}

LayerShare ErodedUnion::cell_share(Index c) const { return share(Integrator(*this), c); }

LayerShare ErodedUnion::cells_share(std::span<const Index> cells) const {
  const Integrator in(*this);
  LayerShare out;
  for (Index c : cells) {
    const LayerShare x = share(in, c);
    out.volume += x.volume;
    out.area += x.area;
  }
  return out;
}

LayerShare ErodedUnion::share(const Integrator& in, Index c) const {
  const AlphaComplex& ac = balls_->complex();
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  if (t.is_infinite(c)) return {};
  LayerSum sum;
  const auto& v = t.cell(c).v;
  for (int k = 0; k < 4; ++k)
    if (shell_factor_[v[k]] > 0 || contact_factor_[v[k]] > 0) {
      const double patch = patch_area(c, k);
      sum.add({shell_factor_[v[k]] * patch, contact_factor_[v[k]] * patch});
    }
  for (int x = 0; x < 4; ++x)
    for (int y = x + 1; y < 4; ++y) {
      const Index e = s.find_edge(v[x], v[y]);
      if (arc_start_[e] != arc_start_[e + 1]) sum.add(in.cell_arcs(c, x, y, e));
    }
  for (int k = 0; k < 4; ++k) {
    const Index f = s.cell_triangle(c, k);
    for (std::size_t p = vertex_start_[f]; p < vertex_start_[f + 1]; ++p)
      if (vertices_[p].cell == c) sum.add(in.cone(p));
  }
  return sum.value();
}

}  // namespace alpha

namespace alpha {

ErodedUnion::Nearby::Nearby(std::shared_ptr<const Integrator> in, std::unique_ptr<Hood> hood)
    : in_(std::move(in)), hood_(std::move(hood)) {}
ErodedUnion::Nearby::Nearby(Nearby&&) noexcept = default;
ErodedUnion::Nearby& ErodedUnion::Nearby::operator=(Nearby&&) noexcept = default;
ErodedUnion::Nearby::~Nearby() = default;

ErodedUnion::Nearby ErodedUnion::nearby(const Vec3& center, double reach) const {
  auto hood = std::make_unique<Nearby::Hood>();
  auto in = std::make_shared<const Integrator>(*this);
  in->gather(center, reach, *hood);
  return Nearby(std::move(in), std::move(hood));
}

ErodedUnion::Nearby ErodedUnion::Nearby::narrowed(const Vec3& center, double reach) const {
  auto hood = std::make_unique<Hood>();
  in_->narrow(*hood_, center, reach, *hood);
  for (const auto& [c, w] : hood_->buried)
    if (in_->buried_near(c, w, center, reach)) hood->buried.emplace_back(c, w);
  return Nearby(in_, std::move(hood));
}

ErodedUnion::Nearest ErodedUnion::Nearby::nearest(const Vec3& x, double limit) const {
  return in_->nearest(*hood_, x, limit);
}

double ErodedUnion::Nearby::outside_by(const Vec3& x) const {
  double d = HUGE_VAL;
  for (const Hood::Ball& b : hood_->balls) d = std::min(d, norm(x - b.c) - b.radius);
  for (const auto& [c, w] : hood_->buried) d = std::min(d, norm(x - c) - std::sqrt(w));
  return d;
}

namespace {

// Whether x lies on the inner side (that of the opposite vertex) of each
// facet k of finite cell c with bit k set in `facets`.
bool inside_facets(const Triangulation& t, Index c, const Vec3& x, unsigned facets) {
  const auto& v = t.cell(c).v;
  for (int k = 0; k < 4; ++k) {
    if (!(facets >> k & 1)) continue;
    const auto& f = kFacet[k];
    const Vec3 a = t.point(v[f[0]]), ab = t.point(v[f[1]]) - a, ac = t.point(v[f[2]]) - a;
    const Vec3 n = cross(ab, ac);
    const double side = dot(n, x - a), inner = dot(n, t.point(v[k]) - a);
    if (side * inner < 0) return false;
  }
  return true;
}

// The cell holding x by a visibility walk from `start` (floating-point
// sides: a point on a facet may go to either cell); an infinite cell when
// x lies beyond the hull.
Index locate(const Triangulation& t, const Vec3& x, Index start) {
  Index c = start;
  if (t.is_infinite(c)) c = t.cell(c).n[t.infinite_position(c)];
  for (std::size_t step = 0; step < 4 * t.num_cells() + 8; ++step) {
    if (t.is_infinite(c)) return c;
    Index next = kNone;
    for (int i = 0; i < 4 && next == kNone; ++i) {
      const int k = int((i + step) % 4);  // rotating start: no cycling on a flat cell
      if (!inside_facets(t, c, x, 1u << k)) next = t.cell(c).n[k];
    }
    if (next == kNone) return c;
    c = next;
  }
  return c;
}

}  // namespace

Index ErodedUnion::share_cell(const Vec3& x, const Nearest& n, Index hint) const {
  const AlphaComplex& ac = balls_->complex();
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  using On = Nearest::On;
  switch (n.on) {
    case On::far:
      return kNone;
    case On::vertex:
      return vertices_[n.which].cell;
    case On::outside:
      return locate(t, x, hint != kNone ? hint : 0);
    case On::sphere:
    case On::circle: {
      // The cells around the ball's vertex (the edge): their cones (wedges)
      // there are bounded by the facets through it, those opposite the
      // cell's other vertices.
      const auto feature = [&](Index v) {
        return n.on == On::sphere ? v == n.which : v == s.edge(n.which)[0] || v == s.edge(n.which)[1];
      };
      const int features = n.on == On::sphere ? 1 : 2;
      const auto around = [&](Index c) {
        int found = 0;
        for (Index v : t.cell(c).v) found += feature(v);
        return found == features;
      };
      // A walk through those cells, from the hint when it is one of them:
      // across a facet through the feature that has the point on its far
      // side (the first facet tried rotating, as in locate). A few steps
      // where trying every cell around took dozens. Crossing into an
      // infinite cell, the point is beyond a hull facet through the
      // feature, outside every finite cell's cone (they fill the hull's
      // tangent cone there): that cell is the answer (all infinite cells
      // count alike: no share).
      const Index first_edge = n.on == On::sphere ? s.vertex_edges(n.which).front() : n.which;
      Index c = hint;
      if (c == kNone || t.is_infinite(c) || !around(c)) {
        const auto cells = s.triangle_cells(*s.edge_triangles(first_edge).begin());
        c = t.is_infinite(cells[0]) ? cells[1] : cells[0];
      }
      for (std::size_t step = 0; step < 64; ++step) {
        if (t.is_infinite(c)) return c;
        Index next = kNone;
        for (int i = 0; i < 4 && next == kNone; ++i) {
          const int k = int((i + step) % 4);
          if (!feature(t.cell(c).v[k]) && !inside_facets(t, c, n.point, 1u << k)) next = t.cell(c).n[k];
        }
        if (next == kNone) return c;
        c = next;
      }
      // Round in circles (rounding on flat cells; not seen so far): every
      // cell around, the first finite one holding the point, else an
      // infinite one.
      Index any = kNone;
      const auto holds = [&](Index cell) {
        unsigned facets = 0;
        for (int k = 0; k < 4; ++k)
          if (!feature(t.cell(cell).v[k])) facets |= 1u << k;
        return inside_facets(t, cell, n.point, facets);
      };
      const auto search = [&](Index e) {
        for (Index f : s.edge_triangles(e))
          for (Index cell : s.triangle_cells(f)) {
            if (t.is_infinite(cell)) any = cell;
            else if (holds(cell)) return cell;
          }
        return kNone;
      };
      if (n.on == On::circle) {
        const Index found = search(n.which);
        return found != kNone ? found : any;
      }
      for (Index e : s.vertex_edges(n.which))
        if (const Index found = search(e); found != kNone) return found;
      return any;
    }
  }
  return kNone;
}

}  // namespace alpha
