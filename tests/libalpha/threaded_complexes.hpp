// SPDX-License-Identifier: Apache-2.0
// The alpha complexes of the same weighted random points (a 100^3 box,
// weights in [0.5, 2)) built on 2 and on 3 threads: enough points
// (AlphaComplex::kThreadsFrom vertices) for the triangulation and the
// complex to use them. The threaded triangulation numbers its cells
// canonically, the same for any thread count above 1.
#pragma once
#include <cstdint>

#include "alpha/alpha_complex.hpp"
#include "alpha/triangulation.hpp"

namespace testing {

struct ThreadedComplexes {
  alpha::Triangulation t2, t3;
  alpha::AlphaComplex a2, a3;
  explicit ThreadedComplexes(std::uint64_t seed);
};

}  // namespace testing
