// SPDX-License-Identifier: Apache-2.0
#include "alpha/union_of_balls.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "alpha/error.hpp"
#include "compensated_sum.hpp"

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

// Dihedral angle of tetrahedron (a, b, c, d) at edge ab.
double dihedral_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 e = b - a;
  const Vec3 n1 = cross(e, c - a), n2 = cross(e, d - a);
  return std::atan2(norm(cross(n1, n2)), dot(n1, n2));
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
  std::vector<double> radius(n, 0.0);
  for (Index i = 0; i < n; ++i) {
    const double w = t.weight(i);
    if (!(w >= 0)) fail("union of balls: point " + std::to_string(i) + " has negative weight " + std::to_string(w));
    radius[i] = std::sqrt(w);
  }
  // The balls of a simplex relative to its first vertex.
  auto balls = [&]<std::size_t N>(const std::array<Index, N>& v, std::array<Ball, N>& b) {
    for (std::size_t k = 0; k < N; ++k) b[k] = {t.point(v[k]) - t.point(v[0]), t.weight(v[k]), radius[v[k]]};
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
  edge_term_.assign(s.num_edges(), {});
  triangle_term_.assign(s.num_triangles(), {});
  cell_term_.assign(t.num_cells(), {});

  for (Index v = 0; v < n; ++v)
    if (in_dual_complex_vertex(v)) area[v].add(4 * kPi * t.weight(v));
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
    edge_term_[e] = {lens.volume, lens.area};
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
    triangle_term_[f] = {tt.volume, tt.area};
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
    cell_term_[c] = {tt.volume, tt.area};
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
    ball_area_[i] = denoised(area[i].value(), 4 * kPi * t.weight(i));
    volume[i].add(radius[i] * ball_area_[i]);
  }
  for (Index e = 0; e < s.num_edges(); ++e) {
    const double f = facet[e].value();
    if (f == 0) continue;
    const auto& v = s.edge(e);
    const Ball b0{{}, t.weight(v[0]), radius[v[0]]}, b1{{}, t.weight(v[1]), radius[v[1]]};
    const double d = norm(t.point(v[1]) - t.point(v[0]));
    volume[v[0]].add(radical_offset(b0, b1, d) * f);
    volume[v[1]].add(radical_offset(b1, b0, d) * f);
  }
  Sum total_area, total_volume;
  for (Index i = 0; i < n; ++i) {
    ball_volume_[i] = denoised(volume[i].value() / 3, 4 * kPi / 3 * t.weight(i) * radius[i]);
    total_area.add(ball_area_[i]);
    total_volume.add(ball_volume_[i]);
  }
  area_ = total_area.value();
  volume_ = total_volume.value();
}

CellCover UnionOfBalls::cell_cover(Index c) const {
  const Triangulation& t = complex_->triangulation();
  const Simplices& s = complex_->simplices();
  if (t.is_infinite(c)) return {};
  const auto& v = t.cell(c).v;
  std::array<Vec3, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = t.point(v[k]);
  Sum volume, area;
  // A term of a simplex, times the cell's fraction.
  auto add = [&]<std::size_t N>(const Term<N>& term, double fraction) {
    volume.add(fraction * term.volume);
    for (std::size_t k = 0; k < N; ++k) area.add(fraction * term.area[k]);
  };
  for (int k = 0; k < 4; ++k) {
    if (!in_dual_complex_vertex(v[k])) continue;
    const double w = t.weight(v[k]);
    const Term<1> ball{4 * kPi / 3 * w * std::sqrt(w), {4 * kPi * w}};
    add(ball, solid_angle(p[k], p[(k + 1) % 4], p[(k + 2) % 4], p[(k + 3) % 4]) / (4 * kPi));
  }
  for (int e = 0; e < 6; ++e) {
    const int x = kEdge[e][0], y = kEdge[e][1];
    const Index id = s.find_edge(v[x], v[y]);
    const Term<2>& lens = edge_term_[id];
    if (lens.volume == 0 && lens.area[0] == 0 && lens.area[1] == 0) continue;
    add(lens, -dihedral_angle(p[x], p[y], p[kEdgeOthers[e][0]], p[kEdgeOthers[e][1]]) / (2 * kPi));
  }
  for (int k = 0; k < 4; ++k) {
    const Index f = s.cell_triangle(c, k);
    add(triangle_term_[f], 0.5);
  }
  add(cell_term_[c], -1.0);
  return {volume.value(), area.value()};
}

std::size_t UnionOfBalls::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(ball_area_) + bytes(ball_volume_) + bytes(edge_term_) + bytes(triangle_term_) + bytes(cell_term_);
}

}  // namespace alpha
