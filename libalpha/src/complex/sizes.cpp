// SPDX-License-Identifier: Apache-2.0
#include "alpha/sizes.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>

#include "alpha/error.hpp"
#include "numerics/dyadic.hpp"
#include "numerics/exact.hpp"
#include "numerics/exact_size.hpp"

namespace alpha {
namespace {

// ---------------------------------------------------------------------------
// The formulas, written once for every number type (filter, 128-bit, GMP).
//
// Relative to p0 (the vertex with the smallest index), with u_i = p_i - p0,
// dw_i = w_i - w0 and h_i = |u_i|^2 - dw_i, the center c = p0 + x solves
// 2 u_i.x = h_i with x in the span of the u_i, and r^2 = |x|^2 - w0:
//   edge      x = h0 u0 / (2L)        L = |u0|^2
//   triangle  x = (V x n) / (2A)      n = u0 x u1, A = |n|^2, V = h0 u1 - h1 u0
//   tetra     x = m / (2 det)         m = h0 u1xu2 + h1 u2xu0 + h2 u0xu1
// (check: u_i.(V x n) = h_i A, u_i.m = h_i det). As V lies in the plane,
// |V x n| = |V| |n|, so every size is r^2 = N / D with D > 0:
//   vertex    N = -w0                 D = 1
//   edge      N = h0^2 - 4 w0 L       D = 4 L
//   triangle  N = |V|^2 - 4 w0 A      D = 4 A
//   tetra     N = |m|^2 - 4 w0 det^2  D = 4 det^2
// Sums of squares keep N and D well conditioned; 4 is an exact scaling.

template <class T> struct Local {
  int k = 0;    // number of vertices - 1
  T u[3][3];    // u_i
  T dw[3];      // dw_i
  T w0;
};

template <class T> T dot(const T* a, const T* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

template <class T> void cross(const T* a, const T* b, T* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

// kWeighted false: every weight is 0, its terms are left out (the
// double-double rounding's; the filter keeps one code path).
template <bool kWeighted, class T> T lifted(const Local<T>& s, int i) {
  if constexpr (kWeighted) return dot(s.u[i], s.u[i]) - s.dw[i];
  return dot(s.u[i], s.u[i]);
}
// x - 4 w0 X, the last term of N.
template <bool kWeighted, class T> T minus_weight(const Local<T>& s, const T& x, const T& X) {
  if constexpr (kWeighted) return x - s.w0 * X * 4;
  return x;
}

// A triangle's normal n, A = |n|^2 and V (shared by its size and its power
// frame, so that both compute the same values).
template <bool kWeighted = true, class T> void triangle_plane(const Local<T>& s, T* n, T& A, T* V) {
  const auto& u = s.u;
  cross(u[0], u[1], n);
  A = dot(n, n);
  const T h0 = lifted<kWeighted>(s, 0), h1 = lifted<kWeighted>(s, 1);
  for (int a = 0; a < 3; ++a) V[a] = h0 * u[1][a] - h1 * u[0][a];
}
template <bool kWeighted = true, class T> void triangle_size(const Local<T>& s, const T& A, const T* V, T& N, T& D) {
  N = minus_weight<kWeighted>(s, dot(V, V), A);
  D = A * 4;
}

template <bool kWeighted = true, class T> void size_terms(const Local<T>& s, T& N, T& D) {
  const auto& u = s.u;
  if (s.k == 0) {
    N = T(0) - s.w0;
    D = T(1);
  } else if (s.k == 1) {
    const T L = dot(u[0], u[0]);
    const T h = kWeighted ? T(L - s.dw[0]) : L;
    N = minus_weight<kWeighted>(s, T(h * h), L);
    D = L * 4;
  } else if (s.k == 2) {
    T n[3], A, V[3];
    triangle_plane<kWeighted>(s, n, A, V);
    triangle_size<kWeighted>(s, A, V, N, D);
  } else {
    T c[3][3], m[3];
    cross(u[1], u[2], c[0]);
    cross(u[2], u[0], c[1]);
    cross(u[0], u[1], c[2]);
    const T det = dot(u[0], c[0]);
    const T h0 = lifted<kWeighted>(s, 0), h1 = lifted<kWeighted>(s, 1), h2 = lifted<kWeighted>(s, 2);
    for (int a = 0; a < 3; ++a) m[a] = h0 * c[0][a] + h1 * c[1][a] + h2 * c[2][a];
    const T det2 = det * det;
    N = minus_weight<kWeighted>(s, dot(m, m), det2);
    D = det2 * 4;
  }
}

// Power distance of q to the smallest sphere of s (a vertex, edge or
// triangle), times the positive denominator `den` (1, L or A): with
// v = q - p0 and dq = w0 - w_q, pi = |v|^2 + dq - 2 v.x. The terms that
// depend on s alone form its frame, computed once for many q.
template <class T> struct PowerFrame {
  T den;    // 1, L or A
  T h;      // edge: h0
  T V[3];   // triangle: V (for its size)
  T Vn[3];  // triangle: V x n
};

template <class T> PowerFrame<T> power_frame(const Local<T>& s) {
  PowerFrame<T> f;
  const auto& u = s.u;
  if (s.k == 0) {
    f.den = T(1);
  } else if (s.k == 1) {
    f.den = dot(u[0], u[0]);
    f.h = f.den - s.dw[0];
  } else {
    T n[3];
    triangle_plane(s, n, f.den, f.V);
    cross(f.V, n, f.Vn);
  }
  return f;
}

template <class T> T power_terms(const Local<T>& s, const PowerFrame<T>& f, const T* v, const T& dq) {
  const T g = dot(v, v) + dq;
  if (s.k == 0) return g;
  if (s.k == 1) return f.den * g - f.h * dot(s.u[0], v);
  return f.den * g - dot(v, f.Vn);
}

// ---------------------------------------------------------------------------
// Filter: each value carries its permanent p (the same expression with
// absolute values and every '-' read as '+').
//
// Error analysis (Higham ch. 3; u = 2^-53, gamma_d = d u / (1 - d u)): give
// each leaf a level d (1 for a rounded difference p_i - p0 or w_i - w0, 0
// for an input w0), an op A+-B the level max(dA, dB) + 1 and A*B the level
// dA + dB + 1. By induction |fl(E) - E| <= gamma_d(E) perm(E). The levels of
// the code above (written left to right exactly as counted):
//   edge      L 5, h 6, N 14, D 5
//   triangle  n 4, A 11, h 6, V 9, N 22, D 11
//   tetra     c 4, det 8, D 17, h 6, m 13, N 30
//   power     vertex 6; edge 13; triangle (V x n 15, v.(V x n) 19) 20
// We use (d + 1) u times the computed permanent: the extra u covers gamma_d
// vs d u, the permanent being evaluated in doubles from rounded leaves
// (factor at most (1+u)^40), and underflow (below).
//
// Range: nonzero lengths (coordinate differences) must lie in
// [2^-80, 2^100] and nonzero squared lengths (weights) in [2^-160, 2^200].
// Then permanents stay below 2^820 (no overflow), and every nonzero
// permanent of a product of degree <= 8 exceeds 2^-640, so an underflowing
// product errs by less than 2^-1075 < 2^-435 of its permanent: negligible
// next to u. Outside the range the filter gives up (error = +inf).
// Checked once for all points (all_in_filter_range) instead of at each
// leaf: coordinates 0 or of magnitude in [2^-27, 2^99] are multiples of
// 2^-79, so their nonzero differences lie in [2^-79, 2^100] (rounding
// is monotone and both ends are doubles); weights 0 or in [2^-107, 2^199]
// likewise give differences in [2^-159, 2^200].
constexpr double kU = 0x1p-53;
constexpr double kMinLength = 0x1p-80, kMaxLength = 0x1p100;
constexpr double kMinArea = 0x1p-160, kMaxArea = 0x1p200;
constexpr double kSizeN[4] = {0, 15 * kU, 23 * kU, 31 * kU};
constexpr double kSizeD[4] = {0, 6 * kU, 12 * kU, 18 * kU};
constexpr double kPower[3] = {7 * kU, 14 * kU, 21 * kU};
// The few roundings in the bound computations themselves: a relative 16 u
// and, for results in the subnormal range, an absolute 2^-1070.
constexpr double kSlack = 1 + 0x1p-49;
constexpr double kTiny = 0x1p-1070;

struct Approx {
  double v = 0, p = 0;
  Approx() = default;
  Approx(int i) : v(i), p(std::abs(i)) {}
  Approx(double value, double perm) : v(value), p(perm) {}
};
Approx operator+(const Approx& a, const Approx& b) { return {a.v + b.v, a.p + b.p}; }
Approx operator-(const Approx& a, const Approx& b) { return {a.v - b.v, a.p + b.p}; }
Approx operator*(const Approx& a, const Approx& b) { return {a.v * b.v, a.p * b.p}; }

bool in_range(double x, double lo, double hi) {
  const double a = std::fabs(x);
  return (a == 0) | ((a >= lo) & (a <= hi));  // false for NaN and inf; no branches
}
// A leaf, checked unless every point is known to be in range.
template <bool kCheck = true> Approx length_leaf(double x, bool& ok) {
  if constexpr (kCheck) ok &= in_range(x, kMinLength, kMaxLength);
  return {x, std::fabs(x)};
}
template <bool kCheck = true> Approx area_leaf(double x, bool& ok) {
  if constexpr (kCheck) ok &= in_range(x, kMinArea, kMaxArea);
  return {x, std::fabs(x)};
}

// Integer input (grids) decided in doubles, where the filter cannot decide
// a tie: when every coordinate and weight read is an integer of magnitude
// at most 2^50, the leaves (differences) are exact integers, and so is every
// value computed from them while its permanent stays below 2^53 (a
// sub-expression with a larger permanent could only sit under an exactly
// zero factor, whose leaves are all zero). Rounding is monotone, so a
// computed permanent below 2^53 means that no step rounded.
constexpr double kExactPermanent = 0x1p53;
bool small_integer(double x) { return std::fabs(x) <= 0x1p50 && exact::is_integer(x); }
bool small_integer_point(const Vec3* pts, const double* w, std::size_t i) {
  return small_integer(pts[i].x) & small_integer(pts[i].y) & small_integer(pts[i].z) & (!w || small_integer(w[i]));
}

// ---------------------------------------------------------------------------
// Exact evaluation. Doubles are dyadic m 2^e; one common unit 2^unit for
// coordinates and 2^(2 unit) for weights makes all values of a call integers
// (same idea as exact.cpp). 128-bit integers that detect overflow first,
// GMP when any step overflowed.


struct Wide {
  i128 v = 0;
  bool ok = true;  // false once any step overflowed
  Wide() = default;
  Wide(int i) : v(i) {}
  Wide(i128 value, bool good) : v(value), ok(good) {}
};
Wide operator+(const Wide& a, const Wide& b) {
  i128 r;
  const bool o = __builtin_add_overflow(a.v, b.v, &r);
  return {r, a.ok && b.ok && !o};
}
Wide operator-(const Wide& a, const Wide& b) {
  i128 r;
  const bool o = __builtin_sub_overflow(a.v, b.v, &r);
  return {r, a.ok && b.ok && !o};
}
Wide operator*(const Wide& a, const Wide& b) {
  i128 r;
  const bool o = __builtin_mul_overflow(a.v, b.v, &r);
  return {r, a.ok && b.ok && !o};
}

bool certainly_zero(const Wide& x) { return x.ok && x.v == 0; }
bool certainly_zero(const mpz_class& x) { return x == 0; }

// d in units of 2^unit (the shift only for nonzero d: a zero's exponent is
// INT_MAX).
template <class T> T to_int(const Dyadic& d, int unit);
template <> Wide to_int<Wide>(const Dyadic& d, int unit) {
  if (d.m == 0) return Wide(0);
  const int shift = d.e - unit;
  const int bits = shift + static_cast<int>(std::bit_width(static_cast<std::uint64_t>(std::llabs(d.m))));
  if (bits > 120) return {0, false};
  return {i128(d.m) << shift, true};
}
template <> mpz_class to_int<mpz_class>(const Dyadic& d, int unit) {
  mpz_class r(static_cast<long>(d.m));
  if (d.m != 0) r <<= static_cast<mp_bitcnt_t>(d.e - unit);
  return r;
}

// The points (and alpha) of one exact evaluation, in one common unit.
struct Scaled {
  Dyadic c[9][3], w[9];
  Dyadic alpha;  // a squared length to compare with, if any
  int n = 0;
  int unit = 0;  // coordinates in units of 2^unit, squared lengths of 2^(2 unit)

  void add(const Vec3& p, double weight) {
    c[n][0] = split(p.x), c[n][1] = split(p.y), c[n][2] = split(p.z);
    w[n++] = split(weight);
  }
  void finish() {
    int ec = INT_MAX, ew = alpha.e;
    for (int i = 0; i < n; ++i) {
      for (const Dyadic& d : c[i]) ec = std::min(ec, d.e);
      ew = std::min(ew, w[i].e);
    }
    unit = std::min(ec, ew == INT_MAX ? INT_MAX : ew >> 1);  // >> floors
    if (unit == INT_MAX) unit = 0;                            // all zero
  }
  template <class T> T coord(int i, int a) const { return to_int<T>(c[i][a], unit); }
  template <class T> T weight(int i) const { return to_int<T>(w[i], 2 * unit); }
  template <class T> T alpha_value() const { return to_int<T>(alpha, 2 * unit); }

  // The simplex of k + 1 points stored from slot `first` on.
  template <class T> Local<T> local(int first, int k) const {
    Local<T> s;
    s.k = k;
    s.w0 = weight<T>(first);
    for (int i = 0; i < k; ++i) {
      for (int a = 0; a < 3; ++a) s.u[i][a] = coord<T>(first + 1 + i, a) - coord<T>(first, a);
      s.dw[i] = weight<T>(first + 1 + i) - s.w0;
    }
    return s;
  }
  template <class T> void size(int first, int k, T& N, T& D) const {
    size_terms(local<T>(first, k), N, D);
    if (certainly_zero(D)) fail("sizes: degenerate simplex (affinely dependent points)", ErrorKind::Misuse);
  }
};

mpz_class to_mpz(i128 v) {
  const bool negative = v < 0;
  const u128 m = negative ? -static_cast<u128>(v) : static_cast<u128>(v);
  mpz_class r(static_cast<unsigned long>(m >> 64));
  r <<= 64;
  r += static_cast<unsigned long>(m & ~std::uint64_t(0));
  return negative ? mpz_class(-r) : r;
}

// Sign of f(T) evaluated in 128-bit integers, or in GMP if that overflowed.
template <class F> int exact_sign(F f) {
  const Wide w = f(Wide{});
  if (w.ok) return (w.v > 0) - (w.v < 0);
  return sgn(f(mpz_class{}));
}

// The double nearest to q, ties to even (mpq's get_d truncates).
double nearest_double(const mpq_class& q) {
  const double t = q.get_d();
  if (!std::isfinite(t) || mpq_class(t) == q) return t;
  const double away = std::nextafter(t, q > 0 ? HUGE_VAL : -HUGE_VAL);
  const mpq_class tq(t);
  mpq_class mid;
  if (std::isfinite(away))
    mid = (tq + mpq_class(away)) / 2;
  else
    mid = tq + (tq - mpq_class(std::nextafter(t, 0.0))) / 2;
  const int c = cmp(abs(q), abs(mid));
  if (c != 0) return c < 0 ? t : away;
  return (std::bit_cast<std::uint64_t>(t) & 1) == 0 ? t : away;
}

int sign(double x) { return (x > 0) - (x < 0); }

}  // namespace

Simplex::Simplex(std::span<const Index> vs) : n(static_cast<int>(vs.size())) {
  if (n < 1 || n > 4) fail("Simplex: needs 1 to 4 vertices", ErrorKind::Misuse);
  std::copy(vs.begin(), vs.end(), v.begin());
}

int compare_filtered(const Size& a, const Size& b) {
  if (a.error == 0 && b.error == 0) return sign(a.value - b.value);  // exact: fl(a-b) has the sign of a-b
  // With gap = fl(a-b) and tol = fl(fl(ea+eb) (1+2^-50)), gap > tol implies
  // a - b > ea + eb: the slack outweighs the three roundings.
  const double gap = a.value - b.value;
  const double tol = (a.error + b.error) * (1 + 0x1p-50);
  if (gap > tol) return 1;
  if (gap < -tol) return -1;
  return kUndecided;  // also for NaN or infinite bounds
}

int compare_filtered(const Size& a, double alpha_sq) { return compare_filtered(a, Size{alpha_sq, 0}); }

bool all_small_integers(const Vec3* points, const double* weights, std::size_t n) {
  bool all = true;
  for (std::size_t i = 0; i < n; ++i) all &= small_integer_point(points, weights, i);
  return all;
}

bool all_in_filter_range(const Vec3* points, const double* weights, std::size_t n) {
  constexpr double kLow = 0x1p-27, kHigh = 0x1p99, kLowWeight = 0x1p-107, kHighWeight = 0x1p199;  // see the filter
  bool all = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = points[i];
    all &= in_range(p.x, kLow, kHigh) & in_range(p.y, kLow, kHigh) & in_range(p.z, kLow, kHigh) &
           (!weights || in_range(weights[i], kLowWeight, kHighWeight));
  }
  return all;
}

bool SizeKernel::small_integers(std::span<const Index> ids) const {
  if (small_integers_) return true;
  bool all = true;
  for (const Index i : ids) all &= small_integer_point(pts_, w_, i);
  return all;
}

namespace {

// The simplex with sorted indices: p0 is the smallest index, so that a
// simplex gives the same doubles whatever the order of its vertices.
// Unused slots are set to kNone, the largest index, and all four sorted by
// a branch-free network: random vertex orders cost no mispredictions.
Simplex sorted(const Simplex& s) {
  if (s.n < 1 || s.n > 4) fail("sizes: a simplex has 1 to 4 vertices", ErrorKind::Misuse);
  Simplex r = s;
  for (int i = 1; i < 4; ++i) r.v[i] = i < s.n ? s.v[i] : kNone;
  auto order = [&](int i, int j) {
    const Index a = r.v[i], b = r.v[j];
    const Index swap = (a ^ b) & (0u - Index(b < a));  // xor mask, 0 when in order
    r.v[i] = a ^ swap, r.v[j] = b ^ swap;
  };
  order(0, 1), order(2, 3), order(0, 2), order(1, 3), order(1, 2);
  return r;
}

}  // namespace

namespace {

// The filter's local frame of a sorted simplex; ok turns false when a leaf
// is out of the filter's range (with kCheck; without, the caller knows
// every point in range).
template <bool kCheck> Local<Approx> approx_local(const Vec3* pts, const double* w, const Simplex& s, bool& ok) {
  const double w0 = w ? w[s.v[0]] : 0.0;
  Local<Approx> l;
  l.k = s.n - 1;
  l.w0 = area_leaf<kCheck>(w0, ok);
  const Vec3& p0 = pts[s.v[0]];
  for (int i = 0; i < l.k; ++i) {
    const Vec3& p = pts[s.v[i + 1]];
    l.u[i][0] = length_leaf<kCheck>(p.x - p0.x, ok);
    l.u[i][1] = length_leaf<kCheck>(p.y - p0.y, ok);
    l.u[i][2] = length_leaf<kCheck>(p.z - p0.z, ok);
    l.dw[i] = area_leaf<kCheck>(w ? w[s.v[i + 1]] - w0 : 0.0, ok);
  }
  return l;
}
Local<Approx> approx_local(const Vec3* pts, const double* w, const Simplex& s, bool& ok, bool in_filter_range) {
  return in_filter_range ? approx_local<false>(pts, w, s, ok) : approx_local<true>(pts, w, s, ok);
}

}  // namespace

namespace {

// The filtered size N / D of a simplex of k + 1 vertices (k > 0), whose
// leaves were in range (ok) or not. On small integers (`integers`: the
// whole input) N and D are exact below 2^53 (see small_fraction); a quotient
// the double holds exactly (fma: N - value D is exact) then has no error,
// and equal such sizes need no exact comparison.
Size filtered_size(const Approx& N, const Approx& D, int k, bool ok, bool integers) {
  double value = N.v / D.v;
  if (integers && N.p < kExactPermanent && D.p < kExactPermanent && D.v != 0 && std::fma(value, D.v, -N.v) == 0)
    return {value, 0};
  if (std::isnan(value)) value = HUGE_VAL;  // D = 0: keep values sortable
  const double eN = kSizeN[k] * N.p, eD = kSizeD[k] * D.p;
  if (!ok || !(D.v > eD)) return {value, HUGE_VAL};
  // N/D - N'/D' = (N - N')/D' + N (1/D - 1/D') for the exact N', D' with
  // D' >= D - eD > 0; then the rounding of the quotient itself.
  const double bound = (eN + std::fabs(N.v) * (eD / D.v)) / (D.v - eD) + kU * std::fabs(value);
  return {value, bound * kSlack + kTiny};
}

}  // namespace

Size SizeKernel::size(const Simplex& simplex) const {
  const Simplex s = sorted(simplex);
  if (s.n == 1) return {w_ ? -w_[s.v[0]] : -0.0, 0};
  bool ok = true;
  const Local<Approx> l = approx_local(pts_, w_, s, ok, in_filter_range_);
  Approx N, D;
  size_terms(l, N, D);
  return filtered_size(N, D, l.k, ok, small_integers_);
}

Vec3 SizeKernel::center(const Simplex& simplex) const {
  const Simplex s = sorted(simplex);
  const Vec3& p0 = pts_[s.v[0]];
  const int k = s.n - 1;
  if (k == 0) return p0;
  const double w0 = w_ ? w_[s.v[0]] : 0.0;
  double u[3][3], h[3];
  for (int i = 0; i < k; ++i) {
    const Vec3& p = pts_[s.v[i + 1]];
    u[i][0] = p.x - p0.x, u[i][1] = p.y - p0.y, u[i][2] = p.z - p0.z;
    h[i] = dot(u[i], u[i]) - (w_ ? w_[s.v[i + 1]] - w0 : 0.0);
  }
  double x[3], den;  // x / den, see the formulas at the top
  if (k == 1) {
    for (int a = 0; a < 3; ++a) x[a] = h[0] * u[0][a];
    den = 2 * dot(u[0], u[0]);
  } else if (k == 2) {
    double n[3], V[3];
    cross(u[0], u[1], n);
    for (int a = 0; a < 3; ++a) V[a] = h[0] * u[1][a] - h[1] * u[0][a];
    cross(V, n, x);
    den = 2 * dot(n, n);
  } else {
    double c[3][3];
    cross(u[1], u[2], c[0]);
    cross(u[2], u[0], c[1]);
    cross(u[0], u[1], c[2]);
    for (int a = 0; a < 3; ++a) x[a] = h[0] * c[0][a] + h[1] * c[1][a] + h[2] * c[2][a];
    den = 2 * dot(u[0], c[0]);
  }
  return {p0.x + x[0] / den, p0.y + x[1] / den, p0.z + x[2] / den};
}

ExactSize exact_fraction(const SizeKernel& kernel, const Simplex& simplex) {
  const Simplex s = sorted(simplex);
  Scaled in;
  const Vec3* points = kernel.points();
  const double* weights = kernel.weights();
  for (int i = 0; i < s.n; ++i) in.add(points[s.v[i]], weights ? weights[s.v[i]] : 0.0);
  in.finish();
  ExactSize out;
  out.unit = in.unit;  // sizes are squared lengths: of 4^unit
  // Small dyadic input (grids) fits 128 bits: no GMP arithmetic.
  Wide num, den;
  in.size(0, s.n - 1, num, den);
  if (num.ok && den.ok) {
    out.num = to_mpz(num.v), out.den = to_mpz(den.v);
    return out;
  }
  in.size(0, s.n - 1, out.num, out.den);
  return out;
}

mpq_class exact_size(const SizeKernel& kernel, const Simplex& simplex) {
  const ExactSize f = exact_fraction(kernel, simplex);
  mpq_class q(f.num, f.den);
  q.canonicalize();
  if (f.unit >= 0)
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(2 * f.unit));
  else
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-2 * f.unit));
  return q;
}

std::optional<SmallFraction> small_fraction(const SizeKernel& kernel, const Simplex& simplex) {
  const Simplex s = sorted(simplex);
  if (!kernel.small_integers(std::span<const Index>(s.v.data(), std::size_t(s.n)))) return std::nullopt;
  bool ok = true;  // unused: such integers neither over- nor underflow
  const Local<Approx> l = approx_local<false>(kernel.points(), kernel.weights(), s, ok);
  Approx N, D;
  size_terms(l, N, D);
  if (!(N.p < kExactPermanent && D.p < kExactPermanent)) return std::nullopt;
  if (D.v == 0) fail("sizes: degenerate simplex (affinely dependent points)", ErrorKind::Misuse);
  return SmallFraction{std::int64_t(N.v), std::int64_t(D.v)};
}

int compare_small(const SmallFraction& a, const SmallFraction& b) {
  const i128 left = i128(a.num) * b.den, right = i128(b.num) * a.den;  // D > 0; below 2^106
  return (left > right) - (left < right);
}

int compare_exact(const ExactSize& a, const ExactSize& b) {
  // a - b has the sign of (na db 4^ua - nb da 4^ub) * sign(da db).
  mpz_class left = a.num * b.den, right = b.num * a.den;
  const int shift = 2 * (a.unit - b.unit);
  if (shift > 0) mpz_mul_2exp(left.get_mpz_t(), left.get_mpz_t(), mp_bitcnt_t(shift));
  if (shift < 0) mpz_mul_2exp(right.get_mpz_t(), right.get_mpz_t(), mp_bitcnt_t(-shift));
  return cmp(left, right) * sgn(a.den) * sgn(b.den);
}

double rounded_exact(const SizeKernel& kernel, const Simplex& s) {
  const Size f = kernel.size(s);
  if (f.error == 0) return f.value;
  // From the unreduced fraction by one integer division (no gcd): the
  // quotient's 54-56 leading bits and a sticky remainder round correctly.
  const ExactSize x = exact_fraction(kernel, s);
  const int sign = sgn(x.num) * sgn(x.den);
  if (sign == 0) return 0.0;
  mpz_class a = abs(x.num), b = abs(x.den), q, r;
  const long k = 55 - (long(mpz_sizeinbase(a.get_mpz_t(), 2)) - long(mpz_sizeinbase(b.get_mpz_t(), 2)));
  if (k > 0) mpz_mul_2exp(a.get_mpz_t(), a.get_mpz_t(), mp_bitcnt_t(k));
  if (k < 0) mpz_mul_2exp(b.get_mpz_t(), b.get_mpz_t(), mp_bitcnt_t(-k));
  mpz_tdiv_qr(q.get_mpz_t(), r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  // a / b = (q + r / b) 2^-k with 2^54 <= q < 2^56.
  const std::uint64_t bits = mpz_get_ui(q.get_mpz_t());
  const int extra = std::bit_width(bits) - 53;
  std::uint64_t m = bits >> extra;
  const std::uint64_t rest = bits & ((std::uint64_t(1) << extra) - 1), half = std::uint64_t(1) << (extra - 1);
  if (rest > half || (rest == half && (r != 0 || (m & 1)))) ++m;
  const long exponent = 2L * x.unit - k + extra;
  // Below the normal range ldexp would round a second time.
  if (exponent + 53 < -1021) return nearest_double(exact_size(kernel, s));
  return sign * std::ldexp(double(m), int(std::clamp(exponent, -2000L, 2000L)));
}


namespace {

// ---------------------------------------------------------------------------
// The nearest double without GMP: N and D in double-double arithmetic
// (about 106 bits), then the side of the exact N / D against the midpoints
// around a candidate double, each a sign with a rigorous bound.
//
// A Twin is hi + lo with |lo| <= ulp(hi) / 2, plus its permanent p as in the
// filter. The operations are those of Joldes, Muller & Popescu (ACM TOMS
// 2017): AccurateDWPlusDW errs by less than 3u^2 of its result, DWTimesDW1
// by less than 7u^2; we use u2 = 16u^2 for either. The leaves (coordinate
// and weight differences) are exact here (two_diff), so the levels of the
// filter analysis restart at 0:
//   edge N 10, D 4; triangle N 16, D 8; tetra N 22, D 12
// and |Twin(E) - E| <= (level + 1) u2 perm(E). Within the filter's range
// a product's underflow errs by less than 2^-435 of its permanent, well
// under u2; Dekker's product cannot overflow below 2^996.
constexpr double kU2 = 16 * kU * kU;
constexpr double kTwinN[4] = {0, 11 * kU2, 17 * kU2, 23 * kU2};
constexpr double kTwinD[4] = {0, 5 * kU2, 9 * kU2, 13 * kU2};
// The permanents' own roundings (at most 60 factors 1 + u) and the few in
// the bounds.
constexpr double kTwinSlack = 1 + 0x1p-40;

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}
void fast_two_sum(double a, double b, double& s, double& e) {  // |a| >= |b| or a == 0
  s = a + b;
  e = b - (s - a);
}
void veltkamp(double a, double& high, double& low) {
  const double t = a * 134217729.0;  // 2^27 + 1
  high = t - (t - a);
  low = a - high;
}
// p + e = a b exactly: with a fused multiply-add (2 operations) or Dekker's
// product (17); the same p and e, the error of a product being unique.
template <bool kFma> void two_prod(double a, double b, double& p, double& e) {
  p = a * b;
  if constexpr (kFma) {
    e = std::fma(a, b, -p);
  } else {
    double ah, al, bh, bl;
    veltkamp(a, ah, al);
    veltkamp(b, bh, bl);
    e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
  }
}

template <bool kFma> struct TwinOf {
  double hi = 0, lo = 0, p = 0;
  TwinOf() = default;
  TwinOf(int i) : hi(i), p(std::abs(i)) {}
  TwinOf(double h, double l, double perm) : hi(h), lo(l), p(perm) {}

  friend TwinOf operator+(const TwinOf& x, const TwinOf& y) {
    double sh, sl, th, tl, vh, vl, zh, zl;
    two_sum(x.hi, y.hi, sh, sl);
    two_sum(x.lo, y.lo, th, tl);
    fast_two_sum(sh, sl + th, vh, vl);
    fast_two_sum(vh, tl + vl, zh, zl);
    return {zh, zl, x.p + y.p};
  }
  friend TwinOf operator-(const TwinOf& x, const TwinOf& y) { return x + TwinOf(-y.hi, -y.lo, y.p); }
  friend TwinOf operator*(const TwinOf& x, const TwinOf& y) {
    double ch, cl, zh, zl;
    two_prod<kFma>(x.hi, y.hi, ch, cl);
    fast_two_sum(ch, cl + (x.hi * y.lo + x.lo * y.hi), zh, zl);
    return {zh, zl, x.p * y.p};
  }
};

// a - b exactly, as a leaf.
template <bool kFma> TwinOf<kFma> exact_difference(double a, double b) {
  double s, e;
  two_sum(a, -b, s, e);
  return {s, e, std::fabs(s) + std::fabs(e)};
}

// Sign of N - (c + h) D for the exact N, D within eN, eD of the Twins
// (D > 0; h a power of two with h D normal), or 0 when not certain.
template <bool kFma>
int midpoint_side(const TwinOf<kFma>& N, double eN, const TwinOf<kFma>& D, double eD, double c, double h) {
  using Twin = TwinOf<kFma>;
  double p, e;
  two_prod<kFma>(c, D.hi, p, e);
  const double t = c * D.lo;  // errs by at most u |t|
  const Twin a = N - Twin(p, e, 0);
  const Twin b = a - Twin(t, 0, 0);
  const Twin r = b - Twin(h * D.hi, h * D.lo, 0);
  const double ops = kU2 * (std::fabs(a.hi) + std::fabs(b.hi) + std::fabs(r.hi));
  const double bound = (eN + std::fabs(c + h) * eD + kU * std::fabs(t) + ops) * kTwinSlack + kTiny;
  if (r.hi > bound) return 1;
  if (r.hi < -bound) return -1;
  return 0;
}

bool in_twin_range(double x, double lo, double hi) { return std::fabs(x) >= lo && std::fabs(x) <= hi; }

// The neighbouring doubles of a normal c (nextafter is a library call).
double next_up(double c) {
  const auto bits = std::bit_cast<std::uint64_t>(c);
  return std::bit_cast<double>(c > 0 ? bits + 1 : bits - 1);
}
double next_down(double c) {
  const auto bits = std::bit_cast<std::uint64_t>(c);
  return std::bit_cast<double>(c > 0 ? bits - 1 : bits + 1);
}

template <bool kFma> std::optional<double> rounded_twin(const SizeKernel& kernel, const Simplex& simplex) {
  using Twin = TwinOf<kFma>;
  const Simplex s = sorted(simplex);
  if (s.n < 2) return std::nullopt;
  const Vec3* pts = kernel.points();
  const double* w = kernel.weights();
  // The filter's leaves (exact here), in the filter's range.
  bool ok = true;
  Local<Twin> l;
  l.k = s.n - 1;
  const double w0 = w ? w[s.v[0]] : 0.0;
  l.w0 = Twin(area_leaf(w0, ok).v, 0, std::fabs(w0));
  const Vec3& p0 = pts[s.v[0]];
  for (int i = 0; i < l.k; ++i) {
    const Vec3& q = pts[s.v[i + 1]];
    l.u[i][0] = exact_difference<kFma>(q.x, p0.x);
    l.u[i][1] = exact_difference<kFma>(q.y, p0.y);
    l.u[i][2] = exact_difference<kFma>(q.z, p0.z);
    l.dw[i] = w ? exact_difference<kFma>(w[s.v[i + 1]], w0) : Twin(0);
    for (int a = 0; a < 3; ++a) length_leaf(l.u[i][a].hi, ok);
    area_leaf(l.dw[i].hi, ok);
  }
  if (!ok) return std::nullopt;
  Twin N, D;
  if (w) size_terms(l, N, D);
  else size_terms<false>(l, N, D);
  const double eN = kTwinN[l.k] * N.p * kTwinSlack, eD = kTwinD[l.k] * D.p * kTwinSlack;
  // D certainly positive, and the candidates and h D away from under- and overflow.
  if (!(D.hi - eD > 0) || !in_twin_range(D.hi, 0x1p-500, 0x1p500)) return std::nullopt;
  double c = N.hi / D.hi;
  for (int step = 0; step < 4 && in_twin_range(c, 0x1p-400, 0x1p400); ++step) {
    const double up = next_up(c), down = next_down(c);
    const int above = midpoint_side(N, eN, D, eD, c, (up - c) / 2);
    const int below = midpoint_side(N, eN, D, eD, c, (down - c) / 2);
    if (above < 0 && below > 0) return c;
    if (above > 0) c = up;
    else if (below < 0) c = down;
    else return std::nullopt;  // near a midpoint (or on it: a tie)
  }
  return std::nullopt;
}

// Where the instruction set lacks FMA (x86-64 before AVX2), a clone with it
// for the processors that have one: everything inlined (flatten) so that
// std::fma is the instruction, not a library call. sizes.cpp is compiled
// with -ffp-contract=off, so that no other product and sum fuses there.
#if defined(__FMA__) || defined(__aarch64__)
constexpr bool kNativeFma = true;
#else
constexpr bool kNativeFma = false;
#endif
#if !defined(__FMA__) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ALPHA_FMA_CLONE 1
__attribute__((target("fma"), flatten)) std::optional<double> rounded_fma(const SizeKernel& kernel,
                                                                           const Simplex& s) {
  return rounded_twin<true>(kernel, s);
}
#endif

}  // namespace

std::optional<double> rounded_filtered(const SizeKernel& kernel, const Simplex& simplex, bool fma) {
  if (!fma) return rounded_twin<false>(kernel, simplex);
#ifdef ALPHA_FMA_CLONE
  static const bool has_fma = __builtin_cpu_supports("fma");
  if (has_fma) return rounded_fma(kernel, simplex);
#endif
  return rounded_twin<kNativeFma>(kernel, simplex);
}

double SizeKernel::rounded_size(const Simplex& s) const {
  if (const std::optional<double> r = rounded_filtered(*this, s)) return *r;
  return rounded_exact(*this, s);
}

int SizeKernel::compare(const Simplex& a, const Simplex& b) { return compare(a, size(a), b, size(b)); }

int SizeKernel::compare(const Simplex& a, const Size& sa, const Simplex& b, const Size& sb) {
  const int f = compare_filtered(sa, sb);
  if (f != kUndecided) {
    ++stats_.compare.filtered;
    return f;
  }
  const Simplex A = sorted(a), B = sorted(b);
  Scaled in;
  for (int i = 0; i < A.n; ++i) in.add(pts_[A.v[i]], w_ ? w_[A.v[i]] : 0.0);
  for (int i = 0; i < B.n; ++i) in.add(pts_[B.v[i]], w_ ? w_[B.v[i]] : 0.0);
  in.finish();
  // N_A / D_A - N_B / D_B has the sign of N_A D_B - N_B D_A (D > 0).
  const int e = exact_sign([&](auto tag) {
    using T = decltype(tag);
    T na, da, nb, db;
    in.size(0, A.n - 1, na, da);
    in.size(A.n, B.n - 1, nb, db);
    return T(na * db - nb * da);
  });
  ++(e != 0 ? stats_.compare.exact : stats_.compare.perturbed);
  return e;
}

int SizeKernel::compare(const Simplex& a, double alpha_sq) {
  if (std::isnan(alpha_sq)) fail("sizes: alpha_sq is not a number", ErrorKind::Misuse);
  if (std::isinf(alpha_sq)) {
    ++stats_.compare.filtered;
    return alpha_sq > 0 ? -1 : 1;
  }
  const int f = compare_filtered(size(a), alpha_sq);
  if (f != kUndecided) {
    ++stats_.compare.filtered;
    return f;
  }
  const Simplex A = sorted(a);
  Scaled in;
  for (int i = 0; i < A.n; ++i) in.add(pts_[A.v[i]], w_ ? w_[A.v[i]] : 0.0);
  in.alpha = split(alpha_sq);
  in.finish();
  const int e = exact_sign([&](auto tag) {
    using T = decltype(tag);
    T n, d;
    in.size(0, A.n - 1, n, d);
    return T(n - d * in.alpha_value<T>());
  });
  ++(e != 0 ? stats_.compare.exact : stats_.compare.perturbed);
  return e;
}

bool SizeKernel::attached(const Simplex& s, Index q) { return attached_any(s, std::span<const Index>(&q, 1)); }

bool SizeKernel::attached_any(const Simplex& s, std::span<const Index> qs) { return attached_any(s, qs, nullptr); }

std::optional<Size> SizeKernel::size_unless_attached(const Simplex& s, std::span<const Index> qs) {
  Size z;
  if (attached_any(s, qs, &z)) return std::nullopt;
  return z;
}

namespace {

// Unweighted edge ab and point q: the power distance of q to the edge's
// smallest sphere is (a - q).(b - q). Its filter (leaves level 1, products
// 3, sums 5: 6 u times the permanent, no range check: an over- or
// underflow gives an infinite bound or stays under kTiny) and, for integer
// input, its exact value. kUndecided when neither decides.
int edge_power_sign(const SizeKernel& kernel, Index a, Index b, Index q) {
  const Vec3* pts = kernel.points();
  const Vec3 &pa = pts[a], &pb = pts[b], &pq = pts[q];
  const double x[3] = {pa.x - pq.x, pa.y - pq.y, pa.z - pq.z}, y[3] = {pb.x - pq.x, pb.y - pq.y, pb.z - pq.z};
  const double value = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  const double perm = std::fabs(x[0] * y[0]) + std::fabs(x[1] * y[1]) + std::fabs(x[2] * y[2]);
  const double e = 6 * kU * perm * kSlack + kTiny;
  if (value > e) return 1;
  if (value < -e) return -1;
  const Index ids[3] = {a, b, q};
  if (perm < kExactPermanent && kernel.small_integers(ids)) return sign(value);
  return kUndecided;
}

}  // namespace

bool SizeKernel::attached_any(const Simplex& simplex, std::span<const Index> qs, Size* size) {
  const auto distinct = [&](Index a, Index b) {
    return pts_[a].x != pts_[b].x || pts_[a].y != pts_[b].y || pts_[a].z != pts_[b].z;
  };
  if (simplex.n == 2 && !w_ && distinct(simplex.v[0], simplex.v[1])) {  // else the general code throws
    std::size_t k = 0;
    for (; k < qs.size(); ++k) {
      const int sign = edge_power_sign(*this, simplex.v[0], simplex.v[1], qs[k]);
      if (sign == kUndecided) break;  // the general code below decides it
      ++(sign != 0 ? stats_.attached.filtered : stats_.attached.perturbed);
      if (sign < 0) return true;
    }
    if (k == qs.size()) {
      if (size) *size = this->size(simplex);
      return false;
    }
    qs = qs.subspan(k);
  }
  const Simplex s = sorted(simplex);
  if (s.n > 3) fail("attached: only vertices, edges and triangles can be attached", ErrorKind::Misuse);
  bool ok = true;
  const Local<Approx> l = approx_local(pts_, w_, s, ok, in_filter_range_);
  const PowerFrame<Approx> frame = power_frame(l);
  const double w0 = w_ ? w_[s.v[0]] : 0.0;
  const Vec3& p0 = pts_[s.v[0]];
  int integers = -1;  // whether s's points are small integers, once asked
  for (const Index q : qs) {
    const double wq = w_ ? w_[q] : 0.0;
    const Vec3& pq = pts_[q];
    bool ok_q = ok;
    const double d[4] = {pq.x - p0.x, pq.y - p0.y, pq.z - p0.z, w0 - wq};
    if (!in_filter_range_)
      ok_q &= in_range(d[0], kMinLength, kMaxLength) & in_range(d[1], kMinLength, kMaxLength) &
              in_range(d[2], kMinLength, kMaxLength) & in_range(d[3], kMinArea, kMaxArea);
    const Approx v[3] = {{d[0], std::fabs(d[0])}, {d[1], std::fabs(d[1])}, {d[2], std::fabs(d[2])}};
    const Approx P = power_terms(l, frame, v, Approx(d[3], std::fabs(d[3])));
    const double e = kPower[l.k] * P.p + kTiny;
    if (ok_q && (P.v > e || P.v < -e)) {
      ++stats_.attached.filtered;
      if (P.v < 0) return true;
      continue;
    }
    if (integers < 0) integers = small_integers(std::span<const Index>(s.v.data(), std::size_t(s.n)));
    if (integers && P.p < kExactPermanent && frame.den.p < kExactPermanent &&
        small_integers(std::span<const Index>(&q, 1))) {
      if (frame.den.v == 0) fail("attached: degenerate simplex (affinely dependent points)", ErrorKind::Misuse);
      ++(P.v != 0 ? stats_.attached.filtered : stats_.attached.perturbed);  // decided in doubles
      if (P.v < 0) return true;
      continue;
    }
    Scaled in;
    for (int i = 0; i < s.n; ++i) in.add(pts_[s.v[i]], w_ ? w_[s.v[i]] : 0.0);
    in.add(pq, wq);
    in.finish();
    const int sign = exact_sign([&](auto tag) {
      using T = decltype(tag);
      const Local<T> loc = in.local<T>(0, s.n - 1);
      const PowerFrame<T> f = power_frame(loc);
      if (certainly_zero(f.den)) fail("attached: degenerate simplex (affinely dependent points)", ErrorKind::Misuse);
      T vq[3];
      for (int a = 0; a < 3; ++a) vq[a] = in.coord<T>(s.n, a) - in.coord<T>(0, a);
      return power_terms(loc, f, vq, T(loc.w0 - in.weight<T>(s.n)));
    });
    ++(sign != 0 ? stats_.attached.exact : stats_.attached.perturbed);
    if (sign < 0) return true;
  }
  if (size && s.n == 3) {  // from the frame: the values size() computes
    Approx N, D;
    triangle_size(l, frame.den, frame.V, N, D);
    *size = filtered_size(N, D, l.k, ok, small_integers_);
  } else if (size) {
    *size = this->size(s);
  }
  return false;
}

}  // namespace alpha
