// SPDX-License-Identifier: Apache-2.0
#include "threaded_complexes.hpp"

#include "point_sets.hpp"

namespace testing {
namespace {

constexpr std::size_t kPoints = alpha::AlphaComplex::kThreadsFrom + 1000;

std::vector<alpha::Vec3> points(std::uint64_t seed) { return random_points(kPoints, seed, 100.0); }
std::vector<double> weights(std::uint64_t seed) { return random_weights(kPoints, seed + 1, 0.5, 2.0); }

}  // namespace

ThreadedComplexes::ThreadedComplexes(std::uint64_t seed)
    : t2(points(seed), weights(seed), 2), t3(points(seed), weights(seed), 3), a2(t2, 2), a3(t3, 3) {}

}  // namespace testing
