// SPDX-License-Identifier: Apache-2.0
// The library's internal radix sorts (libalpha/src/util/radix_sort.hpp) against
// the standard sorts: radix_sort as std::stable_sort (equal keys kept in
// input order), radix_sort_in_place as std::sort by (key, minor key).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "util/radix_sort.hpp"

TEST_CASE("radix sorts agree with the standard sorts", "[radix]") {
  std::mt19937_64 rng(91);
  // Below and above the sizes where histograms pay off (and the in-place
  // sort's small-bucket cutoff); keys with few distinct values (many ties),
  // with high digits all equal (skipped), and spread over the whole range.
  for (const std::size_t n :
       {std::size_t(0), std::size_t(1), std::size_t(100), std::size_t(129), std::size_t(5000), std::size_t(70000)})
    for (const std::uint64_t mask : {std::uint64_t(7), std::uint64_t(0xFFFFFF), ~std::uint64_t(0)}) {
      INFO("n " << n << ", mask " << mask);
      std::vector<std::pair<std::uint64_t, std::size_t>> items(n);  // (key, input position)
      for (std::size_t i = 0; i < n; ++i) items[i] = {rng() & mask, i};
      const auto input = items;
      auto expected = items;
      std::stable_sort(expected.begin(), expected.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      alpha::radix_sort(std::span(items), [](const auto& item) { return item.first; });
      CHECK(items == expected);
      // 32-bit keys: the low half only.
      alpha::radix_sort(std::span(items), [](const auto& item) { return std::uint32_t(item.first); });
      std::stable_sort(expected.begin(), expected.end(),
                       [](const auto& a, const auto& b) { return std::uint32_t(a.first) < std::uint32_t(b.first); });
      CHECK(items == expected);
      // In place, equal keys by input position, from a shuffled input.
      items = input;
      std::shuffle(items.begin(), items.end(), rng);
      alpha::radix_sort_in_place(
          std::span(items), [](const auto& item) { return item.first; },
          [](const auto& item) { return std::uint32_t(item.second); });
      expected = input;
      std::sort(expected.begin(), expected.end());
      CHECK(items == expected);
    }
}
