// SPDX-License-Identifier: Apache-2.0
// An allocator whose resize() leaves trivial elements uninitialized: for
// arrays that are written before they are read, filled by several threads
// (each touches its own pages first) or at random places, where zeroing
// hundreds of megabytes first would cost a pass of its own.
#pragma once
#include <memory>
#include <new>
#include <utility>

namespace alpha {

template <class T>
struct UninitializedAllocator : std::allocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialized: no zeroing
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace alpha
