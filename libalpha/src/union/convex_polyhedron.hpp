// SPDX-License-Identifier: Apache-2.0
// A convex polyhedron as its faces, clipped by half-spaces: the part of a
// tetrahedron inside one power cell (UnionOfBalls::cell_cover).
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "alpha/geometry.hpp"

namespace alpha {

class ConvexPolyhedron {
public:
  ConvexPolyhedron() = default;  // empty
  ConvexPolyhedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { reset(a, b, c, d); }

  // Becomes the tetrahedron abcd, not flat (its faces' outward sides are
  // taken from its orientation); keeps the storage.
  void reset(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

  // Keeps the part where dot(n, x) <= offset (n not zero). Points are
  // classified in doubles: a plane through a vertex or an edge leaves
  // faces of zero area, which weigh nothing in any measure over the faces.
  void clip(const Vec3& n, double offset);

  bool empty() const { return faces_ == 0; }
  std::size_t num_faces() const { return faces_; }
  // The face's outward unit normal, and its vertex loop (indices of
  // vertex()), counter-clockwise about the normal.
  const Vec3& normal(std::size_t f) const { return normal_[f]; }
  std::span<const std::uint32_t> loop(std::size_t f) const {
    return {corner_.data() + start_[f], start_[f + 1] - start_[f]};
  }
  const Vec3& vertex(std::uint32_t v) const { return vertex_[v]; }

private:
  // Every vertex once (a clip classifies each once and cuts each edge
  // once), and each one referenced by a loop. A loop may name a vertex
  // twice in a row (a cap lists each point cut on an edge once per face
  // of the edge).
  void keep_referenced();
  // The buffers only grow (none is filled again per clip): faces_ and
  // vertices_ say how much of normal_, start_ (one more) and vertex_ is
  // the polyhedron's.
  std::vector<Vec3> normal_, vertex_;
  std::vector<std::uint32_t> corner_, start_{0};  // face f's loop: corner_[start_[f], start_[f + 1])
  std::uint32_t faces_ = 0, vertices_ = 0;
  // Scratch for clip, kept to avoid allocations.
  std::vector<Vec3> next_normal_, next_vertex_;
  std::vector<std::uint32_t> next_corner_, next_start_, renumber_;
  std::vector<double> side_;
  std::vector<std::array<std::uint32_t, 3>> cut_;  // (inside end, outside end, the point cut)
  std::vector<std::pair<double, std::uint32_t>> cap_;
};

}  // namespace alpha
