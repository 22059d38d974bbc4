// SPDX-License-Identifier: Apache-2.0
// The part of a ball inside a convex polyhedron, in closed form.
//
// With the ball's centre p as apex, the polyhedron Q is a signed sum of
// the pyramids over its faces, 1_Q = sum_f sign(h_f) 1_pyr(p, f) (h_f: the
// distance from p to f's plane, positive when p is on its inner side).
// A pyramid meets the ball in a solid bounded by the sphere and by f's
// plane inside the disc D_f of radius sqrt(r^2 - h_f^2) about p's foot
// (its other faces pass through p), so by the divergence theorem
//   V(B & pyr) = (r A_f + |h_f| area(f & D_f)) / 3,
// A_f = r^2 * the solid angle of f \ D_f seen from p (the sphere's part
// in the pyramid). Each face splits, about the foot, into signed right
// triangles (foot, foot of the edge's line, edge end), whose areas and
// solid angles inside and outside D_f are elementary (atan2, sqrt); a
// face whose plane misses the ball only needs its solid angle.
// Degenerate faces (zero area, or p in their plane) contribute 0, and
// every term is continuous in the vertices.
#pragma once
#include "union/convex_polyhedron.hpp"

namespace alpha {

struct BallPart {
  double volume = 0;
  double area = 0;  // of the sphere inside the polyhedron
};

// The ball of radius r about the origin inside q.
BallPart ball_in_polyhedron(const ConvexPolyhedron& q, double r);

}  // namespace alpha
