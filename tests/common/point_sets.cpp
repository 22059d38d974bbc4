// SPDX-License-Identifier: Apache-2.0
#include "point_sets.hpp"

#include <cmath>
#include <random>

namespace testing {

std::vector<alpha::Vec3> random_points(std::size_t n, std::uint64_t seed, double scale) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, scale);
  std::vector<alpha::Vec3> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  return pts;
}

std::vector<alpha::Vec3> grid_points(int n, double spacing) {
  std::vector<alpha::Vec3> pts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) pts.push_back({i * spacing, j * spacing, k * spacing});
  return pts;
}

std::vector<alpha::Vec3> sphere_points(int r2) {
  std::vector<alpha::Vec3> pts;
  for (int x = -r2; x <= r2; ++x)
    for (int y = -r2; y <= r2; ++y)
      for (int z = -r2; z <= r2; ++z)
        if (x * x + y * y + z * z == r2) pts.push_back({double(x), double(y), double(z)});
  return pts;
}

std::vector<double> random_weights(std::size_t n, std::uint64_t seed, double lo, double hi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> w(n);
  for (auto& x : w) x = u(rng);
  return w;
}

std::vector<alpha::Vec3> jitter(std::vector<alpha::Vec3> points, double step, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  for (alpha::Vec3& q : points) {
    const alpha::Vec3 d{g(rng), g(rng), g(rng)};
    q = q + (step / alpha::norm(d)) * d;
  }
  return points;
}

std::vector<alpha::Vec3> ring_points(int n, double R, double h, double phase) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<alpha::Vec3> pts;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * kPi * i / n;
    pts.push_back({R * std::cos(a), R * std::sin(a), h});
  }
  return pts;
}

std::vector<alpha::Vec3> cage_points(int n, double S, double cap, int window) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<alpha::Vec3> pts;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, phi = i * kPi * (3 - std::sqrt(5.0));
    if (z > std::cos(cap) - 0.02) continue;
    const double rho = std::sqrt(1 - z * z);
    pts.push_back({S * rho * std::cos(phi), S * rho * std::sin(phi), S * z});
  }
  for (const alpha::Vec3& p : ring_points(window, S * std::sin(cap), S * std::cos(cap))) pts.push_back(p);
  return pts;
}

}  // namespace testing
