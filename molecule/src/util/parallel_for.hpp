// SPDX-License-Identifier: Apache-2.0
// Runs independent tasks on a few threads. The tasks write their own
// result slots, so what the caller assembles does not depend on which
// thread ran what or when.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace molecule {

// Calls task(order[k]) for every k on `threads` threads (the calling
// thread one of them), each thread taking the next k not yet taken: put
// the longest tasks first. If tasks throw, rethrows the exception of the
// earliest k, as a sequential loop over the tasks that ran would.
template <class Task>
void parallel_for(const std::vector<std::size_t>& order, unsigned threads, const Task& task) {
  std::atomic<std::size_t> next{0};
  std::mutex failed_mutex;
  std::size_t failed_at = order.size();
  std::exception_ptr failure;
  const auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < order.size();) {
      try {
        task(order[k]);
      } catch (...) {
        const std::lock_guard lock(failed_mutex);
        if (k < failed_at) failed_at = k, failure = std::current_exception();
        next = order.size();  // start no more tasks
      }
    }
  };
  std::vector<std::thread> helpers;
  const std::size_t n = std::min<std::size_t>(std::max(1u, threads), order.size());
  for (std::size_t h = 1; h < n; ++h) try {
      helpers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: fewer do the work
    }
  work();
  for (std::thread& h : helpers) h.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace molecule
