// SPDX-License-Identifier: Apache-2.0
// The median the benchmarks quote (noisy 2-core machine: medians, not means).
#pragma once
#include <algorithm>
#include <vector>

namespace bench {

// Middle value; the mean of the two middle ones for an even count; 0 if empty.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace bench
