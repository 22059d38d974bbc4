// SPDX-License-Identifier: Apache-2.0
// Stable sort by an unsigned integer key, in linear time: the alpha complex
// sorts tens of millions of sizes and ranks, where comparison sorts spend
// most of their time in mispredicted branches.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "huge_pages.hpp"

namespace alpha {

// Sorts items by key(item) (an unsigned integer), keeping the order of equal
// keys: least significant digit first, 16 bits at a time, skipping the
// digits that all keys share. Needs a second buffer of items.
template <class T, class KeyOf>
void radix_sort(std::vector<T>& items, KeyOf key) {
  using Key = decltype(key(items[0]));
  static_assert(std::is_unsigned_v<Key>);
  constexpr int kBits = 16, kDigits = int(sizeof(Key) * 8 / kBits);
  constexpr std::size_t kBuckets = std::size_t(1) << kBits;
  const std::size_t n = items.size();
  if (n < kBuckets / 16) {  // the histograms would dominate
    std::stable_sort(items.begin(), items.end(), [&](const T& a, const T& b) { return key(a) < key(b); });
    return;
  }
  auto digit = [&](const T& item, int d) { return std::size_t(key(item) >> (kBits * d)) & (kBuckets - 1); };
  std::vector<std::array<std::size_t, kBuckets>> count(kDigits);
  for (auto& c : count) c.fill(0);
  for (const T& item : items)
    for (int d = 0; d < kDigits; ++d) ++count[d][digit(item, d)];
  std::vector<T> buffer;
  assign_huge(buffer, n);
  for (int d = 0; d < kDigits; ++d) {
    auto& c = count[d];
    if (c[digit(items[0], d)] == n) continue;  // one bucket: nothing moves
    std::size_t start = 0;
    for (std::size_t& b : c) start += std::exchange(b, start);
    for (const T& item : items) buffer[c[digit(item, d)]++] = item;
    items.swap(buffer);
  }
}

}  // namespace alpha
