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

#include "util/huge_pages.hpp"

namespace alpha {

// Sorts items by key(item) (an unsigned integer), keeping the order of equal
// keys: least significant digit first, 16 bits at a time, skipping the
// digits that all keys share. Needs a second buffer of items.
template <class T, class KeyOf>
void radix_sort(std::span<T> items, KeyOf key) {
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
  T *from = items.data(), *to = buffer.data();
  for (int d = 0; d < kDigits; ++d) {
    auto& c = count[d];
    if (c[digit(from[0], d)] == n) continue;  // one bucket: nothing moves
    std::size_t start = 0;
    for (std::size_t& b : c) start += std::exchange(b, start);
    for (std::size_t i = 0; i < n; ++i) to[c[digit(from[i], d)]++] = from[i];
    std::swap(from, to);
  }
  if (from != items.data()) std::copy(from, from + n, items.data());
}

namespace radix_detail {

// Byte `byte` of an item's 96-bit key: bytes 11 to 4 are key(item)'s, 3 to
// 0 minor(item)'s.
template <class T, class KeyOf, class MinorOf>
std::size_t byte_of(const T& item, const KeyOf& key, const MinorOf& minor, int byte) {
  return std::size_t(byte >= 4 ? key(item) >> (8 * (byte - 4)) : minor(item) >> (8 * byte)) & 255;
}

// The highest byte below `below` in which the items' 96-bit keys differ,
// or -1.
template <class T, class KeyOf, class MinorOf>
int highest_differing_byte(const T* first, const T* last, const KeyOf& key, const MinorOf& minor, int below) {
  std::uint64_t key_any = 0, key_all = ~std::uint64_t(0);
  std::uint32_t minor_any = 0, minor_all = ~std::uint32_t(0);
  for (const T* p = first; p != last; ++p)
    key_any |= key(*p), key_all &= key(*p), minor_any |= minor(*p), minor_all &= minor(*p);
  const std::uint64_t key_differs = key_any ^ key_all;
  const std::uint32_t minor_differs = minor_any ^ minor_all;
  for (int byte = below - 1; byte >= 0; --byte)
    if ((byte >= 4 ? key_differs >> (8 * (byte - 4)) : minor_differs >> (8 * byte)) & 255) return byte;
  return -1;
}

// Buckets this small are sorted on their keys read once, then moved
// through a copy: fewer key reads than more histogram passes.
constexpr std::size_t kSmall = 128;

template <class T, class KeyOf, class MinorOf>
void sort_small(T* first, std::size_t n, const KeyOf& key, const MinorOf& minor) {
  struct Keyed {
    std::uint64_t key;
    std::uint32_t minor, at;
  };
  Keyed keyed[kSmall];  // not initialized: written before read
  T items[kSmall];
  for (std::size_t i = 0; i < n; ++i)
    keyed[i] = {key(first[i]), minor(first[i]), std::uint32_t(i)}, items[i] = std::move(first[i]);
  std::sort(keyed, keyed + n,
            [](const Keyed& a, const Keyed& b) { return a.key < b.key || (a.key == b.key && a.minor < b.minor); });
  for (std::size_t i = 0; i < n; ++i) first[i] = std::move(items[keyed[i].at]);
}

// Sorts [first, last) by byte `byte` of the keys, then each bucket by the
// lower bytes: most significant byte first, each bucket's items swapped to
// their place (American flag sort; McIlroy, Bostic & McIlroy 1993).
template <class T, class KeyOf, class MinorOf>
void sort_from_byte(T* first, T* last, const KeyOf& key, const MinorOf& minor, int byte) {
  for (;;) {
    const std::size_t n = std::size_t(last - first);
    if (n <= kSmall) return sort_small(first, n, key, minor);
    auto digit = [&](const T& item) { return byte_of(item, key, minor, byte); };
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
      if (byte > 0)
        for (std::size_t b = 0; b < 256; ++b)
          if (count[b] > 1) sort_from_byte(first + (end[b] - count[b]), first + end[b], key, minor, byte - 1);
      return;
    }
    // One bucket: nothing moved. Already in order (a grid's equal sizes,
    // in id order), or on to the highest lower byte in which these items
    // differ (not a histogram per byte).
    if (std::is_sorted(first, last, [&](const T& a, const T& b) {
          return key(a) < key(b) || (key(a) == key(b) && minor(a) < minor(b));
        }))
      return;
    byte = highest_differing_byte(first, last, key, minor, byte);
    if (byte < 0) return;  // equal keys
  }
}

}  // namespace radix_detail

// Sorts items by key(item) (a std::uint64_t), equal keys by minor(item) (a
// std::uint32_t), in place. Not stable: items with equal key and minor end
// in an unspecified order, so callers make them distinct (e.g. an id) for a
// deterministic result.
template <class T, class KeyOf, class MinorOf>
void radix_sort_in_place(std::span<T> items, KeyOf key, MinorOf minor) {
  T *first = items.data(), *last = first + items.size();
  const int byte = radix_detail::highest_differing_byte(first, last, key, minor, 12);
  if (byte >= 0) radix_detail::sort_from_byte(first, last, key, minor, byte);
}

}  // namespace alpha
