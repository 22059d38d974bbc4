// SPDX-License-Identifier: Apache-2.0
// ErodedUnion::share_cell: the cell whose share counts a point. The
// boundary is found in eroded_union_boundary.cpp, integrated in
// eroded_union_integrator.cpp.
#include "alpha/eroded_union.hpp"

#include <cmath>

namespace alpha {
namespace {

// Whether x lies on the inner side (that of the opposite vertex) of each
// facet k of finite cell c with bit k set in `facets`.
bool inside_facets(const Triangulation& t, Index c, const Vec3& x, unsigned facets) {
  const auto& v = t.cell(c).v;
  for (int k = 0; k < 4; ++k) {
    if (!(facets >> k & 1)) continue;
    const auto& f = kFacet[k];
    const Vec3 a = t.point(v[f[0]]), ab = t.point(v[f[1]]) - a, ac = t.point(v[f[2]]) - a;
    const Vec3 n = cross(ab, ac);
    const double side = dot(n, x - a), inner = dot(n, t.point(v[k]) - a);
    if (side * inner < 0) return false;
  }
  return true;
}

// The cell holding x by a visibility walk from `start` (floating-point
// sides: a point on a facet may go to either cell); an infinite cell when
// x lies beyond the hull.
Index locate(const Triangulation& t, const Vec3& x, Index start) {
  Index c = start;
  if (t.is_infinite(c)) c = t.cell(c).n[t.infinite_position(c)];
  for (std::size_t step = 0; step < 4 * t.num_cells() + 8; ++step) {
    if (t.is_infinite(c)) return c;
    Index next = kNone;
    for (int i = 0; i < 4 && next == kNone; ++i) {
      const int k = int((i + step) % 4);  // rotating start: no cycling on a flat cell
      if (!inside_facets(t, c, x, 1u << k)) next = t.cell(c).n[k];
    }
    if (next == kNone) return c;
    c = next;
  }
  return c;
}

}  // namespace

Index ErodedUnion::share_cell(const Vec3& x, const Nearest& n, Index hint) const {
  const AlphaComplex& ac = balls_->complex();
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  using On = Nearest::On;
  switch (n.on) {
    case On::far:
      return kNone;
    case On::vertex:
      return vertices_[n.which].cell;
    case On::outside:
      return locate(t, x, hint != kNone ? hint : 0);
    case On::sphere:
    case On::circle: {
      // The cells around the ball's vertex (the edge): their cones (wedges)
      // there are bounded by the facets through it, those opposite the
      // cell's other vertices.
      const auto feature = [&](Index v) {
        return n.on == On::sphere ? v == n.which : v == s.edge(n.which)[0] || v == s.edge(n.which)[1];
      };
      const int features = n.on == On::sphere ? 1 : 2;
      const auto around = [&](Index c) {
        int found = 0;
        for (Index v : t.cell(c).v) found += feature(v);
        return found == features;
      };
      // A walk through those cells, from the hint when it is one of them:
      // across a facet through the feature that has the point on its far
      // side (the first facet tried rotating, as in locate). A few steps
      // where trying every cell around took dozens. Crossing into an
      // infinite cell, the point is beyond a hull facet through the
      // feature, outside every finite cell's cone (they fill the hull's
      // tangent cone there): that cell is the answer (all infinite cells
      // count alike: no share).
      const Index first_edge = n.on == On::sphere ? s.vertex_edges(n.which).front() : n.which;
      Index c = hint;
      if (c == kNone || t.is_infinite(c) || !around(c)) {
        const auto cells = s.triangle_cells(*s.edge_triangles(first_edge).begin());
        c = t.is_infinite(cells[0]) ? cells[1] : cells[0];
      }
      for (std::size_t step = 0; step < 64; ++step) {
        if (t.is_infinite(c)) return c;
        Index next = kNone;
        for (int i = 0; i < 4 && next == kNone; ++i) {
          const int k = int((i + step) % 4);
          if (!feature(t.cell(c).v[k]) && !inside_facets(t, c, n.point, 1u << k)) next = t.cell(c).n[k];
        }
        if (next == kNone) return c;
        c = next;
      }
      // Round in circles (rounding on flat cells; not seen so far): every
      // cell around, the first finite one holding the point, else an
      // infinite one.
      Index any = kNone;
      const auto holds = [&](Index cell) {
        unsigned facets = 0;
        for (int k = 0; k < 4; ++k)
          if (!feature(t.cell(cell).v[k])) facets |= 1u << k;
        return inside_facets(t, cell, n.point, facets);
      };
      const auto search = [&](Index e) {
        for (Index f : s.edge_triangles(e))
          for (Index cell : s.triangle_cells(f)) {
            if (t.is_infinite(cell)) any = cell;
            else if (holds(cell)) return cell;
          }
        return kNone;
      };
      if (n.on == On::circle) {
        const Index found = search(n.which);
        return found != kNone ? found : any;
      }
      for (Index e : s.vertex_edges(n.which))
        if (const Index found = search(e); found != kNone) return found;
      return any;
    }
  }
  return kNone;
}

}  // namespace alpha
