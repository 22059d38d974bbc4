// SPDX-License-Identifier: Apache-2.0
#include "alpha/predicates.hpp"

#include <algorithm>
#include <cmath>

#include "exact.hpp"

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

// Returns the sign, or 2 when the filter cannot decide.
int filtered_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  const double det = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  const double mx = std::max({std::fabs(ux), std::fabs(vx), std::fabs(wx)});
  const double my = std::max({std::fabs(uy), std::fabs(vy), std::fabs(wy)});
  const double mz = std::max({std::fabs(uz), std::fabs(vz), std::fabs(wz)});
  if (!in_filter_range(std::min({mx, my, mz})) || !in_filter_range(std::max({mx, my, mz}))) return 2;
  const double eps = kOrientBound * mx * my * mz;
  if (det > eps) return 1;
  if (det < -eps) return -1;
  return 2;
}

// Written out row by row: this is the hottest function of the construction,
// and the unweighted instance drops the weight terms at compile time.
template <bool kWeighted>
[[gnu::always_inline]] inline int filtered_power_det(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& q3,
                                                    const double w[4], const Vec3& p, double wp) {
  auto dw = [&](int i) { return kWeighted ? w[i] - wp : 0.0; };
  const double x0 = q0.x - p.x, y0 = q0.y - p.y, z0 = q0.z - p.z, d0 = dw(0);
  const double x1 = q1.x - p.x, y1 = q1.y - p.y, z1 = q1.z - p.z, d1 = dw(1);
  const double x2 = q2.x - p.x, y2 = q2.y - p.y, z2 = q2.z - p.z, d2 = dw(2);
  const double x3 = q3.x - p.x, y3 = q3.y - p.y, z3 = q3.z - p.z, d3 = dw(3);
  const double s0 = x0 * x0 + y0 * y0 + z0 * z0, s1 = x1 * x1 + y1 * y1 + z1 * z1;
  const double s2 = x2 * x2 + y2 * y2 + z2 * z2, s3 = x3 * x3 + y3 * y3 + z3 * z3;
  const double h0 = s0 - d0, h1 = s1 - d1, h2 = s2 - d2, h3 = s3 - d3;
  // 2x2 minors of the xy columns, then 3x3 minors with z, then along h.
  const double m01 = x0 * y1 - x1 * y0, m02 = x0 * y2 - x2 * y0, m03 = x0 * y3 - x3 * y0;
  const double m12 = x1 * y2 - x2 * y1, m13 = x1 * y3 - x3 * y1, m23 = x2 * y3 - x3 * y2;
  const double m012 = z0 * m12 - z1 * m02 + z2 * m01;
  const double m013 = z0 * m13 - z1 * m03 + z3 * m01;
  const double m023 = z0 * m23 - z2 * m03 + z3 * m02;
  const double m123 = z1 * m23 - z2 * m13 + z3 * m12;
  const double det = (h3 * m012 - h2 * m013) + (h1 * m023 - h0 * m123);
  const double mx = std::max(std::max(std::fabs(x0), std::fabs(x1)), std::max(std::fabs(x2), std::fabs(x3)));
  const double my = std::max(std::max(std::fabs(y0), std::fabs(y1)), std::max(std::fabs(y2), std::fabs(y3)));
  const double mz = std::max(std::max(std::fabs(z0), std::fabs(z1)), std::max(std::fabs(z2), std::fabs(z3)));
  const double mh = std::max(std::max(s0 + std::fabs(d0), s1 + std::fabs(d1)), std::max(s2 + std::fabs(d2), s3 + std::fabs(d3)));
  // mh >= mx^2, my^2, mz^2: its upper limit bounds them too.
  if (!in_filter_range(std::min({mx, my, mz, mh})) || !(mh < 1e60)) return 2;
  const double eps = kPowerBound * mx * my * mz * mh;
  if (det > eps) return 1;
  if (det < -eps) return -1;
  return 2;
}

}  // namespace

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

int Kernel::orient3d(Index a, Index b, Index c, Index d) {
  return orient3d(pts_[a], pts_[b], pts_[c], pts_[d]);
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
    int next = -1;
    for (int k = 0; k < 4; ++k)
      if (rank[k] > p_rank && (next < 0 || rank[k] > rank[next])) next = k;
    if (next < 0) return true;  // p has the largest remaining perturbation: its weight wins
    const int o = orient_with_p(next);
    if (o != 0) return o < 0;
    rank[next] = -1;
  }
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
// the exact stage takes are built only when it cannot decide.
bool Kernel::power_conflict(Index a, Index b, Index c, Index d, Index p) {
  const double wq[4] = {weight(a), weight(b), weight(c), weight(d)};
  const int s = w_ ? filtered_power_det<true>(pts_[a], pts_[b], pts_[c], pts_[d], wq, pts_[p], weight(p))
                   : filtered_power_det<false>(pts_[a], pts_[b], pts_[c], pts_[d], wq, pts_[p], 0.0);
  if (s != 2) {
    ++stats_.power.filtered;
    return s < 0;
  }
  const Vec3* q[4] = {&pts_[a], &pts_[b], &pts_[c], &pts_[d]};
  const Index id[4] = {a, b, c, d};
  return exact_conflict(q, wq, id, p);
}

bool Kernel::hull_conflict(Index a, Index b, Index c, Index p) {
  const int o = orient3d(a, b, c, p);
  if (o != 0) return o > 0;
  // p is coplanar with the hull facet. Its orthocircle test equals the power
  // test against any cell (a,b,c,d) with d off the plane, since d's lifted
  // value is multiplied by orient3d(a,b,c,p) = 0. Take d = a moved along an
  // axis by an exactly representable step, and give it no perturbation.
  const Vec3& pa = pts_[a];
  Vec3 d = pa;
  int od = 0;
  for (int axis = 0; axis < 3 && od == 0; ++axis) {
    d = axis_offset(pa, axis);
    od = orient3d(pts_[a], pts_[b], pts_[c], d);
  }
  const Vec3* q[4] = {&pts_[a], &pts_[b], &pts_[c], &d};
  Index id[4] = {a, b, c, kNone};  // d is virtual: never perturbed
  if (od < 0) std::swap(q[0], q[1]), std::swap(id[0], id[1]);
  const double wq[4] = {weight(id[0]), weight(id[1]), weight(c), weight(a)};
  return cell_conflict(q, wq, id, p);
}

int Kernel::power_side_exact(Index a, Index b, Index c, Index d, Index p) {
  const Vec3* q[4] = {&pts_[a], &pts_[b], &pts_[c], &pts_[d]};
  const double wq[4] = {weight(a), weight(b), weight(c), weight(d)};
  return -exact::power_det(q, wq, pts_[p], weight(p));
}

}  // namespace alpha
