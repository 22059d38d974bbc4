// SPDX-License-Identifier: Apache-2.0
// The integrals of ErodedUnion's pieces (eroded_union_integrator.cpp: the
// totals, the cells' shares and the nearest-point queries;
// eroded_union_shares.cpp: the per-atom split; eroded_union_patch.cpp: the
// patches' areas), on the free geometry of eroded_union_geometry.hpp and
// the hoods of eroded_union_hood.hpp. Internal: included by those three
// files only.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "alpha/eroded_union.hpp"
#include "numerics/compensated_sum.hpp"
#include "union/eroded_union_geometry.hpp"
#include "union/eroded_union_hood.hpp"
#include "union/piece_shares.hpp"

namespace alpha {
namespace eroded_union_detail {

using Nearest = ErodedUnion::Nearest;

// Volumes and areas of pieces, summed compensated in the order added.
struct LayerSum {
  Sum volume, area;
  void add(const LayerShare& x) {
    volume.add(x.volume);
    area.add(x.area);
  }
  LayerShare value() const { return {volume.value(), area.value()}; }
};

}  // namespace eroded_union_detail

using namespace eroded_union_detail;

// The integrals of the pieces of one ErodedUnion.
class ErodedUnion::Integrator {
  friend class ErodedUnion;  // nearby() gathers

public:
  using Hood = Nearby::Hood;

  // The nearest point of F to x, if nearer than limit (see Nearest): on a
  // sphere whose ball holds x (x's radial projection, kept when on the
  // boundary), on an arc (the circle's nearest point, kept when on an
  // arc) or a boundary vertex; the nearest of these is the nearest point.
  Nearest nearest(const Hood& h, const Vec3& x, double limit) const {
    using On = Nearest::On;
    Nearest best{On::far, limit, x, kNone};
    // The balls holding x, nearest sphere first: the first whose radial
    // projection of x lies on the boundary gives the nearest sphere point
    // (the boundary test is the costly part: mostly one is needed).
    std::vector<std::pair<double, std::size_t>>& holding = h.holding;
    holding.clear();
    for (std::size_t k = 0; k < h.balls.size(); ++k) {
      const Hood::Ball& b = h.balls[k];
      const Vec3 d = x - b.c;
      const double dd = dot(d, d);
      if (dd >= b.radius_sq) continue;
      const double dist = b.radius - std::sqrt(dd);
      if (dist >= limit) return best;  // F lies outside this ball: at least dist away
      holding.emplace_back(dist, k);
    }
    bool in_union = !holding.empty();
    std::sort(holding.begin(), holding.end());
    for (const auto& [dist, k] : holding) {
      const Hood::Ball& b = h.balls[k];
      const Vec3 d = x - b.c;
      const double rd = std::sqrt(dot(d, d));
      if (rd == 0) continue;
      const Vec3 q = b.c + (b.radius / rd) * d;
      if (on_boundary(b.id, q, b.cover)) {
        best = {On::sphere, dist, q, b.id};
        break;
      }
    }
    for (std::size_t k = 0; k < h.buried.size() && !in_union; ++k)
      in_union = dot(x - h.buried[k].first, x - h.buried[k].first) < h.buried[k].second;
    if (!in_union) return {On::outside, 0, x, kNone};
    for (std::size_t k = 0; k < h.circles.size(); ++k) {
      // Only a circle with an arc point nearer than the best so far can
      // be nearer: most are further, as the ball holding their arcs shows.
      const auto& [m, b] = h.arc_bounds[k];
      const double reach = best.distance + b + 4 * tol_;
      if (dot(x - m, x - m) >= reach * reach) continue;
      const auto& [e, c] = h.circles[k];
      const Vec3 y = x - c.o;
      const double z = dot(y, c.w);
      if (std::fabs(z) >= best.distance) continue;
      const Vec3 perp = y - z * c.w;
      const double s = std::sqrt(dot(perp, perp));
      const double dist = std::sqrt(c.squared_distance(s, z));
      if (dist >= best.distance) continue;
      const double px = s > 0 ? dot(perp, c.e1) / s : eu_.arc_ends_[eu_.arc_start_[e]].cos_begin;
      const double py = s > 0 ? dot(perp, c.e2) / s : eu_.arc_ends_[eu_.arc_start_[e]].sin_begin;
      if (contains(edge_arcs(e), eu_.arc_ends_.data() + eu_.arc_start_[e], px, py))
        best = {On::circle, dist, c.o + c.rho * (px * c.e1 + py * c.e2), e};
    }
    for (const std::size_t v : h.vertices) {
      // The square root only for vertices that can be nearer (the bound
      // is far above the rounding of both sides).
      const Vec3 d = x - eu_.vertices_[v].p;
      const double dd = dot(d, d);
      if (dd >= best.distance * best.distance * (1 + 1e-9)) continue;
      const double dist = std::sqrt(dd);
      if (dist < best.distance) best = {On::vertex, dist, eu_.vertices_[v].p, Index(v)};
    }
    return best;
  }


  explicit Integrator(const ErodedUnion& eu)
      : eu_(eu), t_(eu.balls_->complex().triangulation()), s_(eu.balls_->complex().simplices()), r_(eu.r_),
        tol_(eu.tolerance_) {}

  // The pieces of edge e's arcs (on circle c) inside `sector`, integrated.
  // per_ball: also each piece split by power cell (see add_scaled).
  LayerShare arcs(Index e, const Circle& c, const Arc& sector, std::vector<LayerShare>* per_ball = nullptr) const {
    LayerShare out;
    std::vector<Arc> pieces;
    clip(edge_arcs(e), sector, pieces);
    const std::vector<Site> sites = per_ball ? sites_near(s_.edge(e)) : std::vector<Site>{};
    for (const Arc& piece : pieces) {
      const int parts = int(std::ceil(piece.length / kMaxPiece));
      for (int k = 0; k < parts; ++k) {
        const double begin = piece.begin + piece.length * k / parts, end = piece.begin + piece.length * (k + 1) / parts;
        // The piece's points are within r of the arc, whose ends are a chord
        // 2 rho sin(length / 4) from its midpoint.
        gather(c.o + c.rho * c.radial((begin + end) / 2), 2 * c.rho * std::sin((end - begin) / 4) + r_, piece_);
        bool all_clear;
        const LayerShare x = arc_piece(piece_, c, begin, end, all_clear);
        if (per_ball) {
          PieceShares split;
          const Vec3 mid = c.o + c.rho * c.radial((begin + end) / 2);
          arc_shares(c, begin, end, all_clear,
                     near_sites(sites, s_.edge(e), mid, 2 * c.rho * std::sin((end - begin) / 4) + r_ + tol_), split);
          add_scaled(split, x, s_.edge(e)[0], *per_ball);
        }
        out.volume += x.volume;
        out.area += x.area;
      }
    }
    return out;
  }

  // The pieces of edge e's arcs in the sector of cell c about it (local
  // vertices x, y): between the half-planes through its two other vertices,
  // the short way round.
  LayerShare cell_arcs(Index c, int x, int y, Index e) const {
    const auto& v = t_.cell(c).v;
    const Circle frame = circle_of(t_, s_.edge(e));
    std::array<double, 2> phi;
    int n = 0;
    for (int k = 0; k < 4; ++k)
      if (k != x && k != y) phi[n++] = frame.angle(t_.point(v[k]) - frame.o);
    const double span = wrap(phi[1] - phi[0]);
    return arcs(e, frame, span <= kPi ? Arc{phi[0], span} : Arc{phi[1], kTwoPi - span});
  }

  // The whole circle of edge e, split where its ring's half-planes meet it
  // (the same pieces as the sectors of its cells).
  LayerShare all_arcs(Index e, std::vector<LayerShare>* per_ball) const {
    const auto& ev = s_.edge(e);
    const Circle frame = circle_of(t_, ev);
    std::vector<double> cuts;
    for (Index f : s_.edge_triangles(e))
      for (Index k : s_.triangle(f))
        if (k != ev[0] && k != ev[1]) cuts.push_back(frame.angle(t_.point(k) - frame.o));
    std::sort(cuts.begin(), cuts.end());
    LayerShare out;
    if (cuts.empty()) return arcs(e, frame, {0, kTwoPi}, per_ball);
    for (std::size_t k = 0; k < cuts.size(); ++k) {
      const double next = k + 1 < cuts.size() ? cuts[k + 1] : cuts[0] + kTwoPi;
      const LayerShare x = arcs(e, frame, {cuts[k], next - cuts[k]}, per_ball);
      out.volume += x.volume;
      out.area += x.area;
    }
    return out;
  }

  // The reentrant piece of vertex v (index into vertices_).
  LayerShare cone(std::size_t v, std::vector<LayerShare>* per_ball = nullptr) const {
    const Vertex& vx = eu_.vertices_[v];
    const auto tri = s_.triangle(vx.triangle);
    std::array<Vec3, 3> dir;
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = t_.point(tri[k]) - vx.p;
      dir[k] = (1 / norm(d)) * d;
    }
    const SphericalTriangle cone(dir);
    gather(vx.p, r_, piece_);
    const Hood& hood = piece_;
    // The points at r lie in the cap about the directions' mean that holds
    // the three (the cone is inside it when that is less than a quarter
    // turn wide): tested against what can be found from that cap.
    const Vec3 sum = dir[0] + dir[1] + dir[2], mean = (1 / norm(sum)) * sum;
    const double cos_cap = std::min({dot(mean, dir[0]), dot(mean, dir[1]), dot(mean, dir[2])});
    const Hood* near_r = &hood;
    if (cos_cap > 0) {
      keep_at_r(hood, vx.p, mean, cos_cap, at_r_[0]);
      near_r = &at_r_[0];
    }
    const auto clear_at_r = [&](double s, double sigma) {
      return clear(*near_r, vx.p + r_ * cone.direction(s, sigma, nullptr), r_, v);
    };
    // The nodes' sigma, each computed once.
    std::array<SphericalTriangle::Meridian, 8> meridians;
    for (int j = 0; j < 8; ++j) meridians[j] = cone.meridian(node(0, 1, j));
    std::array<std::array<bool, 8>, 8> at_r;
    bool all_clear = true;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        all_clear =
            (at_r[i][j] = clear(*near_r, vx.p + r_ * cone.direction(node(0, 1, i), meridians[j], nullptr), r_, v)) &&
            all_clear;
    LayerShare out;
    if (all_clear) {
      const double omega = solid_angle({}, dir[0], dir[1], dir[2]);
      out = {omega * r_ * r_ * r_ / 3, omega * r_ * r_};
    }
    // Per s, sigma in pieces where the eroded surface is there (tau = r)
    // or cut off: tau^3 / 3 and r^2 over the solid angle.
    for (int i = 0; i < 8 && !all_clear; ++i) {
      const double s = node(0, 1, i);
      for (const Segment& g : segments(0, 1, at_r[i], [&](double sigma) { return clear_at_r(s, sigma); }))
        for (int j = 0; j < 8; ++j) {
          double jac;
          // A segment of the whole row has the nodes' sigma.
          const Vec3 u = g.lo == 0 && g.hi == 1 ? cone.direction(s, meridians[j], &jac)
                                                : cone.direction(s, node(g.lo, g.hi, j), &jac);
          const double w = weight(0, 1, i) * weight(g.lo, g.hi, j) * jac;
          const double tau = g.holds ? r_ : cut(hood, vx.p, u, v, near_r);
          out.volume += w * tau * tau * tau / 3;
          if (g.holds) out.area += w * r_ * r_;
        }
    }
    if (per_ball) {
      PieceShares split;
      cone_shares(v, hood, all_clear, split);
      add_scaled(split, out, tri[0], *per_ball);
    }
    return out;
  }

  // Per-atom splits (eroded_union_shares.cpp): the parts of pieces in
  // power cells; see ErodedUnion::layer(per_ball).
  std::vector<Site> sites_near(std::span<const Index> balls) const;
  static std::vector<Site> near_sites(std::span<const Site> sites, std::span<const Index> owners, const Vec3& center,
                                      double radius);
  static void add_scaled(const PieceShares& s, const LayerShare& total, Index fallback,
                         std::vector<LayerShare>& per_ball);
  void arc_shares(const Circle& c, double begin, double end, bool all_clear, std::span<const Site> sites,
                  PieceShares& out) const;
  void cone_shares(std::size_t v, const Hood& hood, bool all_clear, PieceShares& out) const;
  void shell_shares(Index i, std::vector<LayerShare>& per_ball) const;

private:
  template <class G>
  void split_ray(std::span<const Site> sites, const Vec3& q, const Vec3& u, double tau, double w, double area, G g,
                 PieceShares& out) const;
  template <class Predicate>
  static std::vector<Segment> node_segments(double a, double b, bool all_clear, Predicate holds);
  template <class CellAt>
  static std::vector<Segment> by_cell(const std::vector<Segment>& in, CellAt cell_at, bool other_cells);
  Index end_cell(std::span<const Site> sites, const Vec3& q, const Vec3& u) const;

  const ErodedUnion& eu_;
  const Triangulation& t_;
  const Simplices& s_;
  double r_, tol_;
  // Scratch kept from piece to piece (no allocation per piece): a piece's
  // hood, arc_piece's rows and their points at r (per node phi), gather's
  // balls.
  mutable Hood piece_;
  mutable std::array<Hood, 8> rows_, at_r_;
  mutable Hood segment_;  // the part near a short stretch of tests: cut()'s, arc_piece()'s changes
  mutable std::vector<Index> ids_;

  std::span<const Arc> edge_arcs(Index e) const {
    return {eu_.arcs_.data() + eu_.arc_start_[e], eu_.arcs_.data() + eu_.arc_start_[e + 1]};
  }

  // Whether some point of edge e's arcs (circle c) is within `radius` of x.
  bool near_arcs(Index e, const Circle& c, const Vec3& x, double radius) const {
    const std::span<const Arc> set = edge_arcs(e);
    const ArcEnds* ends = eu_.arc_ends_.data() + eu_.arc_start_[e];
    const Vec3 y = x - c.o;
    const double z = dot(y, c.w);
    const Vec3 perp = y - z * c.w;
    const double a = dot(perp, c.e1), b = dot(perp, c.e2);
    const double s = std::sqrt(a * a + b * b);
    // The circle's point nearest to x, when on an arc (or x on the axis: all are).
    if (s <= tol_ || contains(set, ends, a, b)) return c.squared_distance(s, z) < radius * radius;
    // Else an arc's end.
    for (std::size_t k = 0; k < set.size(); ++k)
      for (const auto& [cs, sn] : {std::pair{ends[k].cos_begin, ends[k].sin_begin}, {ends[k].cos_end, ends[k].sin_end}}) {
        const Vec3 d = y - c.rho * (cs * c.e1 + sn * c.e2);
        if (dot(d, d) < radius * radius) return true;
      }
    return false;
  }

  // Whether clear() can find circle c (of edge e) at a point within
  // radius - r of x: through a point of its arcs nearer than r to that
  // point, or, for a circle smaller than r, through its axis.
  bool circle_near(Index e, const Circle& c, const Vec3& x, double radius) const {
    return c.squared_distance(x) < radius * radius && (c.rho < r_ + tol_ || near_arcs(e, c, x, radius));
  }

  // Whether a point within `reach` of x can be inside ball b.
  bool ball_near(const Hood::Ball& b, const Vec3& x, double reach) const {
    return norm(b.c - x) < b.radius + reach + tol_;
  }

  // Into h, what clear() can find or be inside at points within `reach`
  // of `center`.
  void gather(const Vec3& center, double reach, Hood& h) const {
    const double radius = reach + r_ + tol_;
    h.balls.clear();
    h.circles.clear();
    h.arc_bounds.clear();
    h.vertices.clear();
    h.buried.clear();
    h.last = {};
    h.inside = false;
    // Balls whose sphere is within radius: the ends of the circles.
    // Buried balls are left out of the pieces (a point inside one is
    // inside another, up to rounding), kept apart for nearest().
    std::vector<Index>& ids = ids_;
    ids.clear();
    eu_.ball_grid_.visit(center, radius + eu_.max_radius_, [&](Index k) {
      if (norm(t_.point(k) - center) >= std::sqrt(t_.weight(k)) + radius) return;
      if (eu_.balls_->ball_areas()[k] > 0)
        ids.push_back(k);
      else if (buried_near(t_.point(k), t_.weight(k), center, reach))
        h.buried.emplace_back(t_.point(k), t_.weight(k));
    });
    std::sort(ids.begin(), ids.end());
    for (Index k : ids) {
      const Hood::Ball b{t_.point(k), std::sqrt(t_.weight(k)), t_.weight(k), k, kNoCover};
      if (ball_near(b, center, reach)) h.balls.push_back(b);
    }
    for (Index k : ids)
      for (std::size_t j = eu_.circle_start_[k]; j < eu_.circle_start_[k + 1]; ++j) {
        const Index e = eu_.circle_edges_[j];
        const auto& v = s_.edge(e);
        if (!std::binary_search(ids.begin(), ids.end(), v[1])) continue;
        // clear() finds a circle through a point of its arcs (see clear).
        const auto& [m, b] = eu_.arc_bounds_[eu_.arc_start_[e]];
        if (dot(center - m, center - m) >= (radius + b + tol_) * (radius + b + tol_)) continue;
        const Circle c = circle_of(t_, v);
        if (!circle_near(e, c, center, radius)) continue;
        h.circles.emplace_back(e, c);
        h.arc_bounds.push_back(eu_.arc_bounds_[eu_.arc_start_[e]]);
      }
    eu_.vertex_grid_.visit(center, radius, [&](Index v) {
      if (norm(eu_.vertices_[v].p - center) < radius) h.vertices.push_back(v);
    });
    std::sort(h.vertices.begin(), h.vertices.end());
  }

  // Whether a buried ball (centre c, squared radius w) is kept for the
  // points within reach of center: nearest() asks whether they are inside.
  bool buried_near(const Vec3& c, double w, const Vec3& center, double reach) const {
    return norm(c - center) < std::sqrt(w) + reach + tol_;
  }

  // Into `out`, what of h (gathered for a wider reach) clear() can find or
  // be inside at points within `reach` of x tested at distances t up to
  // `within` (at most r), in h's order.
  void narrow(const Hood& h, const Vec3& x, double reach, Hood& out) const { narrow(h, x, reach, r_, out); }
  void narrow(const Hood& h, const Vec3& x, double reach, double within, Hood& out) const {
    const double radius = reach + within + 2 * tol_;
    out.start_part_of(h);
    for (const Hood::Ball& b : h.balls)
      if (ball_near(b, x, reach)) out.balls.push_back(b);
    for (std::size_t k = 0; k < h.circles.size(); ++k) {
      // clear() finds a circle through a point of its arcs (see clear).
      const auto& [m, b] = h.arc_bounds[k];
      if (dot(x - m, x - m) >= (radius + b + tol_) * (radius + b + tol_)) continue;
      if (circle_near(h.circles[k].first, h.circles[k].second, x, radius)) {
        out.circles.push_back(h.circles[k]);
        out.arc_bounds.push_back(h.arc_bounds[k]);
      }
    }
    for (const std::size_t v : h.vertices)
      if (norm(eu_.vertices_[v].p - x) < radius) out.vertices.push_back(v);
  }

  // Into `out`, what of h clear() can find or be inside at points
  // x = q + r u tested at distance r, u in a set of unit directions, in
  // h's order. along(d): the least and largest u.d over the set; the
  // points lie within `radius` of `mid`; reaches(k): whether circle k of h
  // can be found there, once its arcs' ball is within reach. Left out by
  // these bounds (with tol_ to spare for rounding): vertices and circles
  // out of clear()'s reach everywhere, balls holding no point, and balls
  // holding every point r deep (no point of them is found; they put every
  // x in the union: out.inside). A vertex within r + tol_ of x is kept (a
  // cone's coincident vertices, see clear).
  template <class Along, class Reaches>
  void keep_at_r(const Hood& h, const Vec3& q, const Along& along, const Vec3& mid, double radius,
                 const Reaches& reaches, Hood& out) const {
    // |x - y|^2 = |y - q|^2 + r^2 - 2 r u.(y - q).
    const auto squared_range = [&](const Vec3& y) {
      const Vec3 d = y - q;
      const auto [least, most] = along(d);
      const double base = dot(d, d) + r_ * r_;
      return std::pair{base - 2 * r_ * most, base - 2 * r_ * least};
    };
    // First whether y is further than `reach` from every point.
    const auto beyond = [&](const Vec3& y, double reach) {
      const double d = radius + reach;
      return dot(y - mid, y - mid) >= d * d;
    };
    out.start_part_of(h);
    for (const Hood::Ball& b : h.balls) {
      if (beyond(b.c, b.radius + tol_)) continue;
      const auto [least, most] = squared_range(b.c);
      if (least >= (b.radius + tol_) * (b.radius + tol_)) continue;  // never inside
      if (b.radius >= r_ && most <= (b.radius - r_) * (b.radius - r_)) {  // inside, deeper than clear() looks
        out.inside = true;
        continue;
      }
      out.balls.push_back(b);
    }
    for (std::size_t k = 0; k < h.circles.size(); ++k) {
      const auto& [m, b] = h.arc_bounds[k];
      const double reach = r_ + b + 4 * tol_;
      if (beyond(m, reach) || squared_range(m).first >= reach * reach || !reaches(k)) continue;
      out.circles.push_back(h.circles[k]);
      out.arc_bounds.push_back(h.arc_bounds[k]);
    }
    const double vertex_reach = r_ + 2 * tol_;
    for (const std::size_t v : h.vertices) {
      const Vec3& p = eu_.vertices_[v].p;
      if (!beyond(p, vertex_reach) && squared_range(p).first < vertex_reach * vertex_reach) out.vertices.push_back(v);
    }
  }

  // keep_at_r for an arc piece's row: x = q + r (cos psi e1 + sin psi e2),
  // psi in [lo, hi] (less than half a turn; ends: cos lo, sin lo, cos hi,
  // sin hi, the same for every row of a piece).
  void keep_at_r(const Hood& h, const Vec3& q, const Vec3& e1, const Vec3& e2, const std::array<double, 4>& ends,
                 Hood& out) const {
    const double cl = ends[0], sl = ends[1], ch = ends[2], sh = ends[3];  // not a binding: lambdas use them
    // The least and largest a cos psi + b sin psi: towards (a, b) and away
    // from it when the arc holds those directions, else at an end (the
    // square root only then).
    const auto wave = [&](double a, double b) {
      const double at_lo = a * cl + b * sl, at_hi = a * ch + b * sh;
      const double after_lo = cl * b - sl * a, before_hi = a * sh - b * ch;
      const bool away = after_lo <= 0 && before_hi <= 0, towards = after_lo >= 0 && before_hi >= 0;
      const double s = away || towards ? std::sqrt(a * a + b * b) : 0;
      return std::pair{away ? -s : std::min(at_lo, at_hi), towards ? s : std::max(at_lo, at_hi)};
    };
    // The points lie within half the chord of its midpoint.
    const Vec3 from = cl * e1 + sl * e2, to = ch * e1 + sh * e2;
    keep_at_r(
        h, q, [&](const Vec3& d) { return wave(dot(d, e1), dot(d, e2)); }, q + (r_ / 2) * (from + to),
        r_ / 2 * norm(to - from) + tol_,
        [&](std::size_t k) { return arcs_reach(h.circles[k].first, h.circles[k].second, q, e1, e2, wave); }, out);
  }

  // keep_at_r for a cone's points at r: u in the cap of directions within
  // the angle acos(cos_cap) < pi / 2 of the unit `axis`.
  void keep_at_r(const Hood& h, const Vec3& p, const Vec3& axis, double cos_cap, Hood& out) const {
    const double sin_cap = std::sqrt((1 - cos_cap) * (1 + cos_cap));
    // u.d = |d| cos(angle to d): largest at the angle nearest axis' to d,
    // least at the furthest.
    const auto along = [&](const Vec3& d) {
      const double length = norm(d), c = dot(axis, d), s = norm(cross(axis, d));
      return std::pair{-c >= length * cos_cap ? -length : c * cos_cap - s * sin_cap,
                       c >= length * cos_cap ? length : c * cos_cap + s * sin_cap};
    };
    keep_at_r(h, p, along, p + (r_ * cos_cap) * axis, r_ * sin_cap + tol_, [](std::size_t) { return true; }, out);
  }

  // Whether clear() can find circle c (edge e) from a point of keep_at_r's
  // arc (x = q + r (cos psi e1 + sin psi e2); wave(a, b): the range of
  // a cos psi + b sin psi over it): only where x's direction about the
  // axis, from the projection (px, py) of x in c's frame, is on an arc.
  // That needs both sides of an arc up to half a turn ahead (one of a
  // longer one) to be >= 0 somewhere; they are linear in (px, py), so of
  // the form k + a cos psi + b sin psi. Where every one is below -tol_,
  // (px, py) is also further than tol_ from the axis.
  template <class Wave>
  bool arcs_reach(Index e, const Circle& c, const Vec3& q, const Vec3& e1, const Vec3& e2, const Wave& wave) const {
    const std::span<const Arc> set = edge_arcs(e);
    const ArcEnds* ends = eu_.arc_ends_.data() + eu_.arc_start_[e];
    const Vec3 d = q - c.o;
    const double px = dot(d, c.e1), py = dot(d, c.e2);
    const double ax = r_ * dot(e1, c.e1), bx = r_ * dot(e2, c.e1), ay = r_ * dot(e1, c.e2), by = r_ * dot(e2, c.e2);
    // The largest cos_s py - sin_s px (s = 1) or px sin_s - py cos_s (s = -1).
    const auto most = [&](double cs, double sn, double side) {
      return side * (cs * py - sn * px) + wave(side * (cs * ay - sn * ax), side * (cs * by - sn * bx)).second;
    };
    for (std::size_t k = 0; k < set.size(); ++k) {
      if (full(set[k])) return true;
      const bool after_begin = most(ends[k].cos_begin, ends[k].sin_begin, 1) >= -tol_;
      const bool before_end = most(ends[k].cos_end, ends[k].sin_end, -1) >= -tol_;
      if (set[k].length <= kPi ? after_begin && before_end : after_begin || before_end) return true;
    }
    return false;
  }

  // Whether p, a point of sphere k, lies on the union's boundary: in k's
  // power cell, i.e. in no ball of a neighbour of k.
  // `cover`: a neighbour to try first, set to the one found covering p
  // (the same neighbour covers the nearby points a piece tests in turn).
  bool on_boundary(Index k, const Vec3& p, std::size_t& cover) const {
    const auto covers = [&](const Cover& m) {
      const Vec3 d = p - m.c;
      return dot(d, d) < m.limit;
    };
    if (cover != kNoCover && covers(eu_.covers_[cover])) return false;
    for (std::size_t m = eu_.cover_start_[k]; m < eu_.cover_start_[k + 1]; ++m)
      if (covers(eu_.covers_[m])) {
        cover = m;
        return false;
      }
    return true;
  }

  // Whether direction d from vertex v lies in its normal cone (spanned by
  // the directions to its triangle's three centers).
  bool in_cone(std::size_t v, const Vec3& d) const {
    const Vertex& vx = eu_.vertices_[v];
    const auto tri = s_.triangle(vx.triangle);
    const Vec3 a = t_.point(tri[0]) - vx.p, b = t_.point(tri[1]) - vx.p, c = t_.point(tri[2]) - vx.p;
    const double whole = dot(a, cross(b, c));
    return dot(d, cross(b, c)) * whole >= 0 && dot(a, cross(d, c)) * whole >= 0 && dot(a, cross(b, d)) * whole >= 0;
  }

  // Whether the point of ball b's sphere nearest to x is nearer than
  // `limit` and on the boundary; `inside`: whether x is in b.
  bool ball_finds(const Hood::Ball& b, const Vec3& x, double limit, bool& inside) const {
    const Vec3 d = x - b.c;
    const double dd = dot(d, d);
    inside = !(dd >= b.radius_sq);
    if (!inside) return false;
    const double deep = b.radius - limit;  // x is nearer than limit to the sphere beyond this
    if ((deep > 0 && dd <= deep * deep) || dd == 0) return false;
    return on_boundary(b.id, b.c + (b.radius / std::sqrt(dd)) * d, b.cover);
  }

  // Whether a point of circle c's arcs (edge e) is nearer to x than `limit`.
  bool circle_finds(Index e, const Circle& c, const Vec3& x, double limit, double limit_sq) const {
    const Vec3 y = x - c.o;
    const double z = dot(y, c.w);
    if (std::fabs(z) >= limit) return false;
    const Vec3 perp = y - z * c.w;
    const double s = std::sqrt(dot(perp, perp));
    if (c.squared_distance(s, z) >= limit_sq) return false;
    // On the axis: all its points equally near.
    return s <= tol_ || contains(edge_arcs(e), eu_.arc_ends_.data() + eu_.arc_start_[e], dot(perp, c.e1), dot(perp, c.e2));
  }

  // Whether what `n` names in h is a point of F nearer to x than `limit`
  // (then clear() answers false: it finds n or an earlier one, or x is
  // outside the union).
  bool finds(const Hood& h, const Nearer& n, const Vec3& x, double limit, double limit_sq) const {
    bool inside;
    switch (n.kind) {
      case Nearer::kBall: return ball_finds(h.balls[n.which], x, limit, inside);
      case Nearer::kCircle: return circle_finds(h.circles[n.which].first, h.circles[n.which].second, x, limit, limit_sq);
      case Nearer::kVertex: {
        const Vec3 d = x - eu_.vertices_[h.vertices[n.which]].p;
        return dot(d, d) < limit_sq;
      }
      case Nearer::kNone: break;
    }
    return false;
  }

  // Whether no point of F (outside the union) is nearer to x than t, up to
  // the tolerance; if one is, `nearer` tells which. `self`: the vertex
  // whose piece x is tested for (or vertices_.size()), which keeps
  // directions shared with a coincident vertex of smaller index out.
  // Without `nearer` only the answer counts: the point h found last is
  // tried first (nearby tests are mostly cut off by the same point).
  bool clear(const Hood& h, const Vec3& x, double t, std::size_t self, Nearer* nearer = nullptr) const {
    const double limit = t - tol_;
    if (limit <= 0) return true;
    const double limit_sq = limit * limit;
    if (!nearer && finds(h, h.last, x, limit, limit_sq)) return false;
    const auto found = [&](Nearer::Kind kind, std::size_t which) {
      if (nearer) *nearer = {kind, which};
      if (kind != Nearer::kNone) h.last = {kind, which};
      return false;
    };
    bool in_union = h.inside;
    for (std::size_t k = 0; k < h.balls.size(); ++k) {
      bool inside;
      if (ball_finds(h.balls[k], x, limit, inside)) return found(Nearer::kBall, k);
      in_union = in_union || inside;
    }
    if (!in_union) return found(Nearer::kNone, 0);
    for (std::size_t k = 0; k < h.circles.size(); ++k) {
      // Only a circle with an arc point nearer than limit can be found
      // (up to 2 tol_ when x is on its axis): most are further.
      const auto& [m, b] = h.arc_bounds[k];
      const double reach = limit + b + 4 * tol_;
      if (dot(x - m, x - m) >= reach * reach) continue;
      if (circle_finds(h.circles[k].first, h.circles[k].second, x, limit, limit_sq)) return found(Nearer::kCircle, k);
    }
    const bool is_vertex = self < eu_.vertices_.size();
    for (std::size_t k = 0; k < h.vertices.size(); ++k) {
      const std::size_t v = h.vertices[k];
      const Vec3 d = x - eu_.vertices_[v].p;
      if (dot(d, d) < limit_sq) return found(Nearer::kVertex, k);
      if (is_vertex && v < self && norm(d) < t + tol_ && norm(eu_.vertices_[v].p - eu_.vertices_[self].p) <= tol_ &&
          in_cone(v, d))
        return found(Nearer::kNone, 0);
    }
    return true;
  }

  // Where the ray q + t u meets the bisector of q and the point of F found
  // nearer (its distance to q + t u equals t, for a circle's point up to
  // kCutPrecision), if
  // in (0, hi): the ray's cut when that point stays the nearer one.
  double crossing(const Hood& h, const Nearer& nearer, const Vec3& q, const Vec3& u, double hi) const {
    double t = -1;
    if (nearer.kind == Nearer::kBall) {  // |q + t u - c| = R - t
      const Hood::Ball& b = h.balls[nearer.which];
      const double den = 2 * (dot(u, b.c - q) - b.radius);
      if (den > 0) t = (dot(q - b.c, q - b.c) - b.radius_sq) / den;
    } else if (nearer.kind == Nearer::kVertex) {  // |q + t u - p| = t
      const Vec3 p = eu_.vertices_[h.vertices[nearer.which]].p;
      const double den = 2 * dot(u, p - q);
      if (den > 0) t = dot(q - p, q - p) / den;
    } else if (nearer.kind == Nearer::kCircle) {  // distance to the circle - t decreases along the ray
      const Circle& c = h.circles[nearer.which].second;
      t = reach_end([&](double m) { return c.squared_distance(q + m * u); }, 0, 0, hi, kCutPrecision * r_);
    }
    return t < hi ? t : -1;
  }

  // The cut distance tau(q, u), at most r: where the nearer point found
  // says, when the test confirms it (clear there, not just beyond), else by
  // bisection on the test.
  // `at_r`: a part of h (in h's order) holding all that clear() can find
  // at q + r u, which answers the test there (mostly a scan up to the point
  // found) from fewer pieces.
  double cut(const Hood& h, const Vec3& q, const Vec3& u, std::size_t self, const Hood* at_r = nullptr) const {
    Nearer nearer;
    if (at_r && at_r != &h) {
      // The first point found in the part is the first in h (h's order):
      // its index in h.
      if (clear(*at_r, q + r_ * u, r_, self, &nearer)) return r_;
      if (!index_in(h, *at_r, nearer) && clear(h, q + r_ * u, r_, self, &nearer)) return r_;
      if (nearer.kind != Nearer::kNone) h.last = nearer;
    } else if (clear(h, q + r_ * u, r_, self, &nearer)) {
      return r_;
    }
    double lo = 0, hi = r_;
    // The test holds on an initial segment of the ray (a point of F nearer
    // to q + t u than t is nearer to q + t' u than t' for t' > t): it holds
    // up to clear_to, tested there, and not from cut_from on.
    double clear_to = lo, cut_from = hi;
    // Below a thousand tolerances the test's answers are rounding noise.
    for (int tries = 0; tries < 4; ++tries) {
      const double t = crossing(h, nearer, q, u, hi);
      if (t <= std::max(lo, 1e3 * tol_)) break;
      if (!clear(h, q + t * u, t, self, &nearer)) {
        hi = cut_from = t;  // cut before: try the point found there
        continue;
      }
      lo = t;
      const double beyond = std::min(hi, t + kCutPrecision * r_);
      if (!clear(h, q + beyond * u, beyond, self)) return t;
      clear_to = t;
      break;
    }
    // The point found last mostly ends the segment where the tolerance
    // lets clear() find it: the tests just before and after that bracket
    // the change, and the bisection's other answers are known (the same
    // points tested, the same tau). Near a change the test can be rounding
    // noise (where a circle's arc ends, at a cone's coincident vertices:
    // not monotone within 1e-8 r), so a bracket's test there can answer
    // otherwise than the bisection's nearby one: tau then moves by less
    // than that noise (on pockets-train, 1 or 2 rays in 13 of 173 chains).
    if (const double s = found_from(h, nearer, q, u, std::max(clear_to, 1e3 * tol_), cut_from);
        s > 0 && !coincident(h, self))
      for (const double x : {s - kBracket * r_, s + kBracket * r_})
        if (x > clear_to && x < cut_from) (clear(h, q + x * u, x, self) ? clear_to : cut_from) = x;
    // The bisection tests points of [lo, hi] on the ray at distances up to
    // hi: once that is short, against the part of h near it (the answers
    // are h's: the rest of h is not found there).
    const Hood* near = &h;
    for (int step = 0; hi - lo > kCutPrecision * r_; ++step) {
      const double mid = (lo + hi) / 2;
      bool holds = mid <= clear_to;
      if (!holds && mid < cut_from) {
        // (Worth it only while a bracket leaves many tests: 2^8 halvings.)
        if (step >= kCutNarrowAfter && near == &h && cut_from - clear_to > 256 * kCutPrecision * r_) {
          narrow(h, q + ((lo + hi) / 2) * u, (hi - lo) / 2 + tol_, hi, segment_);
          near = &segment_;
        }
        holds = clear(*near, q + mid * u, mid, self);
        (holds ? clear_to : cut_from) = mid;
      }
      (holds ? lo : hi) = mid;
    }
    return lo;
  }

  // Whether h holds a vertex of smaller index at vertex `self`'s point
  // (clear()'s test of those is rounding noise along a ray from there).
  bool coincident(const Hood& h, std::size_t self) const {
    if (self >= eu_.vertices_.size()) return false;
    for (const std::size_t v : h.vertices)
      if (v < self && norm(eu_.vertices_[v].p - eu_.vertices_[self].p) <= tol_) return true;
    return false;
  }

  // Where clear() starts to find `nearer` (a vertex, or a circle's point
  // whose arc holds it) on the ray q + t u, in (lo, hi), if its test there
  // changes by far more than rounding between kBracket r before and after
  // (the change is then where it says): its squared distance less
  // (t - tol)^2, which only decreases along the ray (the distance less t
  // does); else -1.
  double found_from(const Hood& h, const Nearer& nearer, const Vec3& q, const Vec3& u, double lo, double hi) const {
    if (nearer.kind != Nearer::kVertex && nearer.kind != Nearer::kCircle) return -1;
    const auto squared_distance = [&](double t) {
      const Vec3 x = q + t * u;
      if (nearer.kind == Nearer::kCircle) return h.circles[nearer.which].second.squared_distance(x);
      const Vec3 d = x - eu_.vertices_[h.vertices[nearer.which]].p;
      return dot(d, d);
    };
    const auto margin = [&](double t) { return squared_distance(t) - (t - tol_) * (t - tol_); };
    const double t = reach_end(squared_distance, tol_, lo, hi, 1e-3 * kBracket * r_);
    const double d = kBracket * r_, sure = 1e-12 * r_ * r_;
    return t - d > lo + kCutPrecision * r_ && t + d < hi && margin(t - d) > sure && margin(t + d) < -sure ? t : -1;
  }

  // The toroidal piece of circle c for phi in [begin, end].
  // all_clear: whether every node saw the eroded surface (closed forms).
  LayerShare arc_piece(const Hood& h, const Circle& c, double begin, double end, bool& all_clear) const {
    const double psi_i = std::atan2(c.z_i, c.rho), psi_j = std::atan2(c.z_j, c.rho);
    const std::size_t none = eu_.vertices_.size();
    // Each node phi's points are within r of its circle point q: tested
    // against the part of the hood near q (its row). Those at r lie on an
    // arc about q, psi from psi_i to psi_j (less than half a turn), tested
    // against what can be found from that arc (keep_at_r).
    const auto clear_at_r = [&](const Hood& near, const Vec3& radial, double psi) {
      return clear(near, c.o + c.rho * radial + r_ * c.ray(radial, psi), r_, none);
    };
    // The rows' circle points and the nodes' directions about them, each
    // computed once (the same values as computed in place).
    std::array<Vec3, 8> radials;
    std::array<double, 8> cos_psi, sin_psi;
    for (int k = 0; k < 8; ++k) {
      radials[k] = c.radial(node(begin, end, k));
      const double psi = node(psi_i, psi_j, k);
      cos_psi[k] = std::cos(psi);
      sin_psi[k] = std::sin(psi);
    }
    const std::array<double, 4> ends{std::cos(psi_i), std::sin(psi_i), std::cos(psi_j), std::sin(psi_j)};
    std::array<std::array<bool, 8>, 8> at_r;
    all_clear = true;
    for (int i = 0; i < 8; ++i) {
      const Vec3& radial = radials[i];
      const Vec3 q = c.o + c.rho * radial;
      keep_at_r(h, q, (-1.0) * radial, c.w, ends, at_r_[i]);
      for (int j = 0; j < 8; ++j)
        all_clear = (at_r[i][j] = clear(at_r_[i], q + r_ * c.ray(radial, cos_psi[j], sin_psi[j]), r_, none)) && all_clear;
    }
    if (all_clear)
      return {(end - begin) * wedge_volume(c.rho, r_, psi_i, psi_j), (end - begin) * wedge_area(c.rho, r_, psi_i, psi_j)};
    for (int i = 0; i < 8; ++i) narrow(h, c.o + c.rho * radials[i], r_, rows_[i]);
    // Per phi, psi in pieces where the eroded surface is there (closed
    // forms) or cut off (the rays' volumes up to tau).
    LayerShare out;
    for (int i = 0; i < 8; ++i) {
      const double w = weight(begin, end, i);
      const Vec3& radial = radials[i];
      const Vec3 q = c.o + c.rho * radial;
      // A change between two nodes is located among the points at r
      // between them: against the part of the row's hood near their arc.
      const Hood* near = &at_r_[i];
      const auto between = [&](double lo, double hi) {
        const Vec3 a = c.ray(radial, lo), b = c.ray(radial, hi);
        narrow(at_r_[i], q + (r_ / 2) * (a + b), r_ / 2 * norm(b - a) + tol_, segment_);
        near = &segment_;
      };
      for (const Segment& g :
           segments(psi_i, psi_j, at_r[i], [&](double psi) { return clear_at_r(*near, radial, psi); }, between)) {
        if (g.holds) {
          out.volume += w * wedge_volume(c.rho, r_, g.lo, g.hi);
          out.area += w * wedge_area(c.rho, r_, g.lo, g.hi);
          continue;
        }
        // A segment of the whole row has the rows' nodes.
        const bool whole = g.lo == psi_i && g.hi == psi_j;
        for (int j = 0; j < 8; ++j) {
          const double psi = node(g.lo, g.hi, j), cs = whole ? cos_psi[j] : std::cos(psi);
          const Vec3 u = c.ray(radial, cs, whole ? sin_psi[j] : std::sin(psi));
          out.volume += w * weight(g.lo, g.hi, j) * ray_volume(c.rho, cs, cut(rows_[i], q, u, none, &at_r_[i]));
        }
      }
    }
    return out;
  }
};

}  // namespace alpha
