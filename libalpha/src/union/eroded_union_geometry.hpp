// SPDX-License-Identifier: Apache-2.0
// The free geometry of the eroded union's integrals: the circle where two
// spheres meet and its frame, sets of arcs on it, the wedges and spherical
// triangles integrated, the 8-node Gauss rule with the bisection that
// cuts an interval where a predicate changes, and the bisection along a
// ray to where a point comes within reach. Internal: included by the
// files that find the union's boundary and integrate it
// (eroded_union_boundary.cpp, eroded_union_hood.hpp,
// eroded_union_integrator.hpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "alpha/eroded_union.hpp"
#include "alpha/triangulation.hpp"

namespace alpha {
namespace eroded_union_detail {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2 * kPi;
// 8-node Gauss-Legendre rule on [-1, 1], nodes ascending.
inline constexpr std::array<double, 8> kNode{-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                      -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                      0.7966664774136267,  0.9602898564975363};
inline constexpr std::array<double, 8> kWeight{0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                        0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                        0.2223810344533745, 0.1012285362903763};
inline constexpr double kCutPrecision = 1e-8;  // of tau, relative to r
inline constexpr int kEdgeBisections = 24;  // where tau = r starts or stops between two nodes
inline constexpr double kMaxPiece = kPi / 4;
// cut()'s bisection narrows its hood to the segment left after this many
// halvings.
inline constexpr int kCutNarrowAfter = 3;
// cut() tests this far (relative to r) before and after where the point of
// F found last starts to be found, located to a thousandth of that.
inline constexpr double kBracket = kCutPrecision / 8;

// Within a turn of [0, 2 pi) (nearly every call), the values fmod gives:
// a - 2 pi is exact there (Sterbenz), as fmod is; -2 pi itself goes to
// fmod, whose -0 stays.
inline double wrap(double a) {
  if (a >= 0 && a < 2 * kTwoPi) return a < kTwoPi ? a : a - kTwoPi;
  if (a < 0 && a > -kTwoPi) return a + kTwoPi;
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

using Arc = ErodedUnion::Arc;

// The circle where the spheres of an edge (p_i, w_i), (p_j, w_j) meet, with a frame:
// center o, unit axis w from p_i to p_j, unit e1, e2 spanning its plane;
// z_i, z_j: the centers' coordinates along w from o.
struct Circle {
  Vec3 o, w, e1, e2;
  double rho = 0, z_i = 0, z_j = 0;

  Vec3 radial(double phi) const { return std::cos(phi) * e1 + std::sin(phi) * e2; }
  // The direction at angle psi from the plane, inwards from the circle's point at `radial`.
  Vec3 ray(const Vec3& radial, double psi) const { return ray(radial, std::cos(psi), std::sin(psi)); }
  Vec3 ray(const Vec3& radial, double cos_psi, double sin_psi) const { return -cos_psi * radial + sin_psi * w; }
  double angle(const Vec3& v) const { return wrap(std::atan2(dot(v, e2), dot(v, e1))); }
  // The squared distance from a point to the circle's nearest point, given
  // the point's distance s from the axis and z from the plane.
  double squared_distance(double s, double z) const { return (s - rho) * (s - rho) + z * z; }
  double squared_distance(const Vec3& x) const {
    const Vec3 y = x - o;
    const double z = dot(y, w);
    return squared_distance(norm(y - z * w), z);
  }
};

// [a, b] cut where a predicate changes, from its values at the 8 Gauss
// nodes: each value extends to the next change, located by bisection
// between the nodes that differ.
struct Segment {
  double lo, hi;
  bool holds;
};

// A spherical triangle of directions (corners a, b, c) in geodesic polar
// coordinates about a: u(s, sigma) lies on the great circle from a to the
// point m(sigma) of the arc from b to c (both spherical interpolations),
// at s of the angle theta(sigma) between them. The solid angle element is
// sin(s theta) theta beta'(sigma), beta the azimuth of m about a,
// beta' = a.(m x m') / sin^2 theta: smooth however wide the triangle.
struct SphericalTriangle {
  std::array<Vec3, 3> dir;
  double gamma;  // the angle from b to c
  explicit SphericalTriangle(const std::array<Vec3, 3>& d)
      : dir(d), gamma(std::atan2(norm(cross(d[1], d[2])), dot(d[1], d[2]))) {}
  // What the directions at one sigma share: m, theta, sin theta and the
  // jacobian's factor |a.(m x m')| (none where the triangle is flat).
  struct Meridian {
    Vec3 m;
    double theta, st, turn = 0;
    bool flat = true;
  };
  Meridian meridian(double sigma) const {
    const double sg = std::sin(gamma);
    const Vec3 m = sg > 0 ? (1 / sg) * (std::sin((1 - sigma) * gamma) * dir[1] + std::sin(sigma * gamma) * dir[2])
                          : dir[1];
    const double theta = std::atan2(norm(cross(dir[0], m)), dot(dir[0], m)), st = std::sin(theta);
    Meridian out{m, theta, st};
    if (st > 0 && sg > 0) {
      const Vec3 dm = (gamma / sg) * (-std::cos((1 - sigma) * gamma) * dir[1] + std::cos(sigma * gamma) * dir[2]);
      out.turn = std::fabs(dot(dir[0], cross(m, dm)));
      out.flat = false;
    }
    return out;
  }
  Vec3 direction(double s, const Meridian& a, double* jacobian) const {
    if (jacobian) *jacobian = a.flat ? 0 : std::sin(s * a.theta) * a.theta * a.turn / (a.st * a.st);
    return a.st > 0 ? (1 / a.st) * (std::sin((1 - s) * a.theta) * dir[0] + std::sin(s * a.theta) * a.m) : dir[0];
  }
  Vec3 direction(double s, double sigma, double* jacobian) const { return direction(s, meridian(sigma), jacobian); }
};

// Node k of the Gauss rule on [a, b], and its weight.
inline double node(double a, double b, int k) { return (a + b) / 2 + (b - a) / 2 * kNode[k]; }
inline double weight(double a, double b, int k) { return (b - a) / 2 * kWeight[k]; }

inline bool full(const Arc& a) { return a.length >= kTwoPi; }

// Into out, the parts of `set` inside `a` (out is not set).
inline void clip(std::span<const Arc> set, const Arc& a, std::vector<Arc>& out) {
  out.clear();
  if (full(a)) {
    out.assign(set.begin(), set.end());
    return;
  }
  for (const Arc& x : set) {
    if (full(x)) {
      out.push_back(a);
      continue;
    }
    const double s = wrap(x.begin - a.begin);
    for (const double start : {s, s - kTwoPi}) {
      const double lo = std::max(start, 0.0), hi = std::min(start + x.length, a.length);
      if (hi > lo) out.push_back({wrap(a.begin + lo), hi - lo});
    }
  }
}

// Keeps the parts of `set` where a cos phi + b sin phi <= c (`scratch`:
// space for the clipping, kept by the caller: no allocation per call).
inline void keep_below(std::vector<Arc>& set, double a, double b, double c, std::vector<Arc>& scratch) {
  const double m = std::hypot(a, b);
  if (c >= m) return;
  if (c <= -m) {
    set.clear();
    return;
  }
  // cos(phi - phi0) <= c / m: phi at least delta from phi0.
  const double delta = std::atan2(std::sqrt((m - c) * (m + c)), c);
  clip(set, {wrap(std::atan2(b, a) + delta), kTwoPi - 2 * delta}, scratch);
  set.swap(scratch);
}

// Whether the direction (x, y) in a circle's frame is on one of its arcs
// (ends: the arcs' end directions), by the signs of cross products.
inline bool contains(std::span<const Arc> set, const ErodedUnion::ArcEnds* ends, double x, double y) {
  for (std::size_t k = 0; k < set.size(); ++k) {
    if (full(set[k])) return true;
    const double after_begin = ends[k].cos_begin * y - ends[k].sin_begin * x;
    const double before_end = x * ends[k].sin_end - y * ends[k].cos_end;
    if (set[k].length <= kPi ? after_begin >= 0 && before_end >= 0 : after_begin >= 0 || before_end >= 0) return true;
  }
  return false;
}

// A ball (centre, radius) holding the points of the arcs `set` of circle
// c (ends: their end directions): about the chord of a single arc up to
// half a turn, else the circle's.
inline std::pair<Vec3, double> arc_bound(std::span<const Arc> set, const ErodedUnion::ArcEnds* ends, const Circle& c) {
  if (set.size() != 1 || set[0].length > kPi) return {c.o, c.rho};
  const ErodedUnion::ArcEnds& a = ends[0];
  const double x = a.cos_begin + a.cos_end, y = a.sin_begin + a.sin_end;
  const double dx = a.cos_end - a.cos_begin, dy = a.sin_end - a.sin_begin;
  return {c.o + (c.rho / 2) * (x * c.e1 + y * c.e2), c.rho / 2 * std::sqrt(dx * dx + dy * dy)};
}

// A frame about the unit axis w (only w, e1, e2 set).
inline Circle circle_of_axis(const Vec3& w) {
  Circle c;
  c.w = w;
  // e1: w crossed with the coordinate axis it is least aligned with.
  const double ax = std::fabs(w.x), ay = std::fabs(w.y), az = std::fabs(w.z);
  const Vec3 axis = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  const Vec3 e = cross(w, axis);
  c.e1 = (1 / norm(e)) * e;
  c.e2 = cross(w, c.e1);
  return c;
}

inline Circle circle_of(const Triangulation& t, const std::array<Index, 2>& edge) {
  const Vec3 &pi = t.point(edge[0]), &pj = t.point(edge[1]);
  const double wi = t.weight(edge[0]), wj = t.weight(edge[1]);
  Circle c;
  const Vec3 d = pj - pi;
  const double len = norm(d);
  c.w = (1 / len) * d;
  const double a = (len * len + wi - wj) / (2 * len);
  c.o = pi + a * c.w;
  c.rho = std::sqrt(std::max(0.0, (std::sqrt(wi) - a) * (std::sqrt(wi) + a)));
  const Circle frame = circle_of_axis(c.w);
  c.e1 = frame.e1;
  c.e2 = frame.e2;
  c.z_i = -a;
  c.z_j = len - a;
  return c;
}

// int_0^T |rho - t c| t dt, c = cos psi > 0.
inline double ray_volume(double rho, double c, double T) {
  const auto f = [&](double t) { return rho * t * t / 2 - c * t * t * t / 3; };
  if (c * T <= rho) return f(T);
  const double t0 = rho / c;  // the ray crosses the circle's axis
  return 2 * f(t0) - f(T);
}

// int_a^b g(psi) dpsi over the wedge's angle, split where r cos psi = rho
// (the torus crosses its axis) so that `smooth(lo, hi, crossing)` sees one
// sign of rho - r cos psi.
template <class Smooth>
double over_wedge(double rho, double r, double a, double b, Smooth smooth) {
  if (rho >= r) return smooth(a, b, false);
  const double psi0 = std::atan2(std::sqrt((r - rho) * (r + rho)), rho);
  double sum = 0;
  const std::array<double, 4> cut{a, std::clamp(-psi0, a, b), std::clamp(psi0, a, b), b};
  for (int k = 0; k < 3; ++k)
    if (cut[k + 1] > cut[k]) sum += smooth(cut[k], cut[k + 1], k == 1);
  return sum;
}

// int_a^b |rho - r cos psi| r dpsi.
inline double wedge_area(double rho, double r, double a, double b) {
  return over_wedge(rho, r, a, b, [&](double lo, double hi, bool crossing) {
    const double x = r * (rho * (hi - lo) - r * (std::sin(hi) - std::sin(lo)));
    return crossing ? -x : x;
  });
}

// int_a^b ray_volume(rho, cos psi, r) dpsi.
inline double wedge_volume(double rho, double r, double a, double b) {
  return over_wedge(rho, r, a, b, [&](double lo, double hi, bool crossing) {
    const double x = rho * r * r / 2 * (hi - lo) - r * r * r / 3 * (std::sin(hi) - std::sin(lo));
    // Past the axis: rho^3 / (3 cos^2 psi) - x's integrand, by 2 f(t0) - f(r).
    return crossing ? rho * rho * rho / 3 * (std::tan(hi) - std::tan(lo)) - x : x;
  });
}

// Where a predicate that holds at a and not at b (or the reverse) changes;
// at_a: its value at a.
template <class Predicate>
double change(double a, double b, bool at_a, Predicate holds, int bisections = kEdgeBisections) {
  for (int k = 0; k < bisections; ++k) {
    const double mid = (a + b) / 2;
    (holds(mid) == at_a ? a : b) = mid;
  }
  return (a + b) / 2;
}

struct NoPreparation {
  void operator()(double, double) const {}
};

// prepare(lo, hi): called before a change is located between the nodes lo
// and hi (the predicate is tested there).
template <class Predicate, class Prepare = NoPreparation>
std::vector<Segment> segments(double a, double b, const std::array<bool, 8>& at_node, Predicate holds,
                              Prepare prepare = {}) {
  std::vector<Segment> out;
  double start = a;
  for (int k = 0; k < 8; ++k) {
    if (k < 7 && at_node[k] == at_node[k + 1]) continue;
    if (k < 7) prepare(node(a, b, k), node(a, b, k + 1));
    const double end = k == 7 ? b : change(node(a, b, k), node(a, b, k + 1), at_node[k], holds);
    out.push_back({start, end, at_node[k]});
    start = end;
  }
  return out;
}

// Where, to `precision`, on the ray q + t u in [lo, hi] a point of F
// (`squared_distance` to q + t u) comes nearer than t - shift: the end of
// the initial segment where it is not (its distance less t only decreases
// along the ray).
template <class SquaredDistance>
double reach_end(const SquaredDistance& squared_distance, double shift, double lo, double hi, double precision) {
  while (hi - lo > precision) {
    const double mid = (lo + hi) / 2;
    (squared_distance(mid) >= (mid - shift) * (mid - shift) ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace eroded_union_detail
}  // namespace alpha
