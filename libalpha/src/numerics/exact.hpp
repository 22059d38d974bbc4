// SPDX-License-Identifier: Apache-2.0
// Exact evaluation of the determinant signs behind the predicates.
// Doubles are exact dyadic numbers m*2^e; shifting all values of one call to
// a common exponent turns them into integers, evaluated in 128-bit integers
// when they are small enough and in GMP otherwise. Integer input near p
// (grids) is decided in doubles first, where that is exact.
#pragma once
#include "alpha/geometry.hpp"

namespace alpha::exact {

// Whether v is an integer: adding and removing 1.5 * 2^52 rounds it to one
// (integers beyond 2^51 may be missed, which only sends them to the exact
// stages). Integer input (grids) is decided in doubles where its values
// stay small.
inline bool is_integer(double v) {
  constexpr double kRound = 0x1.8p52;
  return (v + kRound) - kRound == v;
}

// Sign of det[b-a, c-a, d-a].
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Sign of det of rows (q_i - p, |q_i - p|^2 - (w_i - w_p)), i = 0..3.
int power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp);

// The first stage of power_det, for integer input (grids of unit spacing,
// integer coordinates and weights) with every q_i within 2^9 of p and
// weights within 2^19 of p's: the lifted values are then below 2^21, the
// 3x3 minors below 2^30, each term below 2^51 and the sum below 2^53, so
// doubles are exact. Sets the sign of the determinant and, for k = 0..3,
// orient[k] = sign of orient3d of the q's with q_k replaced by p (what the
// perturbation asks for), from the same minors. False when the input is not
// such.
bool small_power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp, int& det, int orient[4]);

// The stages of power_det after small_power_det (128-bit, then GMP), for
// input that one refused.
int dyadic_power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp);

}  // namespace alpha::exact
