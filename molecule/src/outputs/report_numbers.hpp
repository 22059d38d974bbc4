// SPDX-License-Identifier: Apache-2.0
// The precision of the numbers in the results (report.json, the tables,
// the summary), one rule for each kind, so that a number printed in two
// places reads the same: lengths, areas and volumes to 3 decimals (1e-3 A
// is far below the precision of any structure), probabilities to 4,
// scores and buriedness to 4 significant digits. Never -0.
#pragma once
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace molecule::report_number {

inline double rounded(double x, double scale) {
  const double r = std::round(x * scale) / scale;
  return r == 0 ? 0.0 : r;  // no -0 in the output
}

// Lengths in A, also areas and volumes.
inline double length(double x) { return rounded(x, 1e3); }

// NaN (none computed) stays NaN.
inline double probability(double p) { return std::isnan(p) ? p : rounded(p, 1e4); }

// Scores span many decades (burial enters to the 12th power): 4
// significant digits, so that small molecules' scores do not all read 0.
inline double score(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return std::strtod(text, nullptr) + 0.0;  // + 0.0: no -0
}

}  // namespace molecule::report_number
