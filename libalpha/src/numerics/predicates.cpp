// SPDX-License-Identifier: Apache-2.0
#include "alpha/predicates.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/exact.hpp"

namespace alpha {
namespace {

// Magnitudes outside this range could underflow or overflow in the filters'
// bounds; such calls go straight to exact arithmetic.
bool in_filter_range(double m) { return m > 1e-60 && m < 1e60; }

// Semi-static filter of orient3d: with u = 2^-53 the rounding error of the
// evaluation below (differences included) is at most (7 + 56u) u times the
// permanent (Shewchuk 1997), and the permanent is at most 6 mx my mz.
constexpr double kOrientBound = 4.7e-15;
// Power test: the 3x3 minors carry the bound above, each lifted value an
// error below 7u (|d|^2 + |dw|), products and the 4-term sum add 4u; summed
// over 4 terms this is below 432u mx my mz mh = 4.8e-14 mx my mz mh.
constexpr double kPowerBound = 5.0e-14;

// Two doubles in one register (SSE2, NEON): GCC and Clang vector extensions.
using Pair = double __attribute__((vector_size(16)));
using PairBits = long long __attribute__((vector_size(16)));
inline Pair abs2(Pair a) { return (Pair)((PairBits)a & PairBits{0x7fffffffffffffffLL, 0x7fffffffffffffffLL}); }
inline Pair max2(Pair a, Pair b) { return a > b ? a : b; }
inline Pair low2(Pair a) { return __builtin_shufflevector(a, a, 0, 0); }  // both lanes the low one
inline Pair high2(Pair a) { return __builtin_shufflevector(a, a, 1, 1); }

// orient3d's determinant and the largest magnitudes of its columns. The x
// and y columns side by side in pairs, each value the expression written
// out would round.
struct OrientTerms {
  double det, mx, my, mz;
};

[[gnu::always_inline]] inline OrientTerms orient_terms(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Pair axy{a.x, a.y};
  const Pair u = Pair{b.x, b.y} - axy, v = Pair{c.x, c.y} - axy, w = Pair{d.x, d.y} - axy;
  const double uz = b.z - a.z, vz = c.z - a.z, wz = d.z - a.z;
  // (vx wz - vz wx, vy wz - vz wy), then ux (vy wz - vz wy) - uy (vx wz - vz wx) + uz (vx wy - vy wx).
  const Pair t = v * wz - vz * w;
  const Pair terms = u * __builtin_shufflevector(t, t, 1, 0);
  const Pair mxy = max2(max2(abs2(u), abs2(v)), abs2(w));
  return {terms[0] - terms[1] + uz * (v[0] * w[1] - v[1] * w[0]), mxy[0], mxy[1],
          std::max({std::fabs(uz), std::fabs(vz), std::fabs(wz)})};
}

// Returns the sign, or 2 when the filter cannot decide.
int filtered_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto [det, mx, my, mz] = orient_terms(a, b, c, d);
  if (!in_filter_range(std::min({mx, my, mz})) || !in_filter_range(std::max({mx, my, mz}))) return 2;
  const double eps = kOrientBound * mx * my * mz;
  if (det > eps) return 1;
  if (det < -eps) return -1;
  return 2;
}

// The power test's determinant and the 3x3 minors of its rows (q_i - p),
// the values its filter and its exact-in-doubles path read. The hottest
// function of the construction: rows 0,1 and rows 2,3 side by side in pairs
// (half the instructions of one row at a time), every value the same
// expression as one row at a time would round (so the filter's bound holds
// as derived); the unweighted instance drops the weight terms at compile
// time.
struct PowerTerms {
  double det;
  Pair m012_013, m023_123;  // the minors of rows 0,1,2 and 0,1,3; 0,2,3 and 1,2,3
  double mx, my, mz, mh;    // the largest magnitudes of the x, y, z and lifted columns
};

template <bool kWeighted>
[[gnu::always_inline]] inline PowerTerms power_terms(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& q3,
                                                    const double w[4], const Vec3& p, double wp) {
  const Pair x01 = Pair{q0.x, q1.x} - p.x, x23 = Pair{q2.x, q3.x} - p.x;
  const Pair y01 = Pair{q0.y, q1.y} - p.y, y23 = Pair{q2.y, q3.y} - p.y;
  const Pair z01 = Pair{q0.z, q1.z} - p.z, z23 = Pair{q2.z, q3.z} - p.z;
  const Pair s01 = x01 * x01 + y01 * y01 + z01 * z01, s23 = x23 * x23 + y23 * y23 + z23 * z23;
  // Lifted values h = |q - p|^2 - (w - wp).
  const Pair d01 = kWeighted ? Pair{w[0], w[1]} - wp : Pair{0, 0};
  const Pair d23 = kWeighted ? Pair{w[2], w[3]} - wp : Pair{0, 0};
  const Pair h01 = s01 - d01, h23 = s23 - d23;
  // 2x2 minors of the xy columns: m_ij = x_i y_j - x_j y_i.
  const Pair x32 = __builtin_shufflevector(x23, x23, 1, 0), y32 = __builtin_shufflevector(y23, y23, 1, 0);
  const Pair x02 = __builtin_shufflevector(x01, x23, 0, 2), x13 = __builtin_shufflevector(x01, x23, 1, 3);
  const Pair y02 = __builtin_shufflevector(y01, y23, 0, 2), y13 = __builtin_shufflevector(y01, y23, 1, 3);
  const Pair m02_13 = x01 * y23 - x23 * y01, m03_12 = x01 * y32 - x32 * y01, m01_23 = x02 * y13 - x13 * y02;
  // 3x3 minors with z, in pairs: m012 = z0 m12 - z1 m02 + z2 m01 beside
  // m013 = z0 m13 - z1 m03 + z3 m01, m023 = z0 m23 - z2 m03 + z3 m02 beside
  // m123 = z1 m23 - z2 m13 + z3 m12.
  const Pair m12_13 = __builtin_shufflevector(m03_12, m02_13, 1, 3), m02_03 = __builtin_shufflevector(m02_13, m03_12, 0, 2);
  const Pair m03_13 = __builtin_shufflevector(m03_12, m02_13, 0, 3), m02_12 = __builtin_shufflevector(m02_13, m03_12, 0, 3);
  const Pair m012_013 = low2(z01) * m12_13 - high2(z01) * m02_03 + z23 * low2(m01_23);
  const Pair m023_123 = z01 * high2(m01_23) - low2(z23) * m03_13 + high2(z23) * m02_12;
  // Then along h: (h3 m012 - h2 m013) + (h1 m023 - h0 m123).
  const Pair t23 = __builtin_shufflevector(h23, h23, 1, 0) * m012_013, t01 = __builtin_shufflevector(h01, h01, 1, 0) * m023_123;
  const Pair halves = __builtin_shufflevector(t23, t01, 0, 2) - __builtin_shufflevector(t23, t01, 1, 3);
  // The largest magnitudes of the x and y columns in one pair, z and h in another.
  const Pair ax = max2(abs2(x01), abs2(x23)), ay = max2(abs2(y01), abs2(y23)), az = max2(abs2(z01), abs2(z23));
  const Pair ah = kWeighted ? max2(s01 + abs2(d01), s23 + abs2(d23)) : max2(s01, s23);
  const Pair mxy = max2(__builtin_shufflevector(ax, ay, 0, 2), __builtin_shufflevector(ax, ay, 1, 3));
  const Pair mzh = max2(__builtin_shufflevector(az, ah, 0, 2), __builtin_shufflevector(az, ah, 1, 3));
  return {halves[0] + halves[1], m012_013, m023_123, mxy[0], mxy[1], mzh[0], mzh[1]};
}

// Returns the sign, or 2 when the filter cannot decide.
template <bool kWeighted>
[[gnu::always_inline]] inline int filtered_power_det(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& q3,
                                                    const double w[4], const Vec3& p, double wp) {
  const PowerTerms t = power_terms<kWeighted>(q0, q1, q2, q3, w, p, wp);
  // mh >= mx^2, my^2, mz^2: its upper limit bounds them too.
  if (!in_filter_range(std::min({t.mx, t.my, t.mz, t.mh})) || !(t.mh < 1e60)) return 2;
  const double eps = kPowerBound * t.mx * t.my * t.mz * t.mh;
  if (t.det > eps) return 1;
  if (t.det < -eps) return -1;
  return 2;
}

int sign(double x) { return (x > 0) - (x < 0); }

}  // namespace

bool Kernel::exact_in_doubles(std::span<const Vec3> points, std::span<const double> weights) {
  if (points.empty()) return false;
  // Integers spanning less than 2^9: every difference is at most 511.
  // Below 2^51, a unit step (hull_conflict) is exact too.
  const auto span_below = [](double lo, double hi, double limit) { return hi - lo < limit; };
  const auto small = [](double x) { return std::fabs(x) < 0x1p51 && exact::is_integer(x); };
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    if (!(small(p.x) & small(p.y) & small(p.z))) return false;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  if (!(span_below(lo.x, hi.x, 0x1p9) && span_below(lo.y, hi.y, 0x1p9) && span_below(lo.z, hi.z, 0x1p9)))
    return false;
  if (weights.empty()) return true;
  double wlo = weights[0], whi = weights[0];
  for (double w : weights) {
    if (!exact::is_integer(w)) return false;
    wlo = std::min(wlo, w), whi = std::max(whi, w);
  }
  return span_below(wlo, whi, 0x1p19);
}

int Kernel::orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const int s = filtered_orient3d(a, b, c, d);
  if (s != 2) {
    ++stats_.orient.filtered;
    return s;
  }
  const int e = exact::orient3d(a, b, c, d);
  ++(e != 0 ? stats_.orient.exact : stats_.orient.perturbed);
  return e;
}

Vec3 Kernel::axis_offset(const Vec3& a, int axis) {
  Vec3 d = a;
  double& x = axis == 0 ? d.x : axis == 1 ? d.y : d.z;
  x = x != 0 ? 2 * x : 1.0;  // exact: doubling, or a fresh 1
  return d;
}

// With the weight of point i raised by eps_i, the lifted determinant D (p
// conflicts when D < 0) changes by -eps_i * cofactor_i, and the cofactor of a
// cell vertex is -orient3d(cell with that vertex replaced by p), given by
// orient_with_p(k). The largest eps belongs to the largest index; p's own
// cofactor is -orient3d(cell) < 0, so the loop always ends. A virtual vertex
// (kNone) has no perturbation.
template <class OrientWithP>
bool Kernel::perturbed_conflict(const Index id[4], Index pid, OrientWithP orient_with_p) {
  auto input_index = [&](Index i) { return static_cast<long long>(ids_ ? ids_[i] : i); };
  const long long p_rank = input_index(pid);
  long long rank[4];
  for (int k = 0; k < 4; ++k) rank[k] = id[k] == kNone ? -1 : input_index(id[k]);
  // The vertices above p, largest first (picked one at a time: the first
  // nonzero cofactor usually ends it).
  for (;;) {
    int next = 0;
    for (int k = 1; k < 4; ++k)
      if (rank[k] > rank[next]) next = k;
    if (rank[next] <= p_rank) return true;  // p has the largest remaining perturbation: its weight wins
    const int o = orient_with_p(next);
    if (o != 0) return o < 0;
    rank[next] = -1;
  }
}

// Differences at most 512 (with a hull test's virtual vertex): the 2x2
// minors at most 2^19, the determinant below 2^30.
int Kernel::orient3d_in_doubles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const int s = sign(orient_terms(a, b, c, d).det);
  ++(s != 0 ? stats_.orient.filtered : stats_.orient.perturbed);
  return s;
}

// Differences at most 512 (a hull test's virtual vertex adds one to the
// span) and weight differences below 2^19: lifted values below 2^21, 2x2
// minors at most 2^19, 3x3 minors below 2^30, their products with the
// lifted values below 2^51 and the determinant below 2^53. The minors are
// the cofactors the perturbation asks about (see exact_conflict).
bool Kernel::conflict_in_doubles(const Vec3* q[4], const double wq[4], const Index id[4], Index p) {
  const PowerTerms t = w_ ? power_terms<true>(*q[0], *q[1], *q[2], *q[3], wq, pts_[p], w_[p])
                          : power_terms<false>(*q[0], *q[1], *q[2], *q[3], wq, pts_[p], 0.0);
  if (t.det != 0) {
    ++stats_.power.filtered;
    return t.det < 0;
  }
  ++stats_.power.perturbed;
  return perturbed_conflict(id, p, [&](int k) {
    return k == 0 ? sign(t.m023_123[1]) : k == 1 ? -sign(t.m023_123[0]) : k == 2 ? sign(t.m012_013[1]) : -sign(t.m012_013[0]);
  });
}

bool Kernel::power_conflict_in_doubles(const std::array<Index, 4>& v, Index p) {
  const Vec3* q[4] = {&pts_[v[0]], &pts_[v[1]], &pts_[v[2]], &pts_[v[3]]};
  const double wq[4] = {weight(v[0]), weight(v[1]), weight(v[2]), weight(v[3])};
  return conflict_in_doubles(q, wq, v.data(), p);
}

bool Kernel::exact_conflict(const Vec3* q[4], const double wq[4], const Index id[4], Index p) {
  int s, orient[4];
  const bool small = exact::small_power_det(q, wq, pts_[p], weight(p), s, orient);
  if (!small) s = exact::dyadic_power_det(q, wq, pts_[p], weight(p));
  if (s != 0) {
    ++stats_.power.exact;
    return s < 0;
  }
  ++stats_.power.perturbed;
  if (small) return perturbed_conflict(id, p, [&](int k) { return orient[k]; });
  return perturbed_conflict(id, p, [&](int k) {
    const Vec3* r[4] = {q[0], q[1], q[2], q[3]};
    r[k] = &pts_[p];
    return orient3d(*r[0], *r[1], *r[2], *r[3]);
  });
}

bool Kernel::cell_conflict(const Vec3* q[4], const double wq[4], const Index id[4], Index p) {
  const int s = w_ ? filtered_power_det<true>(*q[0], *q[1], *q[2], *q[3], wq, pts_[p], weight(p))
                   : filtered_power_det<false>(*q[0], *q[1], *q[2], *q[3], wq, pts_[p], 0.0);
  if (s == 2) return exact_conflict(q, wq, id, p);
  ++stats_.power.filtered;
  return s < 0;
}

// The hottest predicate: the filter reads the points in place, and the arrays
// the exact stage takes are built only when it cannot decide (out of line, so
// that the filter's path does not prepare them).
bool Kernel::power_conflict(const std::array<Index, 4>& v, Index p) {
  if (in_doubles_) return power_conflict_in_doubles(v, p);
  int s;
  if (w_) {
    const double wq[4] = {w_[v[0]], w_[v[1]], w_[v[2]], w_[v[3]]};
    s = filtered_power_det<true>(pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[v[3]], wq, pts_[p], w_[p]);
  } else {
    s = filtered_power_det<false>(pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[v[3]], nullptr, pts_[p], 0.0);
  }
  if (s == 2) return exact_power_conflict(v, p);
  ++stats_.power.filtered;
  return s < 0;
}

bool Kernel::exact_power_conflict(const std::array<Index, 4>& v, Index p) {
  const Vec3* q[4] = {&pts_[v[0]], &pts_[v[1]], &pts_[v[2]], &pts_[v[3]]};
  const double wq[4] = {weight(v[0]), weight(v[1]), weight(v[2]), weight(v[3])};
  const Index id[4] = {v[0], v[1], v[2], v[3]};
  return exact_conflict(q, wq, id, p);
}

bool Kernel::hull_conflict(Index a, Index b, Index c, Index p) {
  const int o = orient3d(a, b, c, p);
  if (o != 0) return o > 0;
  // p is coplanar with the hull facet. Its orthocircle test equals the power
  // test against any cell (a,b,c,d) with d off the plane, since d's lifted
  // value is multiplied by orient3d(a,b,c,p) = 0. Take d = a moved along an
  // axis by an exactly representable step (on exact_in_doubles input one
  // unit, so that the differences stay within 512), and give it no
  // perturbation.
  const Vec3& pa = pts_[a];
  Vec3 d = pa;
  int od = 0;
  for (int axis = 0; axis < 3 && od == 0; ++axis) {
    if (in_doubles_) {
      d = pa;
      (axis == 0 ? d.x : axis == 1 ? d.y : d.z) += 1;
      od = orient3d_in_doubles(pa, pts_[b], pts_[c], d);
    } else {
      d = axis_offset(pa, axis);
      od = orient3d(pa, pts_[b], pts_[c], d);
    }
  }
  const Vec3* q[4] = {&pts_[a], &pts_[b], &pts_[c], &d};
  Index id[4] = {a, b, c, kNone};  // d is virtual: never perturbed
  if (od < 0) std::swap(q[0], q[1]), std::swap(id[0], id[1]);
  const double wq[4] = {weight(id[0]), weight(id[1]), weight(c), weight(a)};
  return in_doubles_ ? conflict_in_doubles(q, wq, id, p) : cell_conflict(q, wq, id, p);
}

int Kernel::power_side_exact(Index a, Index b, Index c, Index d, Index p) {
  const Vec3* q[4] = {&pts_[a], &pts_[b], &pts_[c], &pts_[d]};
  const double wq[4] = {weight(a), weight(b), weight(c), weight(d)};
  return -exact::power_det(q, wq, pts_[p], weight(p));
}

}  // namespace alpha
