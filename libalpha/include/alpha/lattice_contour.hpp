// SPDX-License-Identifier: Apache-2.0
// A closed surface around the inside nodes of a cubic lattice: marching
// tetrahedra on the Freudenthal (Kuhn) triangulation of its cubes (each
// cube cut into 6 tetrahedra along its main diagonal, the same way in
// every cube, so neighbouring cubes share their facets' triangles).
//
// The surface crosses each tetrahedron edge from an inside to an outside
// node once, at a point the caller chooses strictly between the two; in a
// tetrahedron it is one triangle (one node apart from the other three) or
// two (two and two). Whatever the points chosen, the result is the
// boundary of a solid: every edge joins exactly two triangles, run through
// in opposite directions, every vertex has one fan of triangles around it
// (a closed, consistently oriented 2-manifold), and no two triangles cross
// (each lies in its own tetrahedron and meets its neighbours' only on the
// facet they share, along the same segment). That holds because the
// surface is a level set of a piecewise linear function with no node on
// the level; it needs the lattice's border nodes outside.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "alpha/geometry.hpp"

namespace alpha {

struct Lattice {
  Vec3 origin{};
  double spacing = 1;
  std::array<std::size_t, 3> size{};  // nodes per axis

  std::size_t num_nodes() const { return size[0] * size[1] * size[2]; }
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return i + size[0] * (j + size[1] * k); }
  Vec3 node(std::size_t n) const {
    const std::size_t i = n % size[0], j = n / size[0] % size[1], k = n / (size[0] * size[1]);
    return {origin.x + spacing * double(i), origin.y + spacing * double(j), origin.z + spacing * double(k)};
  }
};

struct SurfaceMesh {
  std::vector<Vec3> points;
  // Indices into points, counter-clockwise seen from outside: the normal
  // (b - a) x (c - a) points out of the solid.
  std::vector<std::array<Index, 3>> triangles;
};

// The volume a closed mesh so oriented encloses (the divergence theorem).
double enclosed_volume(const SurfaceMesh& mesh);

// Cubes are visited in blocks of kContourBlock^3 (a caller's cache of what
// is near a block stays valid for many calls).
inline constexpr std::size_t kContourBlock = 4;

// The surface around the nodes with inside[n] != 0 (one flag per node,
// numbered as Lattice::index). vertex(a, b, cube) gives the point on the
// segment from inside node a to outside node b, strictly between them; it
// is called once per edge crossed, cube by cube in block order, from the
// first cube holding the edge (`cube`: its lowest node, so the blocks of
// nodes and of cubes are numbered alike). Throws alpha::Error if inside has
// the wrong size or a border node is inside.
//
// split(p, q), if given, may bend the surface's segment between vertices p
// and q (ids of points already made) on the lattice triangle holding both:
// a point returned, strictly inside that triangle, becomes the next vertex
// and the segment runs through it in both tetrahedra sharing the triangle
// (a crease of the surface the lattice would cut). It is called once per
// such segment. A tetrahedron's polygon with points so inserted is fanned
// from the first of them (two: the crease between them is an edge), so the
// result is still a closed, consistently oriented 2-manifold, each
// triangle in its tetrahedron; but a fan can fold where a point is near
// the triangle's sides or the polygon's other vertices near its nodes, so
// that no triangles cross is then the caller's to keep (cells_mesh keeps
// its points clear of both; tested).
using ContourSplit = std::function<std::optional<Vec3>(Index, Index)>;
SurfaceMesh contour(const Lattice& lattice, const std::vector<std::uint8_t>& inside,
                    const std::function<Vec3(std::size_t, std::size_t, std::size_t)>& vertex,
                    const ContourSplit& split = {});

}  // namespace alpha
