// SPDX-License-Identifier: Apache-2.0
// Exact validity check of a triangulation: combinatorial consistency,
// positive orientation, local regularity of every facet (which, with a
// convex hull, implies global regularity) and convexity of the hull.
#pragma once
#include <string>
#include <vector>

#include "alpha/triangulation.hpp"

namespace alpha {

struct ValidationReport {
  bool valid = true;
  std::vector<std::string> problems;  // the first few, human readable
  void add(std::string problem);
};

ValidationReport validate(const Triangulation& t);

}  // namespace alpha
