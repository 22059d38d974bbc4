// SPDX-License-Identifier: Apache-2.0
// Vertices of a mesh through points of a curved surface moved off it so
// that its flat triangles enclose the surface's volume, not the chords'.
//
// A flat triangle T through three points of a surface of second fundamental
// form H misses sum_e e^T H e |T| / 24 of the volume under the surface
// (exact for a quadric: the linear interpolant's error integrated over T),
// and for the unit normals n_v, n_w at an edge's ends
// (n_w - n_v).(w - v) = e^T H e to second order. Raising each vertex along
// its normal by an eighth of the mean of that over its edges raises a
// triangle of a uniform mesh by the missing volume: the lattice's bias
// (negative on a cast: its convex probe patches outweigh its concave atom
// patches) becomes third order in the spacing.
#pragma once
#include <span>

#include "alpha/lattice_contour.hpp"

namespace alpha {

// normals: per point, the outward unit normal of the surface it lies on,
// or zero for a point off it (on a flat cap, a crease): those stay, and
// their edges count for no one.
void offset_chords(SurfaceMesh& mesh, std::span<const Vec3> normals);

}  // namespace alpha
