// SPDX-License-Identifier: Apache-2.0
// Exact sizes of simplices, the values an alpha complex is filtered by.
//
// For a simplex of 1..4 affinely independent weighted points (p_i, w_i),
// the smallest orthogonal sphere has its center c in the affine hull and
// |p_i - c|^2 - w_i = r^2 for every vertex; the SIZE of the simplex is r^2
// (a vertex: -w). Sizes are squared radii and may be negative.
//
// Every size is a rational N / D of the input (D > 0). A Size gives it in
// doubles with a rigorous error bound, so that callers can sort millions of
// sizes in floating point and go exact only where intervals overlap; the
// comparisons here do exactly that: filter, then 128-bit integers when the
// input is small dyadic numbers (grids), then GMP. Exact ties return 0.
//
// A SizeKernel is cheap to create and owns its counters; it is not shared
// between threads (one per thread); its non-counting queries are const.
// The exact sizes themselves (GMP fractions) are internal: src/numerics/exact_size.hpp.
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "alpha/geometry.hpp"
#include "alpha/predicates.hpp"

namespace alpha {

// A simplex by the input indices of its 1..4 vertices, in any order.
// Degenerate simplices (repeated or affinely dependent points) have no
// size: the exact stage throws alpha::Error for them.
struct Simplex {
  std::array<Index, 4> v{kNone, kNone, kNone, kNone};
  int n = 0;  // number of vertices

  Simplex() = default;
  explicit Simplex(Index a) : v{a, kNone, kNone, kNone}, n(1) {}
  Simplex(Index a, Index b) : v{a, b, kNone, kNone}, n(2) {}
  Simplex(Index a, Index b, Index c) : v{a, b, c, kNone}, n(3) {}
  Simplex(Index a, Index b, Index c, Index d) : v{a, b, c, d}, n(4) {}
  explicit Simplex(std::span<const Index> vs);  // 1..4 indices
};

// A size in floating point: |value - exact size| <= error. The error is 0
// when value is exact (vertices) and +inf when the filter could not bound it
// (near-degenerate simplex, input outside the filter's range).
struct Size {
  double value = 0;
  double error = 0;
};

// Order of two sizes (or a size and an exact double) when their intervals
// decide it: -1, +1, or 0 for a certain tie (both exact and equal);
// kUndecided otherwise. Pure floating point, no counters.
inline constexpr int kUndecided = 2;
int compare_filtered(const Size& a, const Size& b);
int compare_filtered(const Size& a, double alpha_sq);

struct SizeStats {
  StageCounts compare;   // 'perturbed' counts exact ties (no perturbation is used)
  StageCounts attached;  // 'perturbed' counts points exactly on the sphere
  SizeStats& operator+=(const SizeStats& o) {
    compare += o.compare, attached += o.attached;
    return *this;
  }
};

class SizeKernel {
public:
  // `weights` may be null (unweighted: all weights zero). Arrays are borrowed.
  // small_integers: the caller's promise that every coordinate and weight
  // is an integer of magnitude at most 2^50 (all_small_integers checks
  // it); their ties are then decided in doubles without checking each
  // simplex's points (grids). in_filter_range: the promise that every
  // point is in the filter's range (all_in_filter_range checks it); no
  // value is then checked at each simplex.
  SizeKernel(const Vec3* points, const double* weights, bool small_integers = false, bool in_filter_range = false)
      : pts_(points), w_(weights), small_integers_(small_integers), in_filter_range_(in_filter_range) {}

  // The filtered size: allocation-free, tens of nanoseconds.
  Size size(const Simplex& s) const;
  // The double nearest to the exact size (ties to even).
  double rounded_size(const Simplex& s) const;
  // Center of the smallest orthogonal sphere, in floating point (not exact).
  Vec3 center(const Simplex& s) const;

  // Exact sign of size(a) - size(b), and of size(a) - alpha_sq (alpha_sq
  // NaN: alpha::Error).
  int compare(const Simplex& a, const Simplex& b);
  int compare(const Simplex& a, double alpha_sq);
  // The same with sizes the caller already computed (sa = size(a), ...).
  int compare(const Simplex& a, const Size& sa, const Simplex& b, const Size& sb);

  // Whether s (a vertex, edge or triangle) is attached by point q: q's power
  // distance |q - c|^2 - r^2 - w_q to the smallest orthogonal sphere of s is
  // strictly negative. Exact; a point on the sphere does not attach.
  bool attached(const Simplex& s, Index q);
  // Whether any of the points qs attaches s: attached(s, q) for each q in
  // turn, up to the first true, with the terms of s computed once.
  bool attached_any(const Simplex& s, std::span<const Index> qs);
  // size(s) when no point of qs attaches s, nothing when one does: a
  // triangle's size from the terms of its attached test.
  std::optional<Size> size_unless_attached(const Simplex& s, std::span<const Index> qs);

  const SizeStats& stats() const { return stats_; }
  const Vec3* points() const { return pts_; }
  const double* weights() const { return w_; }  // null: unweighted
  // Whether the points of `ids` are integers of magnitude at most 2^50
  // (true for all when promised).
  bool small_integers(std::span<const Index> ids) const;

private:
  const Vec3* pts_;
  const double* w_;
  bool small_integers_;
  bool in_filter_range_;
  SizeStats stats_;
  bool attached_any(const Simplex& s, std::span<const Index> qs, Size* size);  // size: set when false
};

// Whether every coordinate and weight (null: none) of n points is an
// integer of magnitude at most 2^50: SizeKernel's promise.
bool all_small_integers(const Vec3* points, const double* weights, std::size_t n);
// Whether every coordinate of n points is 0 or of magnitude in [2^-27,
// 2^99], and every weight (null: none) 0 or in [2^-107, 2^199]: then every
// difference the filter reads is in its range. SizeKernel's promise.
bool all_in_filter_range(const Vec3* points, const double* weights, std::size_t n);

}  // namespace alpha
