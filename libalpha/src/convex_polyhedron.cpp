// SPDX-License-Identifier: Apache-2.0
#include "convex_polyhedron.hpp"

#include <algorithm>
#include <cmath>

namespace alpha {
namespace {

constexpr std::uint32_t kUnset = std::uint32_t(-1);

// A monotone stand-in for atan2(y, x) in [0, 4), for sorting by angle.
double pseudo_angle(double x, double y) {
  const double l = std::fabs(x) + std::fabs(y);
  if (l == 0) return 0;
  const double p = y / l;
  return x < 0 ? 2 - p : y < 0 ? 4 + p : p;
}

}  // namespace

void ConvexPolyhedron::reset(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  normal_.clear(), corner_.clear(), start_.assign(1, 0);
  vertex_.assign({a, b, c, d});
  bool dropped = false;  // a face: then a vertex may be in no loop
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t u = (k + 1) % 4;
    std::uint32_t v = (k + 2) % 4, w = (k + 3) % 4;
    Vec3 n = cross(vertex_[v] - vertex_[u], vertex_[w] - vertex_[u]);
    if (dot(n, vertex_[k] - vertex_[u]) > 0) std::swap(v, w), n = -1.0 * n;  // the loop turns about the outward normal
    const double length = norm(n);
    if (length == 0) {
      dropped = true;
      continue;
    }
    normal_.push_back((1 / length) * n);
    corner_.insert(corner_.end(), {u, v, w});
    start_.push_back(std::uint32_t(corner_.size()));
  }
  if (dropped) keep_referenced();
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
    normal_.clear(), vertex_.clear(), corner_.clear(), start_.assign(1, 0);
    return;
  }
  next_normal_.clear(), next_vertex_.clear(), next_corner_.clear(), next_start_.assign(1, 0), cap_.clear(), cut_.clear();
  renumber_.assign(vertex_.size(), kUnset);
  bool dropped = false;  // a face: then a vertex may be in no loop
  auto kept = [&](std::uint32_t v) {
    if (renumber_[v] == kUnset) renumber_[v] = std::uint32_t(next_vertex_.size()), next_vertex_.push_back(vertex_[v]);
    return renumber_[v];
  };
  // The point where the edge leaves the half-space, from its inside end:
  // computed once for the edge's two faces.
  auto cut = [&](std::uint32_t in, std::uint32_t out) {
    for (const auto& [i, o, x] : cut_)
      if (i == in && o == out) return x;
    const std::uint32_t x = std::uint32_t(next_vertex_.size());
    next_vertex_.push_back(vertex_[in] + (side_[in] / (side_[in] - side_[out])) * (vertex_[out] - vertex_[in]));
    cut_.push_back({in, out, x});
    return x;
  };
  for (std::size_t f = 0; f < normal_.size(); ++f) {
    const std::uint32_t begin = start_[f], end = start_[f + 1];
    const std::size_t before = next_corner_.size();
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = corner_[k], j = corner_[k + 1 < end ? k + 1 : begin];
      const double sa = side_[i], sb = side_[j];
      if (sa <= 0) {
        next_corner_.push_back(kept(i));
        if (sa == 0) cap_.emplace_back(0, next_corner_.back());
      }
      if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
        next_corner_.push_back(sa < 0 ? cut(i, j) : cut(j, i));
        cap_.emplace_back(0, next_corner_.back());
      }
    }
    if (next_corner_.size() - before >= 3) {
      next_normal_.push_back(normal_[f]);
      next_start_.push_back(std::uint32_t(next_corner_.size()));
    } else {
      next_corner_.resize(before);
      dropped = true;
    }
  }
  if (cap_.size() >= 3) {
    // The section of a convex polyhedron is convex: its points in angular
    // order about their centroid, counter-clockwise about n.
    const Vec3 normal = (1 / norm(n)) * n;
    const Vec3 axis = std::fabs(normal.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(normal, axis), v = cross(normal, u);
    Vec3 centroid{};
    for (const auto& [angle, x] : cap_) centroid = centroid + next_vertex_[x];
    centroid = (1.0 / double(cap_.size())) * centroid;
    for (auto& [angle, x] : cap_) {
      const Vec3 d = next_vertex_[x] - centroid;
      angle = pseudo_angle(dot(d, u), dot(d, v));
    }
    // Insertion sort: a section has a handful of points.
    for (std::size_t k = 1; k < cap_.size(); ++k)
      for (std::size_t l = k; l > 0 && cap_[l].first < cap_[l - 1].first; --l) std::swap(cap_[l], cap_[l - 1]);
    for (const auto& [angle, x] : cap_) next_corner_.push_back(x);
    next_normal_.push_back(normal);
    next_start_.push_back(std::uint32_t(next_corner_.size()));
  }
  std::swap(normal_, next_normal_), std::swap(vertex_, next_vertex_), std::swap(corner_, next_corner_),
      std::swap(start_, next_start_);
  if (dropped) keep_referenced();
}

void ConvexPolyhedron::keep_referenced() {
  // Vertices of faces left out (fewer than three points) would take part
  // in the next clip's classification.
  renumber_.assign(vertex_.size(), kUnset);
  for (const std::uint32_t v : corner_) renumber_[v] = 0;
  std::uint32_t next = 0;
  for (std::uint32_t v = 0; v < vertex_.size(); ++v)
    if (renumber_[v] != kUnset) vertex_[next] = vertex_[v], renumber_[v] = next++;
  vertex_.resize(next);
  for (std::uint32_t& v : corner_) v = renumber_[v];
}

}  // namespace alpha
