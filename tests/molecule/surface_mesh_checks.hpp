// SPDX-License-Identifier: Apache-2.0
// Checks of a triangle mesh as a surface (on vertex indices, as a viewer
// such as MeshLab sees a file): closed and manifold, consistently oriented,
// no two triangles crossing, its area and enclosed volume.
#pragma once
#include <cstddef>
#include <string>

#include "alpha/lattice_contour.hpp"

namespace testing {

struct SurfaceReport {
  std::size_t boundary_edges = 0;     // edges of one triangle
  std::size_t nonmanifold_edges = 0;  // edges of three or more triangles
  std::size_t misoriented_edges = 0;  // edges of two triangles run through the same way
  std::size_t nonmanifold_vertices = 0;  // vertices with more than one fan of triangles
  std::size_t degenerate_triangles = 0;  // a repeated vertex index
  std::size_t components = 0;         // connected through edges
  double area = 0, volume = 0;        // volume by the divergence theorem (positive: outward)
  bool closed_manifold() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 && nonmanifold_vertices == 0 &&
           degenerate_triangles == 0;
  }
  std::string summary() const;
};

SurfaceReport surface_report(const alpha::SurfaceMesh& mesh);

// An ASCII OFF file of triangles with its vertex indices as written (no
// merging or repair, unlike OpenMesh's reader: what MeshLab checks).
// REQUIREs a well-formed file.
alpha::SurfaceMesh read_off(const std::string& path);

// Pairs of triangles that cross or touch other than along a shared edge or
// at a shared vertex, decided exactly (orientation predicates in exact
// arithmetic on the float coordinates a file holds); triangles are
// bucketed in a grid, so any size of mesh is checked in full.
std::size_t intersecting_pairs(const alpha::SurfaceMesh& mesh);

}  // namespace testing
