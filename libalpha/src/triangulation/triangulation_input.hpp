// SPDX-License-Identifier: Apache-2.0
// The input check of Triangulation, shared by its construction and its
// dynamic update.
#pragma once
#include <vector>

#include "alpha/geometry.hpp"

namespace alpha {

// Throws alpha::Error for values a triangulation cannot take (see the
// Triangulation constructor).
void check_input(const std::vector<Vec3>& points, const std::vector<double>& weights);
// The same for the values of point i alone (weight null: unweighted).
void check_point(std::size_t i, const Vec3& p, const double* weight);

// Points spanning less than this (but more than 0) along every axis are refused.
inline constexpr double kMinExtent = 1e-100;

}  // namespace alpha
