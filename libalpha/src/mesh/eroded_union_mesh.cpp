// SPDX-License-Identifier: Apache-2.0
#include "alpha/eroded_union_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <list>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "alpha/error.hpp"
#include "mesh/chord_offset.hpp"
#include "alpha/nearest_ball.hpp"

namespace alpha {
namespace {

using Nearby = ErodedUnion::Nearby;
using Nearest = ErodedUnion::Nearest;

// Root finding stops when the point is this fraction of the edge's length
// from the exact surface (the distance to F is within it of r), or the
// bracket this short: 5e-5 A at 0.5 A, a thousandth of what moves the
// area or volume by 1e-5 relative.
constexpr double kRootPrecision = 1e-4;
// A vertex stays this fraction of the spacing away from the nodes: far
// enough to stay apart in a file's single precision (a float's step is
// 6e-5 A at 500 A), or triangles at a node cross once written.
constexpr double kNodeGap = 1e-3;
// How far across a lattice triangle (a fraction of its edge) the second
// point of a cast's mouth boundary is sought, for the boundary's direction
// where the molecular surface meets it (cells_mesh).
constexpr double kCreaseProbe = 0.125;
// A boundary point inserted on a segment is at least this fraction of the
// spacing off it.
constexpr double kCreaseDepth = 0.01;
// A crease's point stays this far inside its lattice triangle (barycentric),
// and none is sought next to a vertex this close to a node (of its edge):
// the triangles there are too thin to bend without crossing once written.
constexpr double kCreaseGap = 0.1;
// Blocks whose neighbourhoods are kept.
constexpr std::size_t kCachedBlocks = 8;
// Cubes per axis of the parts of a block whose crossings ask a
// neighbourhood narrowed to them (a divisor of kContourBlock): the
// crossings near one point of F ask about a tenth of a block's pieces.
constexpr std::size_t kCubeGroup = 2;
static_assert(kContourBlock % kCubeGroup == 0);

// The lattice of `spacing` (aligned to its multiples) over the box [lo, hi]
// with two nodes to spare on every side.
Lattice lattice_over(const Vec3& lo, const Vec3& hi, double spacing) {
  if (!(spacing > 0) || !std::isfinite(spacing))
    fail("mesh: the lattice spacing must be a number > 0", ErrorKind::Misuse);
  Lattice l;
  l.spacing = spacing;
  const double low[3] = {lo.x, lo.y, lo.z}, high[3] = {hi.x, hi.y, hi.z};
  double origin[3];
  double nodes = 1;
  for (int a = 0; a < 3; ++a) {
    origin[a] = (std::floor(low[a] / spacing) - 2) * spacing;
    const double n = std::ceil((high[a] - origin[a]) / spacing) + 3;
    nodes *= n;
    if (!(nodes < double(std::int64_t(1) << 31)))
      fail("mesh: the lattice would have more than 2^31 nodes", ErrorKind::LimitExceeded);
    l.size[a] = std::size_t(n);
  }
  l.origin = {origin[0], origin[1], origin[2]};
  return l;
}

// The Nearby of the lattice's blocks (of kContourBlock nodes per axis),
// reaching every point within one spacing of the block's nodes (its cubes)
// and `limit` beyond: the last few blocks asked for are kept.
class BlockHoods {
public:
  BlockHoods(const ErodedUnion& eu, const Lattice& lattice, double limit) : eu_(eu), lattice_(lattice), limit_(limit) {}

  const Nearby& of(std::size_t node) {
    const std::size_t B = kContourBlock, nx = lattice_.size[0], ny = lattice_.size[1];
    const std::size_t i = node % nx / B, j = node / nx % ny / B, k = node / (nx * ny) / B;
    const std::uint64_t key = (std::uint64_t(k) << 42) | (std::uint64_t(j) << 21) | i;
    for (auto it = cache_.begin(); it != cache_.end(); ++it)
      if (it->first == key) {
        cache_.splice(cache_.begin(), cache_, it);
        return cache_.front().second;
      }
    const double reach = half_diagonal() + lattice_.spacing * std::sqrt(3.0) + limit_ - eu_.r();
    cache_.emplace_front(key, eu_.nearby(center(node), reach));
    if (cache_.size() > kCachedBlocks) cache_.pop_back();
    return cache_.front().second;
  }
  // For the points on the edges of `cube` (its lowest node): the Nearby of
  // its group of kCubeGroup^3 cubes, narrowed from its block's. The last
  // group of each place in a block is kept (cubes are visited block by
  // block).
  const Nearby& of_cube(std::size_t cube) {
    const std::size_t G = kCubeGroup, nx = lattice_.size[0], ny = lattice_.size[1];
    const std::size_t i = cube % nx / G * G, j = cube / nx % ny / G * G, k = cube / (nx * ny) / G * G;
    const std::size_t group = lattice_.index(i, j, k), per = kContourBlock / G;
    auto& [key, near] = groups_[i / G % per + per * (j / G % per + per * (k / G % per))];
    if (near && key == group) return *near;
    const double h = lattice_.spacing, half = double(G) / 2;
    const Vec3 center = lattice_.origin + Vec3{h * (double(i) + half), h * (double(j) + half), h * (double(k) + half)};
    near.emplace(of(cube).narrowed(center, std::sqrt(3.0) * half * h + limit_ - eu_.r()));
    key = group;
    return *near;
  }
  // The centre of the block of `node`: every node of the block and its
  // cubes are within half_diagonal() + sqrt(3) spacings of it.
  Vec3 center(std::size_t node) const {
    const std::size_t B = kContourBlock, nx = lattice_.size[0], ny = lattice_.size[1];
    const std::size_t i = node % nx / B, j = node / nx % ny / B, k = node / (nx * ny) / B;
    const double h = lattice_.spacing, half = double(B - 1) / 2;
    return lattice_.origin + Vec3{h * (double(i * B) + half), h * (double(j * B) + half), h * (double(k * B) + half)};
  }
  // Of a block's nodes from its centre.
  double half_diagonal() const { return std::sqrt(3.0) * double(kContourBlock - 1) / 2 * lattice_.spacing; }
  double limit() const { return limit_; }

private:
  const ErodedUnion& eu_;
  const Lattice& lattice_;
  double limit_;
  std::list<std::pair<std::uint64_t, Nearby>> cache_;
  std::array<std::pair<std::size_t, std::optional<Nearby>>, (kContourBlock / kCubeGroup) * (kContourBlock / kCubeGroup) *
                                                                 (kContourBlock / kCubeGroup)>
      groups_;
};

// Calls f(first node, nodes) for each block of nodes.
template <class F>
void for_blocks(const Lattice& l, F f) {
  const std::size_t B = kContourBlock;
  std::vector<std::size_t> nodes;
  for (std::size_t bk = 0; bk < l.size[2]; bk += B)
    for (std::size_t bj = 0; bj < l.size[1]; bj += B)
      for (std::size_t bi = 0; bi < l.size[0]; bi += B) {
        nodes.clear();
        for (std::size_t k = bk; k < std::min(bk + B, l.size[2]); ++k)
          for (std::size_t j = bj; j < std::min(bj + B, l.size[1]); ++j)
            for (std::size_t i = bi; i < std::min(bi + B, l.size[0]); ++i) nodes.push_back(l.index(i, j, k));
        f(l.index(bi, bj, bk), nodes);
      }
}

// The point at t in [gap, 1 - gap] of the segment from a to b.
Vec3 along(const Vec3& a, const Vec3& b, double t) {
  t = std::clamp(t, kNodeGap, 1 - kNodeGap);
  return a + t * (b - a);
}

// Where the distance to F falls to r on the segment from inside node a
// (distance >= r) to outside node b, and the nearest point of F there:
// Newton's method on phi(t) = d(x(t), F) - r, whose derivative is the unit
// vector from the nearest point to x dotted with b - a, kept inside the
// bracket (bisection where a step leaves it or phi has no derivative:
// outside the union, or beyond the limit). A Newton step of s A lands
// within s^2 / 2r of the root where phi'' is at most 1 / r (the distance,
// r, to a sphere, circle or point): when that is within the precision the
// point is taken without evaluating there, with the nearest point found
// within s of it (within s of the root, 8e-3 A at 0.5 A, where the
// nearest piece changes within the step). 2.3 evaluations on average (1a26A at 0.5 A), where
// evaluating every point took 3.1 and regula falsi ten.
std::pair<Vec3, Nearest> crossing(const Nearby& near, const Vec3& a, const Vec3& b, double r, double limit) {
  const Vec3 d = b - a;
  const double length = norm(d);
  double ta = 0, tb = 1, t = 0.5;
  for (int iter = 0;; ++iter) {
    const Vec3 x = along(a, b, t);
    const Nearest n = near.nearest(x, limit);
    const double phi = n.distance - r;
    (phi >= 0 ? ta : tb) = t;
    double next = (ta + tb) / 2;
    bool newton_step = false;
    const bool smooth = n.on == Nearest::On::sphere || n.on == Nearest::On::circle || n.on == Nearest::On::vertex;
    if (smooth && n.distance > 0) {
      const double slope = dot(x - n.point, d) / n.distance;
      const double newton = slope < 0 ? t - phi / slope : ta;
      if (newton > ta && newton < tb) next = newton, newton_step = true;
    }
    if (std::fabs(phi) < kRootPrecision * length || tb - ta < kRootPrecision || iter == 60) return {x, n};
    const double step = (next - t) * length;
    if (newton_step && step * step < kRootPrecision * length * r) return {along(a, b, next), n};
    t = next;
  }
}

// Where a block of the lattice lies, told from the balls alone (no
// gathering of the pieces near it): every node outside the union, every
// node in the eroded body (in one ball, r deep), or not known.
enum class BlockIs { outside, in_body, unknown };

class BlockBalls {
public:
  BlockBalls(const ErodedUnion& eu, double half_diagonal) : half_(half_diagonal), r_(eu.r()) {
    const Triangulation& t = eu.balls().complex().triangulation();
    for (Index i = 0; i < t.num_points(); ++i) {
      centres_.push_back(t.point(i));
      radii_.push_back(std::sqrt(t.weight(i)));
    }
    nearest_.emplace(centres_, radii_, half_diagonal);
  }
  // Of the block whose nodes are within the half-diagonal of `center`.
  BlockIs where(const Vec3& center) const {
    // To the nearest sphere (< 0 inside), exact when at most half_: only
    // the balls that near are seen (the far blocks, most of the lattice,
    // need no search for their nearest ball).
    double d = HUGE_VAL;
    nearest_->visit_near(center, half_, [&](Index i) { d = std::min(d, norm(center - centres_[i]) - radii_[i]); });
    if (d > half_) return BlockIs::outside;
    if (-d >= r_ + half_) return BlockIs::in_body;
    return BlockIs::unknown;
  }

private:
  double half_, r_;
  std::vector<Vec3> centres_;
  std::vector<double> radii_;
  std::optional<NearestBall> nearest_;
};

// Lower and upper corners of the balls on the union's boundary.
std::pair<Vec3, Vec3> boundary_box(const ErodedUnion& eu) {
  const UnionOfBalls& balls = eu.balls();
  const Triangulation& t = balls.complex().triangulation();
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (Index i = 0; i < t.num_points(); ++i) {
    if (balls.ball_areas()[i] <= 0) continue;
    const double r = std::sqrt(t.weight(i));
    const Vec3 p = t.point(i);
    lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r), std::min(lo.z, p.z - r)};
    hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r), std::max(hi.z, p.z + r)};
  }
  return {lo, hi};
}

}  // namespace

ErodedUnionMesh eroded_union_mesh(const ErodedUnion& eu, double spacing) {
  const auto [lo, hi] = boundary_box(eu);
  if (!(lo.x <= hi.x)) return {};  // no boundary: no surface
  const Lattice lattice = lattice_over(lo, hi, spacing);
  const double r = eu.r();
  // Distances are exact up to two spacings beyond r: the root finder's
  // values are exact near the root.
  BlockHoods hoods(eu, lattice, r + 2 * spacing);
  const BlockBalls block_balls(eu, hoods.half_diagonal());
  std::vector<std::uint8_t> inside(lattice.num_nodes(), 0);
  static_assert(kContourBlock % 2 == 0);
  for_blocks(lattice, [&](std::size_t first, const std::vector<std::size_t>& nodes) {
    // A block deep inside the body or far outside the union is one label:
    // mostly told by the balls alone, else by the pieces near it.
    const Vec3 center = hoods.center(first);
    const BlockIs is = block_balls.where(center);
    if (is == BlockIs::outside) return;
    if (is == BlockIs::in_body) {
      for (std::size_t n : nodes) inside[n] = 1;
      return;
    }
    const Nearby& near = hoods.of(first);
    const double half = hoods.half_diagonal();
    const Nearest at = near.nearest(center, r + half);
    if (at.on == Nearest::On::far) {
      for (std::size_t n : nodes) inside[n] = 1;
      return;
    }
    if (at.on == Nearest::On::outside && near.outside_by(center) > half) return;
    // Else group by group of 2 x 2 x 2 nodes: the distance to F changes by
    // no more than the distance moved, so a group whose centre is further
    // than its half-diagonal from the level r is one label (one call where
    // its nodes took eight: a third of the calls on 1a26A at 0.5 A), the
    // others node by node.
    const double h = lattice.spacing, group_half = std::sqrt(3.0) * h / 2, margin = 1e-6 * h;
    const std::size_t i0 = first % lattice.size[0], j0 = first / lattice.size[0] % lattice.size[1];
    const std::size_t k0 = first / (lattice.size[0] * lattice.size[1]), B = kContourBlock;
    for (std::size_t gk = k0; gk < std::min(k0 + B, lattice.size[2]); gk += 2)
      for (std::size_t gj = j0; gj < std::min(j0 + B, lattice.size[1]); gj += 2)
        for (std::size_t gi = i0; gi < std::min(i0 + B, lattice.size[0]); gi += 2) {
          const Nearest g = near.nearest(lattice.node(lattice.index(gi, gj, gk)) + Vec3{h / 2, h / 2, h / 2},
                                         r + group_half + margin);
          const bool all_in = g.on == Nearest::On::far, all_out = !all_in && g.distance < r - group_half - margin;
          for (std::size_t k = gk; k < std::min(gk + 2, lattice.size[2]); ++k)
            for (std::size_t j = gj; j < std::min(gj + 2, lattice.size[1]); ++j)
              for (std::size_t i = gi; i < std::min(gi + 2, lattice.size[0]); ++i) {
                const std::size_t n = lattice.index(i, j, k);
                inside[n] = all_in || (!all_out && near.nearest(lattice.node(n), r).on == Nearest::On::far);
              }
        }
  });
  ErodedUnionMesh out;
  Index hint = kNone;
  out.mesh = contour(lattice, inside, [&](std::size_t a, std::size_t b, std::size_t cube) {
    const auto [p, n] = crossing(hoods.of_cube(cube), lattice.node(a), lattice.node(b), r, hoods.limit());
    const Index cell = eu.share_cell(p, n, hint);
    if (cell != kNone) hint = cell;
    out.share_cells.push_back(cell);
    return p;
  });
  return out;
}

SurfaceMesh cells_mesh(const ErodedUnion& eu, std::span<const Index> cells, double spacing) {
  const Triangulation& t = eu.balls().complex().triangulation();
  if (cells.empty()) return {};
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (Index c : cells) {
    if (c >= t.num_cells() || t.is_infinite(c))
      fail("mesh: cell " + std::to_string(c) + " is not a finite cell", ErrorKind::Misuse);
    for (Index v : t.cell(c).v) {
      const Vec3 p = t.point(v);
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  const double r = eu.r();
  const Lattice lattice = lattice_over(lo - Vec3{r, r, r}, hi + Vec3{r, r, r}, spacing);
  BlockHoods hoods(eu, lattice, r + 2 * spacing);
  const BlockBalls block_balls(eu, hoods.half_diagonal());
  Index hint = cells.front();
  // Whether x, whose nearest point of F is n, is held.
  const auto held_at = [&](const Vec3& x, const Nearest& n) {
    if (n.on == Nearest::On::far) return false;  // in the eroded body
    const Index c = eu.share_cell(x, n, hint);
    if (c == kNone) return false;
    if (!t.is_infinite(c)) hint = c;
    return std::binary_search(cells.begin(), cells.end(), c);
  };
  const auto held = [&](const Nearby& near, const Vec3& x) { return held_at(x, near.nearest(x, r)); };
  std::vector<std::uint8_t> inside(lattice.num_nodes(), 0);
  for_blocks(lattice, [&](std::size_t first, const std::vector<std::size_t>& nodes) {
    // Outside the union a node is held by the cell holding it; deep in the
    // body by none: told without gathering the pieces near the block.
    const BlockIs is = block_balls.where(hoods.center(first));
    if (is == BlockIs::in_body) return;
    if (is == BlockIs::outside) {
      for (std::size_t n : nodes) {
        const Vec3 x = lattice.node(n);
        inside[n] = held_at(x, {Nearest::On::outside, 0, x, kNone});
      }
      return;
    }
    const Nearby& near = hoods.of(first);
    if (near.nearest(hoods.center(first), r + hoods.half_diagonal()).on == Nearest::On::far) return;  // in the body
    for (std::size_t n : nodes) inside[n] = held(near, lattice.node(n));
  });
  // Where the cast's boundary leaves the segment from held a to b not held
  // (its parameter), by bisection on that membership.
  const auto leaves = [&](const Nearby& near, const Vec3& a, const Vec3& b) {
    double ta = 0, tb = 1;  // held at ta, not at tb
    while (tb - ta > kRootPrecision) {
      const double mid = (ta + tb) / 2;
      (held(near, along(a, b, mid)) ? ta : tb) = mid;
    }
    return (ta + tb) / 2;
  };
  // Per point: the molecular surface's normal there (zero elsewhere), where
  // it is and the ends of its lattice edge (inside, outside).
  std::vector<Vec3> normals, points;
  std::vector<std::pair<std::size_t, std::size_t>> ends;
  const auto vertex = [&](std::size_t a, std::size_t b, std::size_t cube) {
    const Nearby& near = hoods.of_cube(cube);
    const Vec3 pa = lattice.node(a), pb = lattice.node(b);
    ends.emplace_back(a, b);
    // Most crossings are on the molecular surface, b in the body: found by
    // Newton's method as the surface's vertices are, and kept when the
    // point just before it is held (else the cast ends earlier: at a
    // mouth, or where another cell's share begins).
    if (near.nearest(pb, r).on == Nearest::On::far) {
      const auto [p, n] = crossing(near, pb, pa, r, hoods.limit());
      const double t = dot(p - pa, pb - pa) / dot(pb - pa, pb - pa);
      if (held(near, along(pa, pb, t - kRootPrecision))) {
        normals.push_back((1 / norm(p - n.point)) * (p - n.point));  // away from F: into the body
        return points.emplace_back(p);
      }
    }
    normals.push_back({});
    return points.emplace_back(along(pa, pb, leaves(near, pa, pb)));
  };
  // Where the molecular surface meets a mouth (or another cell's share) the
  // cast has a crease, whose corner the lattice's segment between a vertex
  // on either side would cut (the volume lost goes as the crease's length
  // times the spacing squared). The crease's point on their lattice
  // triangle: where the surface's tangent there meets the other
  // boundary's line, through the vertex on it and a second point found an
  // eighth of the way beyond the triangle's edge; taken from the middle of
  // the segment toward it only as far as the triangle allows, strictly
  // inside (beyond it the lattice misses the cast anyway); none when the
  // two lines are near parallel or it is too close to the segment.
  const auto crease = [&](Index p, Index q) -> std::optional<Vec3> {
    const bool p_on = normals[p] != Vec3{}, q_on = normals[q] != Vec3{};
    if (p_on == q_on) return std::nullopt;
    if (q_on) std::swap(p, q);  // p on the molecular surface
    const auto [pa, pb] = ends[p];
    const auto [qa, qb] = ends[q];
    const Vec3 A = lattice.node(pa), B = lattice.node(pb), C = lattice.node(qa), D = lattice.node(qb);
    // Not next to a node (kCreaseGap).
    for (const auto& [v, a, b] : {std::tuple{points[p], A, B}, std::tuple{points[q], C, D}}) {
      const double t = dot(v - a, b - a) / dot(b - a, b - a);
      if (!(t > kCreaseGap && t < 1 - kCreaseGap)) return std::nullopt;
    }
    // The triangle: the shared node (inside or outside) and the two others.
    const Vec3 shared = pa == qa ? A : B, p_end = pa == qa ? B : A, q_end = pa == qa ? D : C;
    const Vec3 face = cross(p_end - shared, q_end - shared);
    const double face2 = dot(face, face);
    const auto weights = [&](const Vec3& x) {  // barycentric: of p_end, q_end, shared
      const double w_p = dot(cross(q_end - shared, x - shared), face) / -face2;
      const double w_q = dot(cross(p_end - shared, x - shared), face) / face2;
      return std::array<double, 3>{w_p, w_q, 1 - w_p - w_q};
    };
    const Nearby& near = hoods.of(pa);
    const Vec3 s0 = pa == qa ? C : C - kCreaseProbe * (A - C), s1 = pa == qa ? D - kCreaseProbe * (B - D) : D;
    if (!held(near, s0) || held(near, s1)) return std::nullopt;
    const double t = leaves(near, s0, s1);
    // On the molecular surface there too: the crease is that close to q.
    if (near.nearest(along(s0, s1, t + kRootPrecision), r).on == Nearest::On::far) return std::nullopt;
    const Vec3 tangent = cross(face, normals[p]), other = along(s0, s1, t) - points[q];
    const double sine = dot(cross(tangent, other), face);
    if (!(std::fabs(sine) > 1e-3 * norm(tangent) * norm(other) * norm(face))) return std::nullopt;
    const Vec3 target = points[p] + (dot(cross(points[q] - points[p], other), face) / sine) * tangent;
    const Vec3 middle = 0.5 * (points[p] + points[q]);
    const std::array<double, 3> from = weights(middle), to = weights(target);
    double reach = 1;
    for (int k = 0; k < 3; ++k)
      if (to[k] < from[k]) reach = std::min(reach, (from[k] - kCreaseGap) / (from[k] - to[k]));
    const Vec3 x = middle + std::max(reach, 0.0) * (target - middle);
    if (!(norm(x - middle) > kCreaseDepth * lattice.spacing)) return std::nullopt;
    normals.push_back({});
    ends.emplace_back(pa, qb);  // not a lattice edge's: never asked for
    return points.emplace_back(x);
  };
  SurfaceMesh mesh = contour(lattice, inside, vertex, crease);
  offset_chords(mesh, normals);
  return mesh;
}

}  // namespace alpha
