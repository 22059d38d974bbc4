// SPDX-License-Identifier: Apache-2.0
// Exact evaluation of the determinant signs behind the predicates.
// Doubles are exact dyadic numbers m*2^e; shifting all values of one call to
// a common exponent turns them into integers, evaluated in 128-bit integers
// when they are small enough (grids, integer input) and in GMP otherwise.
#pragma once
#include "alpha/geometry.hpp"

namespace alpha::exact {

// Sign of det[b-a, c-a, d-a].
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Sign of det of rows (q_i - p, |q_i - p|^2 - (w_i - w_p)), i = 0..3.
int power_det(const Vec3* const q[4], const double w[4], const Vec3& p, double wp);

}  // namespace alpha::exact
