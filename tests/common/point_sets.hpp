// SPDX-License-Identifier: Apache-2.0
// Point sets for the tests: random, degenerate and weighted, all seeded.
#pragma once
#include <cstdint>
#include <vector>

#include "alpha/geometry.hpp"

namespace testing {

std::vector<alpha::Vec3> random_points(std::size_t n, std::uint64_t seed, double scale = 1.0);
// n x n x n integer grid: every cube's 8 corners are cospherical.
std::vector<alpha::Vec3> grid_points(int n, double spacing = 1.0);
// Points exactly on a sphere: integer solutions of x^2+y^2+z^2 = r2.
std::vector<alpha::Vec3> sphere_points(int r2);
// Each point moved by `step` in a random direction.
std::vector<alpha::Vec3> jitter(std::vector<alpha::Vec3> points, double step, std::uint64_t seed);
// Random weights in [lo, hi).
std::vector<double> random_weights(std::size_t n, std::uint64_t seed, double lo, double hi);

// n points on the circle of radius R about the z axis in the plane z = h,
// the first at angle `phase`.
std::vector<alpha::Vec3> ring_points(int n, double R, double h, double phase = 0);
// A closed cage: n Fibonacci points on the sphere of radius S about the
// origin, but for the cap within `cap` radians of +z, whose rim gets a ring
// of `window` points (a window of radius S sin(cap) at height S cos(cap)).
std::vector<alpha::Vec3> cage_points(int n, double S, double cap, int window);

}  // namespace testing
