// SPDX-License-Identifier: Apache-2.0
// Transparent huge pages for big arrays. Filling fresh memory takes a page
// fault per 4 KiB page, a large share of the time spent writing arrays of
// hundreds of megabytes once; 2 MiB pages take 512 times fewer. Only a hint
// to the kernel (Linux, THP in "madvise" mode); a no-op elsewhere.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>
#if __has_include(<sys/mman.h>)
#include <sys/mman.h>
#endif

namespace alpha {

inline void advise_huge_pages([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

// v.reserve(n), the new storage advised before anything touches it.
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

// v.assign(n, value) into advised storage.
template <class T, class A>
void assign_huge(std::vector<T, A>& v, std::size_t n, const T& value = T()) {
  v.clear();
  reserve_huge(v, n);
  v.assign(n, value);
}

inline constexpr std::uintptr_t kDiscardPage = std::uintptr_t(2) << 20;

// The huge pages wholly inside the addresses [first, last) go back.
inline void discard_pages([[maybe_unused]] std::uintptr_t first, [[maybe_unused]] std::uintptr_t last) {
#ifdef MADV_DONTNEED
  first = (first + kDiscardPage - 1) & ~(kDiscardPage - 1);
  last &= ~(kDiscardPage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#endif
}

// For an array read once from the front: v[0, end) has been read for the
// last time, and the pages from the one holding v[begin] up to v[end] that
// hold nothing else of v go back to the system (Linux; a no-op elsewhere),
// so that arrays growing meanwhile do not add to the peak. Their contents
// are lost (they read as zeros if touched again). Called with the previous
// call's end as begin, no page is left behind. In huge pages: a smaller
// piece of one would split it, and each call flushes the TLB.
template <class T, class A>
void discard_read(std::vector<T, A>& v, std::size_t begin, std::size_t end) {
  const auto address = [&](std::size_t i) { return reinterpret_cast<std::uintptr_t>(v.data() + i); };
  // From the page holding v[begin], but not below the array's first whole
  // page: the allocator's own data may share the page before it.
  discard_pages(std::max(address(begin) & ~(kDiscardPage - 1), address(0)), address(end));
}

// v[begin, end) holds nothing that will be read: the huge pages wholly
// inside it go back to the system (Linux; a no-op elsewhere).
template <class T, class A>
void discard_unused(std::vector<T, A>& v, std::size_t begin, std::size_t end) {
  discard_pages(reinterpret_cast<std::uintptr_t>(v.data() + begin), reinterpret_cast<std::uintptr_t>(v.data() + end));
}

// Frees v's storage (v = {} would keep it: that assigns an empty list).
template <class T, class A>
void release(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace alpha
