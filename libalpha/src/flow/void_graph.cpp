// SPDX-License-Identifier: Apache-2.0
#include "alpha/void_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "alpha/error.hpp"

namespace alpha {
namespace {

// Distance from x to the nearest of the given balls' spheres (negative inside).
template <class Vertices>
double clearance_at(const Vec3& x, const Vertices& vs, const Triangulation& t, std::span<const double> radii) {
  double d = std::numeric_limits<double>::infinity();
  for (const Index v : vs) d = std::min(d, norm(x - t.point(v)) - radii[v]);
  return d;
}

// The vertex of cell v not in triangle tri.
Index apex(const std::array<Index, 4>& v, const std::array<Index, 3>& tri) {
  return v[0] + v[1] + v[2] + v[3] - tri[0] - tri[1] - tri[2];
}

}  // namespace

VoidGraph::VoidGraph(const AlphaComplex& ac, std::span<const double> radii)
    : t_(&ac.triangulation()), s_(&ac.simplices()) {
  const Triangulation& t = *t_;
  if (radii.size() != t.num_points()) throw Error("void graph: one radius per point needed", ErrorKind::Misuse);
  SizeKernel sizes = ac.size_kernel();
  const double inf = std::numeric_limits<double>::infinity();
  position_.assign(num_nodes(), Vec3{inf, inf, inf});
  node_clearance_.assign(num_nodes(), inf);
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (t.is_infinite(c)) continue;
    const auto& v = t.cell(c).v;
    position_[c] = sizes.center(Simplex(v[0], v[1], v[2], v[3]));
    node_clearance_[c] = clearance_at(position_[c], v, t, radii);
  }
  const Simplices& s = *s_;
  narrowest_.resize(s.num_triangles());
  clearance_.resize(s.num_triangles());
  for (Index f = 0; f < s.num_triangles(); ++f) {
    const auto tri = s.triangle(f);
    const Simplex simplex(tri[0], tri[1], tri[2]);
    const auto cells = s.triangle_cells(f);
    Vec3 at;
    if (!ac.triangle_interval(f).attached) {
      at = sizes.center(simplex);  // the orthocentre lies on the dual segment
    } else {
      // The cell whose opposite vertex attaches f holds the narrowest point;
      // an infinite cell has no vertex that could. Exactly one does (both
      // would put each cell's orthocentre beyond f's plane on the other's
      // side, against each apex's positive power to the other cell's
      // orthosphere): one test decides.
      Index attaching = t.is_infinite(cells[0]) ? cells[1] : cells[0];
      const Index other = attaching == cells[0] ? cells[1] : cells[0];
      if (!t.is_infinite(other) && !sizes.attached(simplex, apex(t.cell(attaching).v, tri))) attaching = other;
      at = position_[attaching];
    }
    narrowest_[f] = at;
    clearance_[f] = clearance_at(at, tri, t, radii);
    if (t.is_infinite(cells[0]) || t.is_infinite(cells[1])) hull_edges_.push_back(f);
  }
}

}  // namespace alpha
