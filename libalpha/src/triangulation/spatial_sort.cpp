// SPDX-License-Identifier: Apache-2.0
#include "alpha/spatial_sort.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "util/parallel.hpp"

namespace alpha {
namespace {

// Per axis: 2^16 cells resolve any realistic input finer than needed for
// locality, at a third of the cost of full 21-bit keys.
constexpr int kBits = 16;

// The threads for work on n points: those given from 2^14 points on (less
// takes less than starting a thread).
unsigned threads_for(std::size_t n, unsigned threads) { return n >= std::size_t(1) << 14 ? threads : 1u; }

// SplitMix64: tiny, portable and deterministic (std::shuffle is not).
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
};

// Bits 0..15 of v moved to bits 0, 3, 6, ..., 45 (the others zero).
std::uint64_t spread_by_three(std::uint64_t v) {
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

// Skilling's transform ("Programming the Hilbert curve", 2004) from axes to
// the transposed Hilbert index, then interleaved into one key (bit b of
// axis i at 3b + 2 - i). Without branches: each one depends on a coordinate
// bit, which the processor cannot predict.
std::uint64_t hilbert_key(std::uint32_t x[3]) {
  for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      // bit q of x[i] set: invert the low bits of x[0]; else exchange them with x[i]'s.
      const std::uint32_t set = 0u - std::uint32_t((x[i] & q) != 0);
      const std::uint32_t t = (x[0] ^ x[i]) & p & ~set;
      x[0] ^= (p & set) ^ t, x[i] ^= t;
    }
  }
  x[1] ^= x[0], x[2] ^= x[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1) t ^= (q - 1) & (0u - std::uint32_t((x[2] & q) != 0));
  for (int i = 0; i < 3; ++i) x[i] ^= t;
  return spread_by_three(x[0]) << 2 | spread_by_three(x[1]) << 1 | spread_by_three(x[2]);
}

}  // namespace

std::vector<std::uint64_t> hilbert_keys(std::span<const Vec3> points, std::span<const Index> indices, unsigned threads) {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (Index i : indices) {
    const Vec3& p = points[i];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // One scale for all axes keeps the curve's cells cubic.
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double scale = extent > 0 ? ((1u << kBits) - 1) / extent : 0;
  auto cell = [&](double v, double l) {
    return static_cast<std::uint32_t>(std::clamp((v - l) * scale, 0.0, double((1u << kBits) - 1)));
  };
  std::vector<std::uint64_t> keys(indices.size());
  in_parallel(threads_for(indices.size(), threads), indices.size(),
              [&](unsigned, std::size_t begin, std::size_t end) {
                for (std::size_t k = begin; k < end; ++k) {
                  const Vec3& p = points[indices[k]];
                  std::uint32_t x[3] = {cell(p.x, lo.x), cell(p.y, lo.y), cell(p.z, lo.z)};
                  keys[k] = hilbert_key(x);
                }
              });
  return keys;
}

std::vector<std::size_t> brio_rounds(std::size_t n) {
  // Rounds [n/8^(k+1), n/8^k): the first few points form the coarsest round.
  std::vector<std::size_t> cuts{n};
  while (cuts.back() > 256) cuts.push_back(cuts.back() / 8);
  cuts.push_back(0);
  std::reverse(cuts.begin(), cuts.end());
  return cuts;
}

std::vector<Index> brio_order(std::span<const Vec3> points, std::vector<Index> order, unsigned threads,
                              std::uint64_t seed) {
  // Keys first, while the points are read in order (cache friendly), then
  // shuffle the (key, index) pairs.
  const std::vector<std::uint64_t> keys = hilbert_keys(points, order, threads);
  std::vector<std::pair<std::uint64_t, Index>> items(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) items[i] = {keys[i], order[i]};
  SplitMix64 rng{seed};
  for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[rng.next() % i]);
  const std::vector<std::size_t> cuts = brio_rounds(items.size());
  for (std::size_t r = 1; r < cuts.size(); ++r)
    parallel_sort(std::span(items).subspan(cuts[r - 1], cuts[r] - cuts[r - 1]),
                  threads_for(cuts[r] - cuts[r - 1], threads), std::less<>());
  for (std::size_t i = 0; i < items.size(); ++i) order[i] = items[i].second;
  return order;
}

}  // namespace alpha
