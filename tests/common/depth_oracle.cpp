// SPDX-License-Identifier: Apache-2.0
#include "depth_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace testing {

using alpha::Vec3;

DepthOracle::DepthOracle(std::vector<Vec3> centers, std::vector<double> radii, double reach)
    : c_(std::move(centers)), r_(std::move(radii)), reach_(reach) {
  lo_ = {1e300, 1e300, 1e300};
  hi_ = {-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < c_.size(); ++i) {
    const Vec3 p = c_[i];
    const double r = r_[i];
    max_radius_ = std::max(max_radius_, r);
    lo_ = {std::min(lo_.x, p.x - r), std::min(lo_.y, p.y - r), std::min(lo_.z, p.z - r)};
    hi_ = {std::max(hi_.x, p.x + r), std::max(hi_.y, p.y + r), std::max(hi_.z, p.z + r)};
  }
  cell_ = std::max(max_radius_ + reach_, 1e-3);
  const double extent[3] = {hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z};
  for (int a = 0; a < 3; ++a) n_[a] = int(extent[a] / cell_) + 1;
  const auto index = [&](const Vec3& p) {
    return (std::size_t(cell_of(p, 0)) * n_[1] + cell_of(p, 1)) * n_[2] + cell_of(p, 2);
  };
  balls_.resize(std::size_t(n_[0]) * n_[1] * n_[2]);
  triple_points_.resize(balls_.size());
  for (std::size_t i = 0; i < c_.size(); ++i) balls_[index(c_[i])].push_back(int(i));
  // Where three spheres meet, on the boundary.
  for (std::size_t i = 0; i < c_.size(); ++i) {
    std::vector<int> others;
    near(balls_, c_[i], 2 * max_radius_, [&](int j) {
      if (std::size_t(j) > i && alpha::norm(c_[j] - c_[i]) < r_[i] + r_[j]) others.push_back(j);
    });
    for (std::size_t a = 0; a < others.size(); ++a)
      for (std::size_t b = a + 1; b < others.size(); ++b) {
        const int j = others[a], k = others[b];
        const Vec3 p0 = c_[i], u = c_[j] - p0, v = c_[k] - p0, n = cross(u, v);
        const double nn = dot(n, n), w0 = r_[i] * r_[i];
        if (nn == 0) continue;
        const double alpha_u = (dot(u, u) + w0 - r_[j] * r_[j]) / 2, alpha_v = (dot(v, v) + w0 - r_[k] * r_[k]) / 2;
        const Vec3 x = (1 / nn) * (alpha_u * cross(v, n) + alpha_v * cross(n, u));
        const double h2 = w0 - dot(x, x);
        if (h2 < 0) continue;
        for (const double side : {1.0, -1.0}) {
          const Vec3 p = p0 + x + (side * std::sqrt(h2 / nn)) * n;
          if (on_boundary(p)) {
            triple_points_[index(p)].push_back(int(triple_.size()));
            triple_.push_back(p);
          }
        }
      }
  }
}

int DepthOracle::cell_of(const Vec3& p, int axis) const {
  const double x[3] = {p.x - lo_.x, p.y - lo_.y, p.z - lo_.z};
  return std::clamp(int(std::floor(x[axis] / cell_)), 0, n_[axis] - 1);
}

template <class F>
void DepthOracle::near(const std::vector<std::vector<int>>& grid, const Vec3& p, double radius, F f) const {
  const int k = int(std::ceil(radius / cell_));
  const int a = cell_of(p, 0), b = cell_of(p, 1), d = cell_of(p, 2);
  for (int x = std::max(0, a - k); x <= std::min(n_[0] - 1, a + k); ++x)
    for (int y = std::max(0, b - k); y <= std::min(n_[1] - 1, b + k); ++y)
      for (int z = std::max(0, d - k); z <= std::min(n_[2] - 1, d + k); ++z)
        for (int i : grid[(std::size_t(x) * n_[1] + y) * n_[2] + z]) f(i);
}

bool DepthOracle::on_boundary(const Vec3& p) const {
  bool inside = false;
  near(balls_, p, max_radius_, [&](int k) {
    const Vec3 d = p - c_[k];
    inside = inside || dot(d, d) < r_[k] * r_[k] * (1 - 1e-12);
  });
  return !inside;
}

bool DepthOracle::deeper(const Vec3& x, double depth) const {
  // The balls whose sphere comes within `depth` of x; x must be in one.
  std::vector<int> s;
  bool in_union = false;
  near(balls_, x, max_radius_ + depth, [&](int k) {
    const double d = alpha::norm(x - c_[k]);
    in_union = in_union || d < r_[k];
    if (d < r_[k] + depth) s.push_back(k);
  });
  if (!in_union) return false;
  const auto nearer = [&](const Vec3& p) { return alpha::norm(p - x) < depth && on_boundary(p); };
  for (int k : s) {
    const Vec3 d = x - c_[k];
    const double len = alpha::norm(d);
    if (len > 0 && r_[k] > 0 && nearer(c_[k] + (r_[k] / len) * d)) return false;
  }
  for (std::size_t a = 0; a < s.size(); ++a)
    for (std::size_t b = a + 1; b < s.size(); ++b) {
      const int i = s[a], j = s[b];
      const double len = alpha::norm(c_[j] - c_[i]);
      if (len >= r_[i] + r_[j] || len <= std::fabs(r_[i] - r_[j])) continue;
      const Vec3 w = (1 / len) * (c_[j] - c_[i]);
      const double h = (len * len + r_[i] * r_[i] - r_[j] * r_[j]) / (2 * len), rho = std::sqrt(r_[i] * r_[i] - h * h);
      const Vec3 o = c_[i] + h * w, y = x - o, perp = y - dot(y, w) * w;
      const double pl = alpha::norm(perp);
      if (pl > 0 && nearer(o + (rho / pl) * perp)) return false;
    }
  bool near_triple = false;
  near(triple_points_, x, depth, [&](int t) { near_triple = near_triple || alpha::norm(triple_[t] - x) < depth; });
  return !near_triple;
}

std::pair<double, double> DepthOracle::volume_deeper(double depth, long samples, std::uint64_t seed) const {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  long hits = 0;
  for (long k = 0; k < samples; ++k) {
    const Vec3 x{lo_.x + u(rng) * (hi_.x - lo_.x), lo_.y + u(rng) * (hi_.y - lo_.y), lo_.z + u(rng) * (hi_.z - lo_.z)};
    hits += deeper(x, depth);
  }
  const double box = (hi_.x - lo_.x) * (hi_.y - lo_.y) * (hi_.z - lo_.z), f = double(hits) / samples;
  return {box * f, box * std::sqrt(f * (1 - f) / samples)};
}

std::pair<std::vector<double>, std::vector<double>> DepthOracle::cell_volumes_deeper(double depth, long samples,
                                                                                     std::uint64_t seed) const {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<long> hits(c_.size(), 0);
  for (long k = 0; k < samples; ++k) {
    const Vec3 x{lo_.x + u(rng) * (hi_.x - lo_.x), lo_.y + u(rng) * (hi_.y - lo_.y), lo_.z + u(rng) * (hi_.z - lo_.z)};
    if (!deeper(x, depth)) continue;
    std::size_t cell = 0;
    double least = HUGE_VAL;
    for (std::size_t i = 0; i < c_.size(); ++i) {
      const double power = dot(x - c_[i], x - c_[i]) - r_[i] * r_[i];
      if (power < least) least = power, cell = i;
    }
    ++hits[cell];
  }
  const double box = (hi_.x - lo_.x) * (hi_.y - lo_.y) * (hi_.z - lo_.z);
  std::vector<double> volume, sigma;
  for (long h : hits) {
    const double f = double(h) / samples;
    volume.push_back(box * f);
    sigma.push_back(box * std::sqrt(f * (1 - f) / samples));
  }
  return {volume, sigma};
}

}  // namespace testing
