// SPDX-License-Identifier: Apache-2.0
// Doubles as exact dyadic numbers m * 2^e: scaling the values of one exact
// evaluation to a common power of two turns them into integers.
#pragma once
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

namespace alpha {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

struct Dyadic {
  std::int64_t m = 0;  // odd, or 0 for the value 0
  int e = INT_MAX;
};

inline Dyadic split(double v) {
  if (v == 0) return {};
  int e;
  const auto m = static_cast<std::int64_t>(std::ldexp(std::frexp(v, &e), 53));
  const int tz = std::countr_zero(static_cast<std::uint64_t>(m));
  return {m >> tz, e - 53 + tz};
}

}  // namespace alpha
