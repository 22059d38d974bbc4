// SPDX-License-Identifier: Apache-2.0
// discard_read (libalpha/src/util/huge_pages.hpp): the pages it gives back hold
// only the part already read, never a value at or after `end`, and
// successive calls leave no page of the read part behind; discard_unused
// gives back no page that holds a value outside its range.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "util/huge_pages.hpp"

using alpha::discard_read;

TEST_CASE("discard_read keeps every value not yet read", "[memory]") {
  const std::size_t n = 1 << 22;  // 16 MiB: several pages to give back
  std::vector<std::uint32_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::uint32_t(i) | 1;  // never 0
  // Steps not multiples of a page, as the alpha complex's.
  std::size_t read = 0;
  for (std::size_t end = 777; end < n; end += 4099) {
    discard_read(v, read, end);
    read = end;
    for (std::size_t i = end; i < n; i += 97) REQUIRE(v[i] == (std::uint32_t(i) | 1));
    REQUIRE(v[end] == (std::uint32_t(end) | 1));
  }
  for (std::size_t i = read; i < n; ++i) REQUIRE(v[i] == (std::uint32_t(i) | 1));
#ifdef MADV_DONTNEED
  // Given back: read as zeros, except before the array's first whole page
  // (shared with the allocator's data) and in the page holding a value not
  // yet read.
  const auto page = [&](std::size_t i) { return reinterpret_cast<std::uintptr_t>(v.data() + i) / alpha::kDiscardPage; };
  std::size_t kept = 0;
  for (std::size_t i = 0; i < read; ++i)
    if (v[i] != 0) {
      ++kept;
      REQUIRE((page(i) == page(0) || page(i) == page(read)));
    }
  REQUIRE(kept < 2 * alpha::kDiscardPage / sizeof(std::uint32_t));
  REQUIRE(kept < read);  // some pages did go back
#endif
}

TEST_CASE("discard_unused gives back only pages wholly inside the range", "[memory]") {
  const std::size_t n = 1 << 22;  // 16 MiB
  std::vector<std::uint32_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::uint32_t(i) | 1;  // never 0
  // A range starting and ending inside pages, as the critical values' tail.
  const std::size_t begin = 777 + alpha::kDiscardPage / sizeof(std::uint32_t), end = n - 4099;
  alpha::discard_unused(v, begin, end);
  for (std::size_t i = 0; i < begin; ++i) REQUIRE(v[i] == (std::uint32_t(i) | 1));
  for (std::size_t i = end; i < n; ++i) REQUIRE(v[i] == (std::uint32_t(i) | 1));
#ifdef MADV_DONTNEED
  // Inside: zeros, except in the pages the range shares with kept values.
  const auto page = [&](std::size_t i) { return reinterpret_cast<std::uintptr_t>(v.data() + i) / alpha::kDiscardPage; };
  std::size_t kept = 0;
  for (std::size_t i = begin; i < end; ++i)
    if (v[i] != 0) {
      ++kept;
      REQUIRE((page(i) == page(begin - 1) || page(i) == page(end)));
    }
  REQUIRE(kept < end - begin);  // some pages did go back
#endif
}
