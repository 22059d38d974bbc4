// SPDX-License-Identifier: Apache-2.0
// Sorts by an unsigned integer key, in linear time: the alpha complex sorts
// tens of millions of sizes, ranks and pairs, where comparison sorts spend
// most of their time in mispredicted branches. Two kinds: a stable one with
// a second buffer, and one in place for the largest array (the critical
// values: their buffer was 288 MB of the peak memory at 1e6 points).
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
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

namespace radix_detail {

// Buckets this small are sorted on their keys read once, then moved
// through a copy: fewer key reads than more histogram passes.
constexpr std::size_t kSmall = 128;

template <class T, class KeyOf, class TieLess>
void sort_small(T* first, std::size_t n, const KeyOf& key, const TieLess& tie_less) {
  struct Keyed {
    std::uint64_t value;
    std::uint32_t at;
  };
  Keyed keyed[kSmall];  // not initialized: written before read
  T items[kSmall];
  for (std::size_t i = 0; i < n; ++i) keyed[i] = {key(first[i]), std::uint32_t(i)}, items[i] = std::move(first[i]);
  std::sort(keyed, keyed + n, [&](const Keyed& a, const Keyed& b) {
    return a.value < b.value || (a.value == b.value && tie_less(items[a.at], items[b.at]));
  });
  for (std::size_t i = 0; i < n; ++i) first[i] = std::move(items[keyed[i].at]);
}

// Sorts [first, last) by byte `byte` of the keys, then each bucket by the
// lower bytes: most significant byte first, each bucket's items swapped to
// their place (American flag sort; McIlroy, Bostic & McIlroy 1993).
template <class T, class KeyOf, class TieLess>
void sort_from_byte(T* first, T* last, const KeyOf& key, const TieLess& tie_less, int byte) {
  for (;;) {
    const std::size_t n = std::size_t(last - first);
    if (n <= kSmall) return sort_small(first, n, key, tie_less);
    auto digit = [&](const T& item) { return std::size_t(key(item) >> (8 * byte)) & 255; };
    std::array<std::size_t, 256> count{};
    for (const T* p = first; p != last; ++p) ++count[digit(*p)];
    if (count[digit(*first)] < n) {
      std::array<std::size_t, 256> head, end;
      std::size_t start = 0;
      for (std::size_t b = 0; b < 256; ++b) head[b] = start, end[b] = start += count[b];
      for (std::size_t b = 0; b < 256; ++b)
        while (head[b] < end[b]) {  // carry the item at head[b] along a cycle back to bucket b
          T item = std::move(first[head[b]]);
          for (std::size_t d = digit(item); d != b; d = digit(item)) std::swap(item, first[head[d]++]);
          first[head[b]++] = std::move(item);
        }
      for (std::size_t b = 0; b < 256; ++b) {
        T* const bucket = first + (end[b] - count[b]);
        if (count[b] < 2) continue;
        if (byte > 0) sort_from_byte(bucket, first + end[b], key, tie_less, byte - 1);
        else std::sort(bucket, first + end[b], tie_less);  // equal keys
      }
      return;
    }
    if (byte-- == 0) return std::sort(first, last, tie_less);  // equal keys
  }
}

}  // namespace radix_detail

// Sorts items by key(item) (a std::uint64_t), equal keys by tie_less, in
// place; a total order gives a deterministic result (the sort is not stable).
template <class T, class KeyOf, class TieLess>
void radix_sort_in_place(std::span<T> items, KeyOf key, TieLess tie_less) {
  if (items.empty()) return;
  // Start at the highest byte in which keys differ.
  std::uint64_t any = 0, all = ~std::uint64_t(0);
  for (const T& item : items) any |= key(item), all &= key(item);
  int byte = 7;
  while (byte > 0 && ((any ^ all) >> (8 * byte)) == 0) --byte;
  radix_detail::sort_from_byte(items.data(), items.data() + items.size(), key, tie_less, byte);
}

}  // namespace alpha
