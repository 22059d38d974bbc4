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

}  // namespace alpha
