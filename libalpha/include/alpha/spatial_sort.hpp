// SPDX-License-Identifier: Apache-2.0
// Insertion order for incremental construction: a Biased Randomized
// Insertion Order (Amenta, Choi & Rote 2003) whose rounds are each sorted
// along a Hilbert curve, so consecutive points are close (short walks, warm
// caches) while the randomization keeps the expected cost optimal.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "alpha/geometry.hpp"

namespace alpha {

// Order of the given point indices; deterministic for a given seed, the
// same for any number of threads (which sort the long rounds).
std::vector<Index> brio_order(std::span<const Vec3> points, std::vector<Index> indices, unsigned threads = 1,
                              std::uint64_t seed = 0x5eed);

// Where brio_order's rounds of n points begin, ascending: 0, ..., n. Each
// round is sorted along the curve.
std::vector<std::size_t> brio_rounds(std::size_t n);

// 48-bit Hilbert-curve key of each index within the bounding box of the
// points, computed on `threads` threads.
std::vector<std::uint64_t> hilbert_keys(std::span<const Vec3> points, std::span<const Index> indices,
                                        unsigned threads = 1);

}  // namespace alpha
