// SPDX-License-Identifier: Apache-2.0
#include "cavities/cavity_space.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace molecule {
namespace {

using alpha::Index;
using alpha::Vec3;

// Area of the lens two discs (radii r0, r1, centres d apart) share.
double lens_area(double r0, double r1, double d) {
  if (d >= r0 + r1) return 0;
  const double r = std::min(r0, r1);
  if (d <= std::fabs(r0 - r1)) return std::numbers::pi * r * r;
  // One circular segment per disc, cut by the common chord at distance x
  // from the disc's centre (negative: the chord is beyond the centre).
  const auto segment = [](double radius, double x) {
    const double half_chord = std::sqrt(std::max(0.0, radius * radius - x * x));
    return radius * radius * std::atan2(half_chord, x) - x * half_chord;
  };
  const double x0 = (d * d + r0 * r0 - r1 * r1) / (2 * d);
  return segment(r0, x0) + segment(r1, d - x0);
}

}  // namespace

CavitySpace::CavitySpace(const alpha::UnionOfBalls& u) : ac_(u.complex()), union_(u), level_(ac_.level(0.0)) {}

CellSpace CavitySpace::cell(Index c) const {
  const alpha::Triangulation& t = ac_.triangulation();
  const auto& v = t.cell(c).v;
  const Vec3 &a = t.point(v[0]), &b = t.point(v[1]), &d = t.point(v[2]), &e = t.point(v[3]);
  CellSpace m;
  m.volume = alpha::tetrahedron_volume(a, b, d, e);
  const alpha::CellCover cover = union_.cell_cover(c);
  m.sa_empty = m.volume - cover.volume;
  m.sa_area = cover.area;
  m.centroid = 0.25 * (a + b + d + e);
  return m;
}

double CavitySpace::open_area(Index f) const {
  const alpha::Triangulation& t = ac_.triangulation();
  const alpha::Simplices& s = ac_.simplices();
  const auto& fv = s.triangle(f);
  double covered = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = t.point(fv[i]);
    const Vec3 u = t.point(fv[(i + 1) % 3]) - p, w = t.point(fv[(i + 2) % 3]) - p;
    const double angle = std::atan2(norm(cross(u, w)), dot(u, w));
    covered += angle / 2 * t.weight(fv[i]);  // the sector: angle/2 r^2
  }
  for (Index e : s.triangle_edges(f)) {
    if (ac_.edge_interval(e).entry >= level_) continue;
    const auto& ev = s.edge(e);
    covered -= lens_area(std::sqrt(t.weight(ev[0])), std::sqrt(t.weight(ev[1])),
                         norm(t.point(ev[1]) - t.point(ev[0]))) / 2;
  }
  const double area = alpha::triangle_area(t.point(fv[0]), t.point(fv[1]), t.point(fv[2]));
  return std::max(0.0, area - covered);
}

// Closest point by the Voronoi region of p among the triangle's vertices,
// edges and face (Ericson, Real-Time Collision Detection, 5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(p - a);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return norm(p - (a + (d1 / (d1 - d3)) * ab));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return norm(p - (a + (d2 / (d2 - d6)) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return norm(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
  const double denom = 1 / (va + vb + vc);
  return norm(p - (a + (vb * denom) * ab + (vc * denom) * ac));
}

}  // namespace molecule
