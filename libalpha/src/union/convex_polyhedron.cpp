// SPDX-License-Identifier: Apache-2.0
#include "union/convex_polyhedron.hpp"

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

// The first n elements of v, made room for (the buffers only grow).
template <class T>
T* room(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
  return v.data();
}

}  // namespace

void ConvexPolyhedron::reset(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Vec3* vertex = room(vertex_, 4);
  vertex[0] = a, vertex[1] = b, vertex[2] = c, vertex[3] = d;
  vertices_ = 4;
  Vec3* normal = room(normal_, 4);
  std::uint32_t* corner = room(corner_, 12);
  std::uint32_t* start = room(start_, 5);
  std::uint32_t faces = 0, corners = 0;
  bool dropped = false;  // a face: then a vertex may be in no loop
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t u = (k + 1) % 4;
    std::uint32_t v = (k + 2) % 4, w = (k + 3) % 4;
    Vec3 n = cross(vertex[v] - vertex[u], vertex[w] - vertex[u]);
    if (dot(n, vertex[k] - vertex[u]) > 0) std::swap(v, w), n = -1.0 * n;  // the loop turns about the outward normal
    const double length = norm(n);
    if (length == 0) {
      dropped = true;
      continue;
    }
    normal[faces] = (1 / length) * n;
    corner[corners++] = u, corner[corners++] = v, corner[corners++] = w;
    start[++faces] = corners;
  }
  faces_ = faces;
  if (dropped) keep_referenced();
}

void ConvexPolyhedron::clip(const Vec3& n, double offset) {
  const std::uint32_t nv = vertices_;
  double* side = room(side_, nv);
  double low = 0, high = 0;
  for (std::uint32_t i = 0; i < nv; ++i) {
    const double s = dot(n, vertex_[i]) - offset;
    side[i] = s;
    low = std::min(low, s), high = std::max(high, s);
  }
  if (high <= 0) return;
  if (low >= 0) {
    faces_ = 0, vertices_ = 0;
    return;
  }
  // Room for the most a clip can make: per corner of a loop, the corner
  // and a cut point in the face and one point in the cap.
  const std::uint32_t nc = start_[faces_];
  Vec3* next_vertex = room(next_vertex_, nv + nc);
  std::uint32_t* next_corner = room(next_corner_, 3 * std::size_t(nc));
  Vec3* next_normal = room(next_normal_, faces_ + 1);
  std::uint32_t* next_start = room(next_start_, faces_ + 2);
  std::uint32_t* renumber = room(renumber_, nv);
  std::fill_n(renumber, nv, kUnset);
  std::pair<double, std::uint32_t>* cap = room(cap_, nc);
  std::array<std::uint32_t, 3>* cuts = room(cut_, nc);
  std::uint32_t vertices = 0, corners = 0, faces = 0, caps = 0, cut_count = 0;
  next_start[0] = 0;
  bool dropped = false;  // a face: then a vertex may be in no loop
  auto kept = [&](std::uint32_t v) {
    if (renumber[v] == kUnset) renumber[v] = vertices, next_vertex[vertices++] = vertex_[v];
    return renumber[v];
  };
  // The point where the edge leaves the half-space, from its inside end:
  // computed once for the edge's two faces.
  auto cut = [&](std::uint32_t in, std::uint32_t out) {
    for (std::uint32_t k = 0; k < cut_count; ++k)
      if (cuts[k][0] == in && cuts[k][1] == out) return cuts[k][2];
    const std::uint32_t x = vertices;
    next_vertex[vertices++] = vertex_[in] + (side[in] / (side[in] - side[out])) * (vertex_[out] - vertex_[in]);
    cuts[cut_count++] = {in, out, x};
    return x;
  };
  for (std::uint32_t f = 0; f < faces_; ++f) {
    const std::uint32_t begin = start_[f], end = start_[f + 1];
    const std::uint32_t before = corners;
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = corner_[k], j = corner_[k + 1 < end ? k + 1 : begin];
      const double sa = side[i], sb = side[j];
      if (sa <= 0) {
        next_corner[corners++] = kept(i);
        if (sa == 0) cap[caps++] = {0, next_corner[corners - 1]};
      }
      if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
        next_corner[corners++] = sa < 0 ? cut(i, j) : cut(j, i);
        cap[caps++] = {0, next_corner[corners - 1]};
      }
    }
    if (corners - before >= 3) {
      next_normal[faces++] = normal_[f];
      next_start[faces] = corners;
    } else {
      corners = before;
      dropped = true;
    }
  }
  if (caps >= 3) {
    // The section of a convex polyhedron is convex: its points in angular
    // order about their centroid, counter-clockwise about n.
    const Vec3 normal = (1 / norm(n)) * n;
    const Vec3 axis = std::fabs(normal.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(normal, axis), v = cross(normal, u);
    Vec3 centroid{};
    for (std::uint32_t k = 0; k < caps; ++k) centroid = centroid + next_vertex[cap[k].second];
    centroid = (1.0 / double(caps)) * centroid;
    for (std::uint32_t k = 0; k < caps; ++k) {
      const Vec3 d = next_vertex[cap[k].second] - centroid;
      cap[k].first = pseudo_angle(dot(d, u), dot(d, v));
    }
    // Insertion sort: a section has a handful of points.
    for (std::uint32_t k = 1; k < caps; ++k)
      for (std::uint32_t l = k; l > 0 && cap[l].first < cap[l - 1].first; --l) std::swap(cap[l], cap[l - 1]);
    for (std::uint32_t k = 0; k < caps; ++k) next_corner[corners++] = cap[k].second;
    next_normal[faces++] = normal;
    next_start[faces] = corners;
  }
  std::swap(normal_, next_normal_), std::swap(vertex_, next_vertex_), std::swap(corner_, next_corner_),
      std::swap(start_, next_start_);
  faces_ = faces, vertices_ = vertices;
  if (dropped) keep_referenced();
}

void ConvexPolyhedron::keep_referenced() {
  // Vertices of faces left out (fewer than three points) would take part
  // in the next clip's classification.
  std::uint32_t* renumber = room(renumber_, vertices_);
  std::fill_n(renumber, vertices_, kUnset);
  const std::uint32_t corners = start_[faces_];
  for (std::uint32_t k = 0; k < corners; ++k) renumber[corner_[k]] = 0;
  std::uint32_t next = 0;
  for (std::uint32_t v = 0; v < vertices_; ++v)
    if (renumber[v] != kUnset) vertex_[next] = vertex_[v], renumber[v] = next++;
  vertices_ = next;
  for (std::uint32_t k = 0; k < corners; ++k) corner_[k] = renumber[corner_[k]];
}

}  // namespace alpha
