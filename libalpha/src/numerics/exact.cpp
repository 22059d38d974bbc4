// SPDX-License-Identifier: Apache-2.0
#include "numerics/exact.hpp"

#include "numerics/dyadic.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace alpha::exact {
namespace {

int min_exponent(const Dyadic* d, int n) {
  int e = INT_MAX;
  for (int i = 0; i < n; ++i) e = std::min(e, d[i].e);
  return e == INT_MAX ? 0 : e;
}

// Bits needed for |d| scaled to unit 2^unit.
int scaled_bits(const Dyadic& d, int unit) {
  if (d.m == 0) return 0;
  return (d.e - unit) + static_cast<int>(std::bit_width(static_cast<std::uint64_t>(std::llabs(d.m))));
}

bool fits(const Dyadic* d, int n, int unit, int bits) {
  for (int i = 0; i < n; ++i)
    if (scaled_bits(d[i], unit) > bits) return false;
  return true;
}

std::int64_t to_int(const Dyadic& d, int unit) { return d.m == 0 ? 0 : d.m << (d.e - unit); }

mpz_class to_mpz(const Dyadic& d, int unit) {
  mpz_class r(static_cast<long>(d.m));
  if (d.m != 0) r <<= static_cast<mp_bitcnt_t>(d.e - unit);
  return r;
}

template <class T> int sign(const T& v) { return (v > 0) - (v < 0); }

template <class T> T det3(const T* r0, const T* r1, const T* r2) {
  return r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0]) +
         r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
}

// det of the 4x4 matrix with rows (x,y,z,h), expanded along h.
template <class T> T det4(const T r[4][4]) {
  auto minor = [&](int i, int j, int k) {
    const T a[3] = {r[i][0], r[i][1], r[i][2]}, b[3] = {r[j][0], r[j][1], r[j][2]},
            c[3] = {r[k][0], r[k][1], r[k][2]};
    return det3(a, b, c);
  };
  return -r[0][3] * minor(1, 2, 3) + r[1][3] * minor(0, 2, 3) - r[2][3] * minor(0, 1, 3) +
         r[3][3] * minor(0, 1, 2);
}

// Integer input (grids of unit spacing, integer coordinates and weights):
// differences of integers that come out small are exact.
bool is_integer(const Vec3& v) { return exact::is_integer(v.x) & exact::is_integer(v.y) & exact::is_integer(v.z); }

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3* v[4] = {&a, &b, &c, &d};
  // Integers with differences below 2^16: det3's 2x2 minors are below
  // 2^33, its three terms below 2^49 and their sum below 2^51, so doubles
  // are exact.
  if (is_integer(a) & is_integer(b) & is_integer(c) & is_integer(d)) {
    double r[3][3];
    double m = 0;
    for (int i = 1; i < 4; ++i) {
      r[i - 1][0] = v[i]->x - a.x, r[i - 1][1] = v[i]->y - a.y, r[i - 1][2] = v[i]->z - a.z;
      m = std::max({m, std::fabs(r[i - 1][0]), std::fabs(r[i - 1][1]), std::fabs(r[i - 1][2])});
    }
    if (m < 0x1p16) return sign(det3(r[0], r[1], r[2]));
  }
  Dyadic s[12];
  for (int i = 0; i < 4; ++i) {
    s[3 * i] = split(v[i]->x);
    s[3 * i + 1] = split(v[i]->y);
    s[3 * i + 2] = split(v[i]->z);
  }
  const int unit = min_exponent(s, 12);
  if (fits(s, 12, unit, 37)) {  // differences < 2^38: det3 < 2^117
    i128 r[3][3];
    for (int i = 1; i < 4; ++i)
      for (int k = 0; k < 3; ++k) r[i - 1][k] = to_int(s[3 * i + k], unit) - to_int(s[k], unit);
    return sign(det3(r[0], r[1], r[2]));
  }
  mpz_class r[3][3];
  for (int i = 1; i < 4; ++i)
    for (int k = 0; k < 3; ++k) r[i - 1][k] = to_mpz(s[3 * i + k], unit) - to_mpz(s[k], unit);
  return sgn(mpz_class(det3(r[0], r[1], r[2])));
}

bool small_power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp, int& det,
                     int orient[4]) {
  if (!(is_integer(*q[0]) & is_integer(*q[1]) & is_integer(*q[2]) & is_integer(*q[3]) & is_integer(p) &
        is_integer(w[0]) & is_integer(w[1]) & is_integer(w[2]) & is_integer(w[3]) & is_integer(wp)))
    return false;
  double r[4][4];
  bool small = true;
  for (int i = 0; i < 4; ++i) {
    const double x = q[i]->x - p.x, y = q[i]->y - p.y, z = q[i]->z - p.z, dw = w[i] - wp;
    small = small & (std::fabs(x) < 0x1p9) & (std::fabs(y) < 0x1p9) & (std::fabs(z) < 0x1p9) &
            (std::fabs(dw) < 0x1p19);
    r[i][0] = x, r[i][1] = y, r[i][2] = z, r[i][3] = x * x + y * y + z * z - dw;
  }
  if (!small) return false;
  // det[q_i - p, q_j - p, q_k - p]; orient3d of the cell with q_k replaced
  // by p is (-1)^k times the minor of the other three (in order).
  const auto minor = [&](int i, int j, int k) { return det3(r[i], r[j], r[k]); };
  const double m123 = minor(1, 2, 3), m023 = minor(0, 2, 3), m013 = minor(0, 1, 3), m012 = minor(0, 1, 2);
  det = sign(-r[0][3] * m123 + r[1][3] * m023 - r[2][3] * m013 + r[3][3] * m012);
  orient[0] = sign(m123), orient[1] = -sign(m023), orient[2] = sign(m013), orient[3] = -sign(m012);
  return true;
}

int power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp) {
  int det, orient[4];
  return small_power_det(q, w, p, wp, det, orient) ? det : dyadic_power_det(q, w, p, wp);
}

int dyadic_power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp) {
  Dyadic c[15], ws[5];
  for (int i = 0; i < 4; ++i) {
    c[3 * i] = split(q[i]->x);
    c[3 * i + 1] = split(q[i]->y);
    c[3 * i + 2] = split(q[i]->z);
    ws[i] = split(w[i]);
  }
  c[12] = split(p.x), c[13] = split(p.y), c[14] = split(p.z);
  ws[4] = split(wp);
  const int cu = min_exponent(c, 15);
  const bool weighted = std::any_of(ws, ws + 5, [](const Dyadic& d) { return d.m != 0; });
  const int wu = weighted ? min_exponent(ws, 5) : 2 * cu;
  const int hu = std::min(2 * cu, wu);  // unit of the lifted column

  // 128-bit path: coordinates < 2^23 (differences < 2^24), weights small,
  // lifted values < 2^49, so that det4 < 2^127.
  if (fits(c, 15, cu, 23) && fits(ws, 5, wu, 47) && 2 * cu - hu <= 60 && wu - hu <= 60) {
    i128 r[4][4];
    bool ok = true;
    for (int i = 0; i < 4 && ok; ++i) {
      i128 s = 0;
      for (int k = 0; k < 3; ++k) {
        r[i][k] = to_int(c[3 * i + k], cu) - to_int(c[12 + k], cu);
        s += r[i][k] * r[i][k];
      }
      const i128 dw = i128(to_int(ws[i], wu)) - to_int(ws[4], wu);
      const i128 h = (s << (2 * cu - hu)) - (dw << (wu - hu));
      ok = (h < 0 ? -h : h) < (i128(1) << 49);
      r[i][3] = h;
    }
    if (ok) return sign(det4(r));
  }
  mpz_class r[4][4];
  const mpz_class pw = to_mpz(ws[4], wu);
  mpz_class pc[3];
  for (int k = 0; k < 3; ++k) pc[k] = to_mpz(c[12 + k], cu);
  for (int i = 0; i < 4; ++i) {
    mpz_class s = 0;
    for (int k = 0; k < 3; ++k) {
      r[i][k] = to_mpz(c[3 * i + k], cu) - pc[k];
      s += r[i][k] * r[i][k];
    }
    mpz_class dw = to_mpz(ws[i], wu) - pw;
    s <<= static_cast<mp_bitcnt_t>(2 * cu - hu);
    dw <<= static_cast<mp_bitcnt_t>(wu - hu);
    r[i][3] = s - dw;
  }
  return sgn(mpz_class(det4(r)));
}

}  // namespace alpha::exact
