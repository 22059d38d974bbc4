// SPDX-License-Identifier: Apache-2.0
// Loops that visit simplices in an order unrelated to where their records
// lie (the filtration order, a diagram's ranks, input indices of vertices)
// miss the cache at every read once the arrays outgrow it (a million
// points). They ask for the memory of the item kAhead steps on before
// reading the current one's, so that the misses overlap instead of
// following each other; a record that names another (a triangle its cell,
// a cell its points) is asked for a further kAhead steps earlier.
#pragma once
#include <cstddef>

namespace alpha {

inline constexpr std::size_t kAhead = 16;

// GCC counts a prefetch as free of side effects: a helper (a lambda, a
// member) that only prefetches is then "pure" and its calls are deleted.
// The empty volatile asm is a side effect, which keeps them.
inline void prefetch(const void* address) {
  __builtin_prefetch(address);
#if defined(__GNUC__)
  asm volatile("");
#endif
}

}  // namespace alpha
