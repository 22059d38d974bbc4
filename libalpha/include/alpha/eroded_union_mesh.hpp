// SPDX-License-Identifier: Apache-2.0
// Triangle meshes of an eroded union (alpha/eroded_union.hpp): its
// boundary (for the probe-inflated atoms of a molecule, the molecular or
// solvent-excluded surface), and the space outside the eroded body that a
// set of cells holds (a cavity's cast).
//
// Both are contours (alpha/lattice_contour.hpp) on a cubic lattice of the
// given spacing, aligned to multiples of it, so they are closed,
// consistently oriented 2-manifolds without self-intersections whatever
// the input. The implicit function is exact where it is evaluated: a point
// x is in the eroded body when its distance to F (the closure of the
// union's complement) is at least r, computed from the union's boundary
// pieces (ErodedUnion::Nearby). Each mesh vertex lies on a lattice edge
// where that changes, located by root finding on the exact distance to
// 1e-4 of the edge (5e-5 A at 0.5 A; up to 8e-3 A where the last Newton
// step, taken without evaluating, crosses a change of the nearest piece):
// the vertices lie on the exact surface up to that, so area and
// volume converge to the analytic ones as the spacing shrinks (on 1A26
// chain A at 0.5 A both are within 1%; see docs/outputs.md, Meshes).
//
// A cast (cells_mesh) is the set of points outside the eroded body whose
// space is counted in the cells' shares (ErodedUnion::share_cell): the free
// space in the cells, and the probe layer whose nearest point of F lies in
// them; it is capped flat where the cells end in free space (a pocket's
// mouths). Its volume approaches the cells' layer shares plus their free
// space (a cavity's ms_volume): the layer shares are of the same regions
// of space, and the free space is the cells less the union's part in each
// (UnionOfBalls::cell_cover, exact per cell). Its vertices on the
// molecular surface are found as the
// surface's are (Newton's method on the distance); the others (mouths,
// where another cell's share begins) by bisection on that membership, to
// 1e-4 of the spacing. Where the molecular surface meets a mouth the cast
// has a crease, whose corner a lattice cuts (a volume of the crease's
// length times the spacing squared): the segment between a vertex on
// either side is bent toward the crease's point on their lattice triangle
// (contour's split), found from the surface's tangent plane and a second
// point of the mouth.
//
// Cost: blocks of the lattice that the balls alone show to be outside the
// union or deep in the body (alpha/nearest_ball.hpp) are labelled without
// gathering the boundary's pieces near them; the others gather them once
// for their nodes' labels and once for the crossings of their cubes.
#pragma once
#include <span>
#include <vector>

#include "alpha/eroded_union.hpp"
#include "alpha/lattice_contour.hpp"

namespace alpha {

struct ErodedUnionMesh {
  SurfaceMesh mesh;
  // Per point: the cell whose share counts it (ErodedUnion::share_cell),
  // kNone if none was found; may be an infinite cell.
  std::vector<Index> share_cells;
};

// The boundary of the eroded body, every component oriented outward.
// spacing > 0. Throws alpha::Error for a bad spacing or a lattice of more
// than 2^31 nodes.
ErodedUnionMesh eroded_union_mesh(const ErodedUnion& eu, double spacing);

// The cast of `cells` (sorted ids of finite cells), oriented outward (from
// the cast into the body and out of its mouths).
SurfaceMesh cells_mesh(const ErodedUnion& eu, std::span<const Index> cells, double spacing);

}  // namespace alpha
