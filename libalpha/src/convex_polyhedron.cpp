// SPDX-License-Identifier: Apache-2.0
#include "convex_polyhedron.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace alpha {
namespace {

// A monotone stand-in for atan2(y, x) in [0, 4), for sorting by angle.
double pseudo_angle(double x, double y) {
  const double l = std::fabs(x) + std::fabs(y);
  if (l == 0) return 0;
  const double p = y / l;
  return x < 0 ? 2 - p : y < 0 ? 4 + p : p;
}

}  // namespace

void ConvexPolyhedron::reset(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  normal_.clear(), vertex_.clear(), start_.assign(1, 0);
  const std::array<Vec3, 4> p{a, b, c, d};
  for (int k = 0; k < 4; ++k) {
    const Vec3& u = p[(k + 1) % 4];
    Vec3 v = p[(k + 2) % 4], w = p[(k + 3) % 4];
    Vec3 n = cross(v - u, w - u);
    if (dot(n, p[k] - u) > 0) std::swap(v, w), n = -1.0 * n;  // the loop turns about the outward normal
    const double length = norm(n);
    if (length == 0) continue;
    normal_.push_back((1 / length) * n);
    vertex_.insert(vertex_.end(), {u, v, w});
    start_.push_back(std::uint32_t(vertex_.size()));
  }
}

void ConvexPolyhedron::clip(const Vec3& n, double offset) {
  side_.resize(vertex_.size());
  double low = 0, high = 0;
  for (std::size_t i = 0; i < vertex_.size(); ++i) {
    const double s = dot(n, vertex_[i]) - offset;
    side_[i] = s;
    low = std::min(low, s), high = std::max(high, s);
  }
  if (high <= 0) return;
  if (low >= 0) {
    normal_.clear(), vertex_.clear(), start_.assign(1, 0);
    return;
  }
  next_normal_.clear(), next_vertex_.clear(), next_start_.assign(1, 0), cap_.clear();
  for (std::size_t f = 0; f < normal_.size(); ++f) {
    const std::uint32_t begin = start_[f], end = start_[f + 1];
    const std::size_t before = next_vertex_.size();
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t j = i + 1 < end ? i + 1 : begin;
      const double sa = side_[i], sb = side_[j];
      if (sa <= 0) {
        next_vertex_.push_back(vertex_[i]);
        if (sa == 0) cap_.emplace_back(0, vertex_[i]);
      }
      if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
        // From the inside end: the face across the edge gets the same point.
        const std::uint32_t in = sa < 0 ? i : j, out = sa < 0 ? j : i;
        const Vec3 x = vertex_[in] + (side_[in] / (side_[in] - side_[out])) * (vertex_[out] - vertex_[in]);
        next_vertex_.push_back(x);
        cap_.emplace_back(0, x);
      }
    }
    if (next_vertex_.size() - before >= 3) {
      next_normal_.push_back(normal_[f]);
      next_start_.push_back(std::uint32_t(next_vertex_.size()));
    } else {
      next_vertex_.resize(before);
    }
  }
  if (cap_.size() >= 3) {
    // The section of a convex polyhedron is convex: its points in angular
    // order about their centroid, counter-clockwise about n.
    const Vec3 normal = (1 / norm(n)) * n;
    const Vec3 axis = std::fabs(normal.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(normal, axis), v = cross(normal, u);
    Vec3 centroid{};
    for (const auto& [angle, x] : cap_) centroid = centroid + x;
    centroid = (1.0 / double(cap_.size())) * centroid;
    for (auto& [angle, x] : cap_) angle = pseudo_angle(dot(x - centroid, u), dot(x - centroid, v));
    // Insertion sort: a section has a handful of points.
    for (std::size_t k = 1; k < cap_.size(); ++k)
      for (std::size_t l = k; l > 0 && cap_[l].first < cap_[l - 1].first; --l) std::swap(cap_[l], cap_[l - 1]);
    for (const auto& [angle, x] : cap_) next_vertex_.push_back(x);
    next_normal_.push_back(normal);
    next_start_.push_back(std::uint32_t(next_vertex_.size()));
  }
  std::swap(normal_, next_normal_), std::swap(vertex_, next_vertex_), std::swap(start_, next_start_);
}

}  // namespace alpha
