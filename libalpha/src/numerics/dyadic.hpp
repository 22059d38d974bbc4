// SPDX-License-Identifier: Apache-2.0
// Doubles as exact dyadic numbers m * 2^e: scaling the values of one exact
// evaluation to a common power of two turns them into integers.
#pragma once
#include <bit>
#include <climits>
#include <cstdint>

namespace alpha {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

struct Dyadic {
  std::int64_t m = 0;  // odd, or 0 for the value 0
  int e = INT_MAX;
};

// Read from the bits (frexp and ldexp are library calls, and the exact
// stages split up to 20 values a call); finite values only.
inline Dyadic split(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  auto m = static_cast<std::int64_t>(bits & ((std::uint64_t(1) << 52) - 1));
  if (biased == 0 && m == 0) return {};
  int e = -1074;  // subnormal: no implicit bit
  if (biased != 0) {
    m |= std::int64_t(1) << 52;
    e = biased - 1075;
  }
  const int tz = std::countr_zero(static_cast<std::uint64_t>(m));
  m >>= tz;
  return {bits >> 63 ? -m : m, e + tz};
}

}  // namespace alpha
