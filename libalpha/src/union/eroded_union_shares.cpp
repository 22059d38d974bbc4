// SPDX-License-Identifier: Apache-2.0
// ErodedUnion's per-atom split (layer(per_ball)): every point of the layer
// and of the eroded surface goes to the power cell holding it. Apart from
// eroded_union.cpp so that the totals' code is compiled as alone.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "union/eroded_union_integrator.hpp"

namespace alpha {
namespace {

// Where a surface point's power cell changes between two nodes: to 1/4096
// of their gap (the area's integrand jumps there).
constexpr int kCellBisections = 12;

double total_length(const std::vector<Arc>& set) {
  double sum = 0;
  for (const Arc& a : set) sum += a.length;
  return sum;
}

// The ray q + t u, t in [0, tau], cut where its power cell among `sites`
// changes (power differences are linear in t: the lower envelope of lines
// a_m + b_m t): piece(id, t0, t1) for each part in order. Returns the cell
// at tau. At t = 0 (q on the spheres of the piece's balls, powers 0 up to
// rounding) the cell is the one the ray enters.
template <class Piece>
Index ray_cells(std::span<const Site> sites, const Vec3& q, const Vec3& u, double tau, double start, Piece piece) {
  const auto a = [&](const Site& m) { return dot(q - m.p, q - m.p) - m.w; };
  const auto b = [&](const Site& m) { return 2 * dot(u, q - m.p); };
  std::size_t cur = 0;
  double least = a(sites[0]) + b(sites[0]) * start;
  for (std::size_t m = 1; m < sites.size(); ++m) {
    const double x = a(sites[m]) + b(sites[m]) * start;
    if (x < least) cur = m, least = x;
  }
  double t = 0;
  for (;;) {
    const double a_cur = a(sites[cur]), b_cur = b(sites[cur]);
    std::size_t next = cur;
    double next_t = tau, next_b = b_cur;
    for (std::size_t m = 0; m < sites.size(); ++m) {
      const double bm = b(sites[m]);
      if (!(bm < b_cur)) continue;
      const double x = std::max(t, (a(sites[m]) - a_cur) / (b_cur - bm));
      if (x < next_t || (x == next_t && next != cur && bm < next_b)) next = m, next_t = x, next_b = bm;
    }
    if (next == cur) {
      piece(sites[cur].id, t, tau);
      return sites[cur].id;
    }
    if (next_t > t) piece(sites[cur].id, t, next_t);
    t = next_t;
    cur = next;
  }
}

// The convex polygon `poly` (points of a plane) where dot(g, y) <= h.
std::vector<Vec3> clip_polygon(const std::vector<Vec3>& poly, const Vec3& g, double h) {
  std::vector<Vec3> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec3 &y0 = poly[k], &y1 = poly[(k + 1) % poly.size()];
    const double f0 = dot(g, y0) - h, f1 = dot(g, y1) - h;
    if (f0 <= 0) out.push_back(y0);
    if ((f0 < 0 && f1 > 0) || (f0 > 0 && f1 < 0)) out.push_back(y0 + (f0 / (f0 - f1)) * (y1 - y0));
  }
  return out;
}

}  // namespace

// The piece's total split in the proportions of `s` (by volume where no
// node saw its surface; to `fallback` where no node saw the piece): the
// parts sum to the total up to rounding.
void ErodedUnion::Integrator::add_scaled(const PieceShares& s, const LayerShare& total, Index fallback,
                                         std::vector<LayerShare>& per_ball) {
  double volume = 0, area = 0;
  for (const auto& [k, x] : s.parts) {
    volume += x.volume;
    area += x.area;
  }
  if (!(volume > 0)) {
    per_ball[fallback].volume += total.volume;
    per_ball[fallback].area += total.area;
    return;
  }
  for (const auto& [k, x] : s.parts) {
    per_ball[k].volume += total.volume * (x.volume / volume);
    per_ball[k].area += total.area * (area > 0 ? x.area / area : x.volume / volume);
  }
}

// The sites that can hold a point within `radius` of `center`: those not
// of more power than one of the piece's balls (`owners`) all over that
// ball (power differences are linear: least at the ball's rim).
std::vector<Site> ErodedUnion::Integrator::near_sites(std::span<const Site> sites, std::span<const Index> owners,
                                                      const Vec3& center, double radius) {
  std::vector<Site> out;
  for (const Site& m : sites) {
    bool dominated = false;
    for (const Site& a : sites)
      if (a.id != m.id && std::find(owners.begin(), owners.end(), a.id) != owners.end()) {
        const double at_center = (dot(center - m.p, center - m.p) - m.w) - (dot(center - a.p, center - a.p) - a.w);
        dominated = dominated || at_center - 2 * radius * norm(a.p - m.p) > 1e-9 * (1 + std::fabs(at_center));
      }
    if (!dominated) out.push_back(m);
  }
  return out;
}

// The balls of `balls` and their neighbours as power sites, by id.
std::vector<Site> ErodedUnion::Integrator::sites_near(std::span<const Index> balls) const {
  std::vector<Index> ids(balls.begin(), balls.end());
  for (Index k : balls)
    for (Index e : s_.vertex_edges(k)) ids.push_back(s_.edge(e)[0] == k ? s_.edge(e)[1] : s_.edge(e)[0]);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<Site> out;
  for (Index k : ids) out.push_back({t_.point(k), t_.weight(k), k});
  return out;
}

// Splits the ray q + t u, t in [0, tau], by power cell: its volume
// (integrand's antiderivative G, times w) per cell, and the surface's area
// element `area` (0 where the surface is cut off) to the cell at its end.
template <class G>
void ErodedUnion::Integrator::split_ray(std::span<const Site> sites, const Vec3& q, const Vec3& u, double tau, double w,
                                        double area, G g, PieceShares& out) const {
  const Index end = ray_cells(sites, q, u, tau, 1e-6 * r_,
                              [&](Index id, double t0, double t1) { out.add(id, w * (g(t1) - g(t0)), 0); });
  if (area > 0) out.add(end, 0, w * area);
}

// The toroidal piece's rays (see arc_piece) split by power cell, with psi
// cut where the cell a ray enters changes (psi = 0, the radical plane of
// the circle's balls) and where the torus crosses its axis.
void ErodedUnion::Integrator::arc_shares(const Circle& c, double begin, double end, bool all_clear,
                                         std::span<const Site> sites, PieceShares& out) const {
  const double psi_i = std::atan2(c.z_i, c.rho), psi_j = std::atan2(c.z_j, c.rho);
  std::vector<double> cuts{psi_i, psi_j};
  const auto cut_at = [&](double x) {
    if (x > psi_i && x < psi_j) cuts.push_back(x);
  };
  cut_at(0);
  if (c.rho < r_) {
    const double psi0 = std::atan2(std::sqrt((r_ - c.rho) * (r_ + c.rho)), c.rho);
    cut_at(-psi0);
    cut_at(psi0);
  }
  std::sort(cuts.begin(), cuts.end());
  const std::size_t none = eu_.vertices_.size();
  for (int i = 0; i < 8; ++i) {
    const double w = weight(begin, end, i);
    const Vec3 radial = c.radial(node(begin, end, i)), q = c.o + c.rho * radial;
    const auto clear_at_r = [&](double psi) { return clear(at_r_[i], q + r_ * c.ray(radial, psi), r_, none); };
    const auto cell_at_r = [&](double psi) { return end_cell(sites, q, c.ray(radial, psi)); };
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      for (const Segment& g :
           by_cell(node_segments(cuts[k], cuts[k + 1], all_clear, clear_at_r), cell_at_r, sites.size() > 2))
        for (int j = 0; j < 8; ++j) {
          const double psi = node(g.lo, g.hi, j), cs = std::cos(psi);
          const Vec3 u = c.ray(radial, psi);
          const double tau = g.holds ? r_ : cut(rows_[i], q, u, none, &at_r_[i]);
          split_ray(
              sites, q, u, tau, w * weight(g.lo, g.hi, j), g.holds ? std::fabs(c.rho - r_ * cs) * r_ : 0,
              [&](double t) { return ray_volume(c.rho, cs, t); }, out);
        }
  }
}

// The reentrant piece's rays split by power cell: the cone cut by the
// power planes of its three balls (they meet on the vertex's Voronoi
// edge), each part in spherical triangles.
void ErodedUnion::Integrator::cone_shares(std::size_t v, const Hood& hood, bool all_clear, PieceShares& out) const {
  const Vertex& vx = eu_.vertices_[v];
  const auto tri = s_.triangle(vx.triangle);
  const std::vector<Site> sites = near_sites(sites_near(tri), tri, vx.p, r_ + tol_);
  // The triangle of centres, relative to the vertex: central projection
  // maps its points to the cone's directions.
  std::array<Vec3, 3> p;
  std::array<double, 3> power;  // at the vertex (0 up to rounding)
  for (int k = 0; k < 3; ++k) {
    p[k] = t_.point(tri[k]) - vx.p;
    power[k] = dot(p[k], p[k]) - t_.weight(tri[k]);
  }
  for (int m = 0; m < 3; ++m) {
    std::vector<Vec3> poly{p[0], p[1], p[2]};
    for (int n = 0; n < 3; ++n)  // power_m(y) <= power_n(y)
      if (n != m) poly = clip_polygon(poly, 2 * (p[n] - p[m]), power[n] - power[m]);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      const auto unit = [](const Vec3& y) { return (1 / norm(y)) * y; };
      const SphericalTriangle part({unit(poly[0]), unit(poly[k]), unit(poly[k + 1])});
      for (int i = 0; i < 8; ++i) {
        const double s = node(0, 1, i);
        const auto clear_at_r = [&](double sigma) {
          return clear(hood, vx.p + r_ * part.direction(s, sigma, nullptr), r_, v);
        };
        const auto cell_at_r = [&](double sigma) { return end_cell(sites, vx.p, part.direction(s, sigma, nullptr)); };
        for (const Segment& g : by_cell(node_segments(0, 1, all_clear, clear_at_r), cell_at_r, sites.size() > 3))
          for (int j = 0; j < 8; ++j) {
            double jac;
            const Vec3 u = part.direction(s, node(g.lo, g.hi, j), &jac);
            const double tau = g.holds ? r_ : cut(hood, vx.p, u, v);
            split_ray(
                sites, vx.p, u, tau, weight(0, 1, i) * weight(g.lo, g.hi, j) * jac, g.holds ? r_ * r_ : 0,
                [](double t) { return t * t * t / 3; }, out);
          }
      }
    }
  }
}

// The shell under sphere i's patch and its contact patch, per power
// cell: all in i's when p_i is (the cell is convex and holds the patch),
// else the parts beyond the radical planes that pass behind p_i go to
// those neighbours. Moved exactly: the parts sum to the closed forms.
void ErodedUnion::Integrator::shell_shares(Index i, std::vector<LayerShare>& per_ball) const {
  const double patch = eu_.balls_->ball_areas()[i];
  if (patch == 0) return;
  per_ball[i].volume += eu_.shell_factor_[i] * patch;
  per_ball[i].area += eu_.contact_factor_[i] * patch;
  if (r_ == 0) return;
  const Vec3 pi = t_.point(i);
  const double wi = t_.weight(i), radius = std::sqrt(wi);
  struct Neighbour {
    Vec3 d;    // p_m - p_i
    double k;  // |p_m - p_i|^2 - w_m: power_m(p_i + x) = |x|^2 - 2 x.d + k
    Index id;
  };
  std::vector<Neighbour> hood;
  for (Index e : s_.vertex_edges(i)) {
    const Index m = s_.edge(e)[0] == i ? s_.edge(e)[1] : s_.edge(e)[0];
    const Vec3 d = t_.point(m) - pi;
    hood.push_back({d, dot(d, d) - t_.weight(m), m});
  }
  for (const Neighbour& j : hood) {
    const double len = norm(j.d), plane = (wi + j.k) / (2 * len);  // the radical plane, along j.d from p_i
    if (plane >= 0 || plane <= -radius) continue;                  // behind p_i, and the sphere reaching beyond it
    // Frame about j.d: x = p_i + s n, n = z a + sqrt(1 - z^2) (cos phi e1 + sin phi e2).
    const Circle frame = circle_of_axis((1 / len) * j.d);
    // At radius s: the conditions g.n <= h on n for p_i + R n to be on
    // the patch and p_i + s n in j's cell (power_j <= power_m).
    const auto conditions = [&](double s) {
      std::vector<std::pair<Vec3, double>> out;
      for (const Neighbour& m : hood) {
        out.push_back({2 * radius * m.d, wi + m.k});
        if (m.id != j.id) out.push_back({2 * s * (m.d - j.d), m.k - j.k});
      }
      return out;
    };
    // The angle phi of the circle z (of n) where they hold.
    const auto length = [&](const std::vector<std::pair<Vec3, double>>& gh, double z) {
      const double rz = std::sqrt(std::max(0.0, (1 - z) * (1 + z)));
      std::vector<Arc> set{{0, kTwoPi}}, scratch;
      for (const auto& [g, h] : gh) {
        keep_below(set, rz * dot(g, frame.e1), rz * dot(g, frame.e2), h - z * dot(g, frame.w), scratch);
        if (set.empty()) break;
      }
      return total_length(set);
    };
    // Its integral over z where power_j < power_i (z > plane / s), in
    // parts between the z where a condition's circle touches circle z
    // (the length bends there).
    const auto band = [&](double s) {
      const double lo = std::max(-1.0, plane / s), hi = plane / radius;
      const auto gh = conditions(s);
      std::vector<double> cuts{lo, hi};
      for (const auto& [g, h] : gh) {
        const double a = dot(g, frame.w), gg = dot(g, g), b = std::sqrt(std::max(0.0, gg - a * a));
        if (gg < h * h || gg == 0) continue;
        for (const double sign : {-1.0, 1.0}) {
          const double z = (h * a + sign * b * std::sqrt(gg - h * h)) / gg;
          if (z > lo && z < hi) cuts.push_back(z);
        }
      }
      std::sort(cuts.begin(), cuts.end());
      double sum = 0;
      for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
        for (int k = 0; k < 8; ++k) sum += weight(cuts[c], cuts[c + 1], k) * length(gh, node(cuts[c], cuts[c + 1], k));
      return sum;
    };
    // Over s, in parts on each side of s = -plane, where the band reaches z = -1.
    const double inner = radius - r_;
    double volume = 0;
    for (const auto& [lo, hi] :
         {std::pair{inner, std::clamp(-plane, inner, radius)}, {std::clamp(-plane, inner, radius), radius}})
      for (int k = 0; k < 8 && hi > lo; ++k) {
        const double s = node(lo, hi, k);
        volume += weight(lo, hi, k) * s * s * band(s);
      }
    const double area = inner > 0 ? inner * inner * band(inner) : 0;
    per_ball[i].volume -= volume;
    per_ball[i].area -= area;
    per_ball[j.id].volume += volume;
    per_ball[j.id].area += area;
  }
}

// [a, b] in segments where the eroded surface is there or cut off (see
// segments), from the predicate at the 8 nodes; one segment where every
// node of the piece saw it (all_clear).
template <class Predicate>
std::vector<Segment> ErodedUnion::Integrator::node_segments(double a, double b, bool all_clear, Predicate holds) {
  if (all_clear) return {{a, b, true}};
  std::array<bool, 8> at;
  for (int k = 0; k < 8; ++k) at[k] = holds(node(a, b, k));
  return segments(a, b, at, holds);
}

// The segments where the eroded surface is there cut again where the
// power cell of its point (cell_at) changes between nodes: the area's
// integrand jumps there, the volume's bends. Not when only the piece's
// own balls' cells are near (`other_cells` false): the parts are cut
// where theirs meet already.
template <class CellAt>
std::vector<Segment> ErodedUnion::Integrator::by_cell(const std::vector<Segment>& in, CellAt cell_at,
                                                      bool other_cells) {
  if (!other_cells) return in;
  std::vector<Segment> out;
  for (const Segment& g : in) {
    if (!g.holds) {
      out.push_back(g);
      continue;
    }
    double start = g.lo;
    Index before = cell_at(node(g.lo, g.hi, 0));
    for (int k = 0; k < 7; ++k) {
      const Index next = cell_at(node(g.lo, g.hi, k + 1));
      if (next == before) continue;
      const double x = change(
          node(g.lo, g.hi, k), node(g.lo, g.hi, k + 1), true, [&](double y) { return cell_at(y) == before; },
          kCellBisections);
      out.push_back({start, x, true});
      start = x;
      before = next;
    }
    out.push_back({start, g.hi, true});
  }
  return out;
}

// The power cell of the point q + r u.
Index ErodedUnion::Integrator::end_cell(std::span<const Site> sites, const Vec3& q, const Vec3& u) const {
  return ray_cells(sites, q, u, r_, 1e-6 * r_, [](Index, double, double) {});
}

}  // namespace alpha
