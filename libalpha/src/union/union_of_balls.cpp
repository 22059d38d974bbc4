// SPDX-License-Identifier: Apache-2.0
#include "alpha/union_of_balls.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "alpha/error.hpp"
#include "union/ball_in_polyhedron.hpp"
#include "numerics/compensated_sum.hpp"
#include "union/convex_polyhedron.hpp"

namespace alpha {
namespace {

constexpr double kPi = std::numbers::pi;

// A ball relative to the first vertex of its simplex: p is p_v - p_first.
struct Ball {
  Vec3 p;
  double w, r;
};

// Local edges of a triangle and of a tetrahedron, and the two other
// vertices of each edge of a tetrahedron.
constexpr std::array<std::array<int, 2>, 3> kTriangleEdge{{{0, 1}, {0, 2}, {1, 2}}};
constexpr std::array<std::array<int, 2>, 6> kEdge{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
constexpr std::array<std::array<int, 2>, 6> kEdgeOthers{{{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}}};

// Signed distance from the center of ball a to the radical plane of a and b,
// measured towards b (d = |p_b - p_a|).
double radical_offset(const Ball& a, const Ball& b, double d) { return (d * d + a.w - b.w) / (2 * d); }

// The terms of one simplex of K with N = 2, 3 or 4 balls: for each ball,
// the area of its sphere inside all the other balls; for each edge, the
// area of the disc (radical plane inside the balls) where the edge's balls
// have the largest power (the intersection's face in that plane); and the
// volume of the intersection, by the divergence theorem on the pieces of
// the intersection where one ball has the largest power (a piece is bounded
// by that ball's sphere and by faces in radical planes):
//   V = (sum_i r_i area_i - sum_e d_e face_e) / 3.
template <int N>
struct SimplexTerms {
  std::array<double, N> area{};
  std::array<double, N*(N - 1) / 2> face{};
  std::array<double, N*(N - 1) / 2> length{};  // edge lengths
  double volume = 0;

  void finish(const std::array<Ball, N>& b) {
    Sum v;
    for (int i = 0; i < N; ++i) v.add(b[i].r * area[i]);
    for (std::size_t e = 0; e < face.size(); ++e) v.add(-length[e] * face[e]);
    volume = v.value() / 3;
  }
};

// Two balls: the lens. Products of differences of input-sized quantities
// keep thin lenses accurate.
SimplexTerms<2> lens_terms(const std::array<Ball, 2>& b) {
  SimplexTerms<2> t;
  const double d = norm(b[1].p - b[0].p), r0 = b[0].r, r1 = b[1].r;
  const double gap = std::max(0.0, r0 + r1 - d);  // overlap depth
  // Heights of the caps of each sphere inside the other ball.
  const double cap0 = std::clamp(gap * (d + r1 - r0) / (2 * d), 0.0, 2 * r0);
  const double cap1 = std::clamp(gap * (d + r0 - r1) / (2 * d), 0.0, 2 * r1);
  const double a2 = std::max(0.0, gap * (r0 + r1 + d) * (d - r0 + r1) * (d + r0 - r1) / (4 * d * d));
  t.area = {2 * kPi * r0 * cap0, 2 * kPi * r1 * cap1};
  t.face = {kPi * a2};
  t.length = {d};
  t.finish(b);
  return t;
}

// Angle at vertex x of the corner where the three spheres of a triangle
// meet: the angle between the other two spheres' normals seen around x's
// normal at a triple point. The patch of S_x inside the two other balls has
// interior angle pi - this at both of its corners. With g_xy = (w_x + w_y -
// d_xy^2) / 2 = (P - p_x).(P - p_y) at a triple point P, the Binet-Cauchy
// identity gives the cosine part; the sine part is |det(P - p_x, P - p_y,
// P - p_z)| = l |n| (l: height of P over the centers' plane, |n| = twice the
// triangle's area). Both scaled by r_x^2 r_y r_z.
double corner_angle(double wx, double rx, double gxy, double gxz, double gyz, double l_n) {
  return std::atan2(rx * l_n, wx * gyz - gxy * gxz);
}

struct TriangleTerms : SimplexTerms<3> {
  std::array<double, 3> corner{};  // corner_angle at each vertex
};

// Three balls: per sphere, a patch bounded by two circle arcs meeting at the
// two triple points P+-; per radical plane, a circular segment.
TriangleTerms triangle_terms(const std::array<Ball, 3>& b) {
  TriangleTerms t;
  const Vec3 x1 = b[1].p, x2 = b[2].p;  // b[0].p is the origin
  const Vec3 n = cross(x1, x2);
  const double n2 = dot(n, n), nn = std::sqrt(n2);
  // Orthogonal center: 2 c.x_m = |x_m|^2 + w_0 - w_m, c in the centers' plane.
  const double a1 = dot(x1, x1) + b[0].w - b[1].w, a2 = dot(x2, x2) + b[0].w - b[2].w;
  const Vec3 c = (1 / (2 * n2)) * (a1 * cross(x2, n) + a2 * cross(n, x1));
  const double l2 = std::max(0.0, b[0].w - dot(c, c)), l = std::sqrt(l2);  // l2 = -size

  std::array<double, 3> g{}, h0{}, h1{}, phi{};  // per edge (0,1), (0,2), (1,2)
  for (int e = 0; e < 3; ++e) {
    const int x = kTriangleEdge[e][0], y = kTriangleEdge[e][1], z = 3 - x - y;
    const Vec3 xy = b[y].p - b[x].p;
    const double d = norm(xy);
    t.length[e] = d;
    h0[e] = radical_offset(b[x], b[y], d);
    h1[e] = radical_offset(b[y], b[x], d);
    g[e] = b[x].w - h0[e] * d;
    // delta: signed distance in the radical plane from the disc's center to
    // the line of triple points, positive when the center lies where z has
    // the smaller power (inside z's half of the plane).
    const Vec3 center = b[x].p + (h0[e] / d) * xy;
    const double delta = dot(center - c, b[z].p - b[x].p) * d / nn;
    phi[e] = 2 * std::atan2(l, -delta);  // arc of the edge's circle inside B_z
    t.face[e] = (l2 + delta * delta) * phi[e] / 2 + l * delta;  // the segment inside B_z
  }
  for (int x = 0; x < 3; ++x) {
    double turning = 0;
    std::array<double, 2> g_at{};  // g of the two edges at x
    int at = 0, opposite = 0;
    for (int e = 0; e < 3; ++e) {
      const bool first = kTriangleEdge[e][0] == x, second = kTriangleEdge[e][1] == x;
      if (first || second) {
        turning += phi[e] * (first ? h0[e] : h1[e]);
        g_at[at++] = g[e];
      } else {
        opposite = e;
      }
    }
    t.corner[x] = corner_angle(b[x].w, b[x].r, g_at[0], g_at[1], g[opposite], l * nn);
    // Gauss-Bonnet: 2 pi - exterior angles at the two corners - turning of
    // the arcs (cos(theta) * arc angle, with cos(theta) = h / r).
    t.area[x] = b[x].w * (2 * kPi - 2 * t.corner[x]) - b[x].r * turning;
  }
  t.finish(b);
  return t;
}

// Four balls in K: their orthogonal center c has negative power, so each
// piece (where one ball has the largest power) is a cone from c cut by that
// ball: per sphere a patch with three corners (the triple points on the
// cone's edges), per radical plane a disc sector between two rays from c.
// corner[x][k]: corner angle at local vertex x of the triangle opposite
// local vertex k (unused when k == x).
SimplexTerms<4> tetrahedron_terms(const std::array<Ball, 4>& b, const std::array<std::array<double, 4>, 4>& corner) {
  SimplexTerms<4> t;
  const Vec3 x1 = b[1].p, x2 = b[2].p, x3 = b[3].p;
  const double det = dot(x1, cross(x2, x3));
  const double a1 = dot(x1, x1) + b[0].w - b[1].w, a2 = dot(x2, x2) + b[0].w - b[2].w,
               a3 = dot(x3, x3) + b[0].w - b[3].w;
  const Vec3 c = (1 / (2 * det)) * (a1 * cross(x2, x3) + a2 * cross(x3, x1) + a3 * cross(x1, x2));
  const double q = std::max(0.0, b[0].w - dot(c, c));  // -size

  // Unit normal of the face opposite each vertex, pointing to that vertex:
  // the direction of the face's line of triple points into the tetrahedron.
  std::array<Vec3, 4> inward;
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = b[(k + 1) % 4].p;
    Vec3 nk = cross(b[(k + 2) % 4].p - a, b[(k + 3) % 4].p - a);
    if (dot(nk, b[k].p - a) < 0) nk = -1.0 * nk;
    inward[k] = (1 / norm(nk)) * nk;
  }
  std::array<double, 6> phi{}, hx{}, hy{};
  for (int e = 0; e < 6; ++e) {
    const int x = kEdge[e][0], y = kEdge[e][1], o1 = kEdgeOthers[e][0], o2 = kEdgeOthers[e][1];
    const Vec3 xy = b[y].p - b[x].p;
    const double d = norm(xy);
    const Vec3 u = (1 / d) * xy;
    t.length[e] = d;
    hx[e] = radical_offset(b[x], b[y], d);
    hy[e] = radical_offset(b[y], b[x], d);
    Vec3 ev = c - (b[x].p + hx[e] * u);  // from the disc's center to c, in the plane
    ev = ev - dot(ev, u) * u;
    // The sector's rays run from c along the lines of triple points of
    // (x, y, o1) and (x, y, o2), each towards the other vertex's side.
    const Vec3& d1 = inward[o2];
    const Vec3& d2 = inward[o1];
    const Vec3 d12 = cross(d1, d2);
    const Vec3 up = dot(d12, u) >= 0 ? u : -1.0 * u;  // d1 turns to d2 counter-clockwise about up
    const double beta = std::atan2(norm(d12), dot(d1, d2));
    // Where the ray from c along direction dk leaves the circle: at
    // parameter tk; seen from the disc's center, it is turned from dk by
    // asin(Xk / a) = atan2(Xk, rootk), an angle in [-pi/2, pi/2].
    auto exit = [&](const Vec3& dk, double& xk, double& rootk, double& tk) {
      xk = dot(cross(dk, ev), up);
      const double dd = dot(dk, ev);
      rootk = std::sqrt(dd * dd + q);
      tk = dd <= 0 ? rootk - dd : q / (rootk + dd);
    };
    double xk1, root1, t1, xk2, root2, t2;
    exit(d1, xk1, root1, t1);
    exit(d2, xk2, root2, t2);
    phi[e] = beta + std::atan2(xk2 * root1 - xk1 * root2, root1 * root2 + xk1 * xk2);
    const double a_sq = dot(ev, ev) + q;
    // Shoelace about the disc's center: the arc, then the two rays.
    t.face[e] = (a_sq * phi[e] + t2 * xk2 - t1 * xk1) / 2;
  }
  for (int x = 0; x < 4; ++x) {
    double corners = 0, turning = 0;
    for (int k = 0; k < 4; ++k)
      if (k != x) corners += corner[x][k];
    for (int e = 0; e < 6; ++e) {
      if (kEdge[e][0] == x) turning += phi[e] * hx[e];
      if (kEdge[e][1] == x) turning += phi[e] * hy[e];
    }
    t.area[x] = b[x].w * (2 * kPi - corners) - b[x].r * turning;
  }
  t.finish(b);
  return t;
}

}  // namespace

void add_far_points(std::vector<Vec3>& points, std::vector<double>& weights) {
  if (weights.size() != points.size()) fail("add_far_points: one weight per point is needed", ErrorKind::Misuse);
  Vec3 lo = points.empty() ? Vec3{} : points.front(), hi = lo;
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  double max_radius = 0;
  for (double w : weights) max_radius = std::max(max_radius, std::sqrt(std::max(w, 0.0)));
  const Vec3 center = 0.5 * (lo + hi);
  // Every ball lies within reach of the centre; the points are twice as far
  // (and 1 more: a single point ball still gets a tetrahedron of size).
  const double reach = norm(hi - center) + max_radius;
  const double d = 2 * reach + 1;
  for (const Vec3& u : {Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}}) {
    points.push_back(center + d * u);  // |u| = sqrt 3 > 1
    weights.push_back(0);
  }
}

bool UnionOfBalls::in_dual_complex_vertex(Index v) const {
  return complex_->triangulation().status(v) == PointStatus::vertex && complex_->vertex_interval(v).entry < level_;
}

UnionOfBalls::UnionOfBalls(const AlphaComplex& complex) : complex_(&complex), level_(complex.level(0.0)) {
  const Triangulation& t = complex.triangulation();
  const Simplices& s = complex.simplices();
  const std::size_t n = t.num_points();
  radius_.assign(n, 0.0);
  for (Index i = 0; i < n; ++i) {
    const double w = t.weight(i);
    if (!(w >= 0))
      fail("union of balls: point " + std::to_string(i) + " has negative weight " + std::to_string(w),
           ErrorKind::BadInput);
    radius_[i] = std::sqrt(w);
    max_radius_ = std::max(max_radius_, radius_[i]);
  }
  // Area and volume are summed from terms in the fourth and sixth powers
  // of lengths, which leave the doubles' range for balls far from unit
  // size (radii of 1e-99 lost 1 % of the volume): the sums take lengths
  // scaled by a power of two that brings the largest radius near 1, an
  // exact change of unit undone at the end, and 1 for radii in [2^-64,
  // 2^64] (molecules, any practical unit).
  const int exponent = max_radius_ > 0 ? std::ilogb(max_radius_) : 0;
  const double unit = std::abs(exponent) > 64 ? std::ldexp(1.0, -exponent) : 1.0;
  std::vector<double> radius(n), weight(n);
  for (Index i = 0; i < n; ++i) radius[i] = radius_[i] * unit, weight[i] = t.weight(i) * unit * unit;
  // For cell_cover: the balls of K, and each one's neighbours in K.
  balls_ = PointGrid(2 * max_radius_);
  for (Index i = 0; i < n; ++i)
    if (radius_[i] > 0 && in_dual_complex_vertex(i)) balls_.add(t.point(i), i);
  balls_.finish();
  neighbour_start_.assign(n + 1, 0);
  for (Index e = 0; e < s.num_edges(); ++e)
    if (in_dual_complex_edge(e))
      for (Index x : s.edge(e)) ++neighbour_start_[x + 1];
  for (Index i = 0; i < n; ++i) neighbour_start_[i + 1] += neighbour_start_[i];
  neighbours_.resize(neighbour_start_[n]);
  std::vector<Index> next(neighbour_start_.begin(), neighbour_start_.end() - 1);
  for (Index e = 0; e < s.num_edges(); ++e)
    if (in_dual_complex_edge(e)) {
      const auto& ev = s.edge(e);
      neighbours_[next[ev[0]]++] = ev[1];
      neighbours_[next[ev[1]]++] = ev[0];
    }
  // The balls of a simplex relative to its first vertex.
  auto balls = [&]<std::size_t N>(const std::array<Index, N>& v, std::array<Ball, N>& b) {
    for (std::size_t k = 0; k < N; ++k) b[k] = {unit * (t.point(v[k]) - t.point(v[0])), weight[v[k]], radius[v[k]]};
  };

  // The edge joining u and w among a few candidate edge ids.
  auto edge_among = [&](std::span<const Index> candidates, Index u, Index w) {
    const std::array<Index, 2> key{std::min(u, w), std::max(u, w)};
    return *std::find_if(candidates.begin(), candidates.end(),
                         [&](Index e) { return s.edge(e)[0] == key[0] && s.edge(e)[1] == key[1]; });
  };

  // Per ball: the area of its sphere on the boundary; per edge: the area of
  // its power facet inside the balls. Both by inclusion-exclusion over K.
  std::vector<Sum> area(n), facet(s.num_edges());

  for (Index v = 0; v < n; ++v)
    if (in_dual_complex_vertex(v)) area[v].add(4 * kPi * weight[v]);
  // Edges of K whose balls barely touch from outside (their circle's radius
  // a is below 10^-5.5 times the smaller radius, and each sphere's cap in
  // the other ball is at most a hemisphere; balls of radius 0) are left out
  // with all their cofaces: each of those terms lies in the thin lens, of
  // area about 2 pi a^2 < 1e-10 r^2, while the angles of such tiny circles
  // would carry errors of about eps r / a.
  constexpr double kTouching = 1e-11;
  std::vector<char> kept(s.num_edges(), 0);
  for (Index e = 0; e < s.num_edges(); ++e) {
    std::array<Ball, 2> b;
    if (!in_dual_complex_edge(e)) continue;
    balls(s.edge(e), b);
    const SimplexTerms<2> lens = lens_terms(b);
    const bool thin = lens.area[0] <= 2 * kPi * b[0].w && lens.area[1] <= 2 * kPi * b[1].w;
    if (thin && lens.face[0] <= kPi * kTouching * std::min(b[0].w, b[1].w)) continue;
    kept[e] = 1;
    for (int k = 0; k < 2; ++k) area[s.edge(e)[k]].add(-lens.area[k]);
    facet[e].add(lens.face[0]);
  }
  std::vector<std::array<double, 3>> corner(s.num_triangles());  // by triangle(f) order
  for (Index f = 0; f < s.num_triangles(); ++f) {
    std::array<Ball, 3> b;
    const auto& v = s.triangle(f);
    const auto& fe = s.triangle_edges(f);
    if (!in_dual_complex_triangle(f) || !kept[fe[0]] || !kept[fe[1]] || !kept[fe[2]]) continue;
    balls(v, b);
    const TriangleTerms tt = triangle_terms(b);
    for (int k = 0; k < 3; ++k) area[v[k]].add(tt.area[k]);
    for (int e = 0; e < 3; ++e) facet[edge_among(fe, v[kTriangleEdge[e][0]], v[kTriangleEdge[e][1]])].add(-tt.face[e]);
    corner[f] = tt.corner;
  }
  for (Index c = 0; c < t.num_cells(); ++c) {
    std::array<Ball, 4> b;
    const auto& v = t.cell(c).v;
    if (t.is_infinite(c) || !in_dual_complex_cell(c)) continue;
    // Facets 0, 1 and 3 hold all six edges.
    std::array<Index, 9> candidates;
    for (int k : {0, 1, 3})
      std::copy_n(s.triangle_edges(s.cell_triangle(c, k)).begin(), 3, candidates.begin() + (k == 3 ? 6 : 3 * k));
    std::array<Index, 6> ce;
    for (int e = 0; e < 6; ++e) ce[e] = edge_among(candidates, v[kEdge[e][0]], v[kEdge[e][1]]);
    if (std::any_of(ce.begin(), ce.end(), [&](Index e) { return !kept[e]; })) continue;
    balls(v, b);
    std::array<std::array<double, 4>, 4> cell_corner{};
    for (int k = 0; k < 4; ++k) {
      const Index f = s.cell_triangle(c, k);
      for (int j = 0; j < 3; ++j) cell_corner[t.index_of(c, s.triangle(f)[j])][k] = corner[f][j];
    }
    const SimplexTerms<4> tt = tetrahedron_terms(b, cell_corner);
    for (int k = 0; k < 4; ++k) area[v[k]].add(-tt.area[k]);
    for (int e = 0; e < 6; ++e) facet[ce[e]].add(tt.face[e]);
  }

  // Per ball volume (r_i A_i + sum_j h_ij F_ij) / 3: the divergence theorem
  // on B_i & P_i, bounded by its exposed sphere and its facets.
  ball_area_.assign(n, 0.0);
  ball_volume_.assign(n, 0.0);
  std::vector<Sum> volume(n);
  // Values within rounding noise of 0 (a buried sphere, a covered ball)
  // are 0: the terms are at most the sphere's area (ball's volume), a few
  // dozen of them, each with a relative error of a few ulps.
  constexpr double kNoise = 1e-11;
  auto denoised = [&](double x, double whole) { return std::fabs(x) <= kNoise * whole ? 0.0 : x; };
  for (Index i = 0; i < n; ++i) {
    ball_area_[i] = denoised(area[i].value(), 4 * kPi * weight[i]);
    volume[i].add(radius[i] * ball_area_[i]);
  }
  for (Index e = 0; e < s.num_edges(); ++e) {
    const double f = facet[e].value();
    if (f == 0) continue;
    const auto& v = s.edge(e);
    const Ball b0{{}, weight[v[0]], radius[v[0]]}, b1{{}, weight[v[1]], radius[v[1]]};
    const double d = norm(unit * (t.point(v[1]) - t.point(v[0])));
    volume[v[0]].add(radical_offset(b0, b1, d) * f);
    volume[v[1]].add(radical_offset(b1, b0, d) * f);
  }
  Sum total_area, total_volume;
  for (Index i = 0; i < n; ++i) {
    // Back to the input's unit (exact: powers of two, one at a time).
    ball_volume_[i] = denoised(volume[i].value() / 3, 4 * kPi / 3 * weight[i] * radius[i]) / unit / unit / unit;
    ball_area_[i] = ball_area_[i] / unit / unit;
    total_area.add(ball_area_[i]);
    total_volume.add(ball_volume_[i]);
  }
  area_ = total_area.value();
  volume_ = total_volume.value();
}

CellCover UnionOfBalls::cell_cover(Index c) const {
  const Triangulation& t = complex_->triangulation();
  if (t.is_infinite(c)) return {};
  const auto& v = t.cell(c).v;
  std::array<Vec3, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = t.point(v[k]);
  // A flat cell holds nothing measurable (and has no outward sides).
  double longest = 0;
  for (const auto& [x, y] : kEdge) longest = std::max(longest, norm(p[y] - p[x]));
  if (std::fabs(dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0]))) <= 1e-12 * longest * longest * longest) return {};
  const Vec3 center = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  double reach = 0;
  for (const Vec3& x : p) reach = std::max(reach, norm(x - center));
  std::array<Vec3, 4> inward;  // unit normal of the face opposite k, towards k
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = p[(k + 1) % 4];
    Vec3 n = cross(p[(k + 2) % 4] - a, p[(k + 3) % 4] - a);
    if (dot(n, p[k] - a) < 0) n = -1.0 * n;
    inward[k] = (1 / norm(n)) * n;
  }
  // Whether the ball (x, r) misses the cell: it lies beyond its bounding
  // sphere or one of its faces' planes (a few balls that miss pass).
  auto beyond = [&](const Vec3& x, double r) {
    if (norm(x - center) >= reach + r) return true;
    for (int k = 0; k < 4; ++k)
      if (dot(inward[k], x - p[(k + 1) % 4]) <= -r) return true;
    return false;
  };
  // Kept from call to call (no allocation per cell): the balls that reach
  // the cell, the planes of P_i, the cell's part of one.
  thread_local std::vector<Index> near;
  thread_local std::vector<std::pair<Vec3, double>> cuts;
  thread_local ConvexPolyhedron part;
  near.clear();
  balls_.visit(center, reach + max_radius_, [&](Index i) {
    if (!beyond(t.point(i), radius_[i])) near.push_back(i);
  });
  std::sort(near.begin(), near.end());
  Sum volume, area;
  for (Index i : near) {
    // The cell's part of the power cell of i, about i's centre: B_i & P_i
    // is B_i cut by the half-spaces of i's neighbours in K, and in the cell
    // only those of neighbours reaching it cut (a point of B_i where j has
    // the smaller power is in B_j).
    const Vec3& q = t.point(i);
    cuts.clear();
    bool missed = false;  // by P_i: the cell lies beyond one of its planes
    for (Index k = neighbour_start_[i]; k < neighbour_start_[i + 1] && !missed; ++k) {
      const Index j = neighbours_[k];
      if (!std::binary_search(near.begin(), near.end(), j)) continue;
      const Vec3 d = t.point(j) - q;
      const double offset = dot(d, d) + t.weight(i) - t.weight(j);
      missed = std::all_of(p.begin(), p.end(), [&](const Vec3& x) { return 2 * dot(d, x - q) > offset; });
      cuts.push_back({2.0 * d, offset});
    }
    if (missed) continue;
    part.reset(p[0] - q, p[1] - q, p[2] - q, p[3] - q);
    for (std::size_t k = 0; k < cuts.size() && !part.empty(); ++k) part.clip(cuts[k].first, cuts[k].second);
    if (part.empty()) continue;
    const BallPart x = ball_in_polyhedron(part, radius_[i]);
    volume.add(x.volume);
    area.add(x.area);
  }
  return {volume.value(), area.value()};
}

std::size_t UnionOfBalls::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(ball_area_) + bytes(ball_volume_) + bytes(radius_) + bytes(neighbour_start_) + bytes(neighbours_);
}

}  // namespace alpha
