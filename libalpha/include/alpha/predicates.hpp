// SPDX-License-Identifier: Apache-2.0
// Exact geometric predicates on (weighted) points, all in one place.
//
// Every predicate follows one pattern: a floating-point evaluation with a
// proven error bound (semi-static filter); when the bound cannot certify the
// sign, an exact evaluation (128-bit integers when the inputs are small
// dyadic numbers such as grid coordinates, GMP otherwise); and, for the
// power test only, Simulation of Simplicity when the exact value is zero.
// On input of small integers (exact_in_doubles) the filter's own double
// values are exact: their signs are final, and a zero goes straight to the
// perturbation.
//
// The perturbation (Devillers & Teillaud 2011, weights perturbed) raises the
// weight of point i by eps^(N-i): the point with the larger input index has
// the larger perturbation, so results are reproducible and independent of
// memory layout or insertion order. Orientation is never perturbed: the
// triangulation only needs its exact sign, and flat cells cannot arise from
// a regular triangulation of the perturbed points.
//
// A Kernel is cheap to create and owns its counters; it is not shared
// between threads: one per triangulation.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "alpha/geometry.hpp"

namespace alpha {

struct StageCounts {
  std::uint64_t filtered = 0;   // decided in doubles: by the filter, or exactly (exact_in_doubles)
  std::uint64_t exact = 0;      // needed exact arithmetic, nonzero result
  std::uint64_t perturbed = 0;  // exact value zero: decided symbolically
  std::uint64_t calls() const { return filtered + exact + perturbed; }
  StageCounts& operator+=(const StageCounts& o) {
    filtered += o.filtered, exact += o.exact, perturbed += o.perturbed;
    return *this;
  }
};

struct PredicateStats {
  StageCounts orient;  // orient3d (exact zero counts as 'perturbed' = degenerate)
  StageCounts power;   // power test against a cell's orthosphere
  PredicateStats& operator+=(const PredicateStats& o) {
    orient += o.orient, power += o.power;
    return *this;
  }
};

class Kernel {
public:
  // `weights` may be null (unweighted: all weights zero). `ids`, if given,
  // is each point's input index, which orders the perturbation (a builder
  // that stores the points in another order); null: the position itself.
  // Arrays are borrowed. `in_doubles`: the points and weights are
  // exact_in_doubles (checked by the caller, once).
  Kernel(const Vec3* points, const double* weights, const Index* ids = nullptr, bool in_doubles = false)
      : pts_(points), w_(weights), ids_(ids), in_doubles_(in_doubles) {}

  // Whether every coordinate and weight is an integer, the coordinates of
  // magnitude below 2^51 and spanning less than 2^9 along each axis, the
  // weights spanning less than 2^19 (grids): then every value of the power
  // test's and orient3d's filters is an integer below 2^53, so the doubles
  // are exact.
  static bool exact_in_doubles(std::span<const Vec3> points, std::span<const double> weights);

  // Sign of det[b-a, c-a, d-a]: +1 when d lies on the side of plane abc
  // from which a,b,c appear counter-clockwise. Exact, may be 0.
  int orient3d(Index a, Index b, Index c, Index d) {
    return in_doubles_ ? orient3d_in_doubles(pts_[a], pts_[b], pts_[c], pts_[d])
                       : orient3d(pts_[a], pts_[b], pts_[c], pts_[d]);
  }
  int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

  // Whether point p conflicts with the positively oriented cell (a,b,c,d):
  // its power distance to the cell's orthosphere is negative (for unweighted
  // points: p strictly inside the circumsphere). Perturbed: never undecided.
  bool power_conflict(Index a, Index b, Index c, Index d, Index p) { return power_conflict({a, b, c, d}, p); }
  // The same for the cell's vertex array (the indices stay in memory: the
  // filter's path keeps fewer of them in registers).
  bool power_conflict(const std::array<Index, 4>& v, Index p);

  // The same for the infinite cell (a,b,c,inf), where the hull facet (a,b,c)
  // is oriented so that orient3d(a,b,c,q) > 0 for q outside the hull: p
  // conflicts when it sees the facet from outside or, coplanar with it,
  // lies inside its orthocircle (perturbed as above).
  bool hull_conflict(Index a, Index b, Index c, Index p);

  // Exact sign of the unperturbed power test (for checks): +1 conflict,
  // 0 on the orthosphere, -1 outside.
  int power_side_exact(Index a, Index b, Index c, Index d, Index p);

  // a moved along one axis by an exactly representable nonzero step: with
  // orient3d(a,b,c,axis_offset(a,k)) for k = 0,1,2 all zero, a,b,c are collinear.
  static Vec3 axis_offset(const Vec3& a, int axis);

  const PredicateStats& stats() const { return stats_; }

private:
  const Vec3* pts_;
  const double* w_;
  const Index* ids_;
  bool in_doubles_;
  PredicateStats stats_;

  double weight(Index i) const { return w_ ? w_[i] : 0.0; }
  // Filter, exact, then perturbed conflict test of a positive cell q.
  bool cell_conflict(const Vec3* q[4], const double wq[4], const Index id[4], Index p);
  // Its exact and perturbed stages, when the filter cannot decide.
  bool exact_conflict(const Vec3* q[4], const double wq[4], const Index id[4], Index p);
  [[gnu::noinline]] bool exact_power_conflict(const std::array<Index, 4>& v, Index p);
  // The same tests when the filters' doubles are exact (in_doubles_).
  int orient3d_in_doubles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
  [[gnu::always_inline]] inline bool conflict_in_doubles(const Vec3* q[4], const double wq[4], const Index id[4],
                                                         Index p);
  bool power_conflict_in_doubles(const std::array<Index, 4>& v, Index p);
  template <class OrientWithP>
  [[gnu::always_inline]] inline bool perturbed_conflict(const Index id[4], Index pid, OrientWithP orient_with_p);
};

}  // namespace alpha
