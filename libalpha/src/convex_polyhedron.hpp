// SPDX-License-Identifier: Apache-2.0
// A convex polyhedron as its faces, clipped by half-spaces: the part of a
// tetrahedron inside one power cell (UnionOfBalls::cell_cover).
#pragma once
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "alpha/geometry.hpp"

namespace alpha {

class ConvexPolyhedron {
public:
  ConvexPolyhedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { reset(a, b, c, d); }

  // Becomes the tetrahedron abcd, not flat (its faces' outward sides are
  // taken from its orientation); keeps the storage.
  void reset(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

  // Keeps the part where dot(n, x) <= offset (n not zero). Points are
  // classified in doubles: a plane through a vertex or an edge leaves
  // faces of zero area, which weigh nothing in any measure over the faces.
  void clip(const Vec3& n, double offset);

  bool empty() const { return normal_.empty(); }
  std::size_t num_faces() const { return normal_.size(); }
  // The face's outward unit normal, and its vertex loop, counter-clockwise
  // about the normal.
  const Vec3& normal(std::size_t f) const { return normal_[f]; }
  std::span<const Vec3> loop(std::size_t f) const { return {vertex_.data() + start_[f], start_[f + 1] - start_[f]}; }

private:
  std::vector<Vec3> normal_, vertex_;
  std::vector<std::uint32_t> start_;  // face f's loop: vertex_[start_[f], start_[f + 1])
  // Scratch for clip, kept to avoid allocations.
  std::vector<Vec3> next_normal_, next_vertex_;
  std::vector<std::uint32_t> next_start_;
  std::vector<double> side_;
  std::vector<std::pair<double, Vec3>> cap_;
};

}  // namespace alpha
