// SPDX-License-Identifier: Apache-2.0
// Work split across a few threads (the triangulation, its simplices and the alpha complex): the caller
// runs the first share itself. The work must not throw.
#pragma once
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <span>
#include <thread>
#include <vector>

namespace alpha {

// f(t, begin, end) on `threads` threads t, [0, n) cut into equal ranges.
template <class F>
void in_parallel(unsigned threads, std::size_t n, F f) {
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back([&f, t, threads, n] { f(t, n * t / threads, n * (t + 1) / threads); });
  f(0u, std::size_t(0), n / threads);
}

// Flags that threads set, each in a copy of its own (the first thread in
// the flags themselves: no two threads share a word of a vector<bool>);
// merge() ors the other copies in.
class ThreadFlags {
public:
  ThreadFlags(std::vector<bool>& flags, unsigned threads)
      : flags_(flags), copies_(threads - 1, std::vector<bool>(flags.size())) {}
  std::vector<bool>& of(unsigned thread) { return thread == 0 ? flags_ : copies_[thread - 1]; }
  void merge() {
    for (const std::vector<bool>& copy : copies_)
      for (std::size_t i = 0; i < copy.size(); ++i)
        if (copy[i]) flags_[i] = true;
  }

private:
  std::vector<bool>& flags_;
  std::vector<std::vector<bool>> copies_;
};

// std::sort(items, less) with each thread's range sorted on its own, then
// merged. `less` must be a strict total order, so that the result is the
// same for any number of threads.
template <class T, class Less>
void parallel_sort(std::span<T> items, unsigned threads, Less less) {
  const std::size_t n = items.size();
  in_parallel(threads, n, [&](unsigned, std::size_t begin, std::size_t end) {
    std::sort(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end), less);
  });
  // Ranges [0, n t / threads) are sorted; merge in the next one.
  for (unsigned t = 1; t < threads; ++t)
    std::inplace_merge(items.begin(), items.begin() + std::ptrdiff_t(n * t / threads),
                       items.begin() + std::ptrdiff_t(n * (t + 1) / threads), less);
}

}  // namespace alpha
