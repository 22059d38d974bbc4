#include "point_sets.hpp"

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

}  // namespace testing
