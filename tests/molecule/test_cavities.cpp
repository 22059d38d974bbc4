// SPDX-License-Identifier: Apache-2.0
// molecule::find_cavities on synthetic ball sets with known answers (a
// hollow shell, a shell with a hole, a ring, a grid of cubic voids) and on
// a real protein.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/discrete_flow.hpp"
#include "alpha/eroded_union.hpp"
#include "alpha/error.hpp"
#include "alpha/point_set_complex.hpp"
#include "alpha/sizes.hpp"
#include "alpha/union_of_balls.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/cavities.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/structure.hpp"
#include "point_sets.hpp"

using alpha::Index;
using alpha::Vec3;
using molecule::Cavities;
using molecule::Cavity;

namespace {

// The balls (points, van der Waals radii) and the complex of the balls
// inflated by the probe, kept together.
struct Balls {
  std::vector<Vec3> points;
  std::vector<double> radii;
  double probe;
  alpha::PointSetComplex shape;

  Balls(std::vector<Vec3> p, std::vector<double> r, double pr)
      : points(p), radii(r), probe(pr), shape(std::move(p), inflated(r, pr)) {}
  const alpha::Triangulation& triangulation() const { return shape.triangulation(); }
  const alpha::AlphaComplex& complex() const { return shape.complex(); }

  static std::vector<double> inflated(const std::vector<double>& r, double probe) {
    std::vector<double> w;
    for (double x : r) w.push_back(molecule::ball_weight(x, probe));
    return w;
  }
  // Every cavity, however small (min_volume 0: the voids are the b2 classes).
  Cavities cavities(double split_persistence = molecule::CavityOptions{}.split_persistence,
                    double split_volume = molecule::CavityOptions{}.split_volume, unsigned threads = 1) const {
    molecule::CavityOptions options;
    options.threads = threads;
    options.probe = probe;
    options.min_volume = 0;
    options.split_persistence = split_persistence;
    options.split_volume = split_volume;
    return molecule::find_cavities(complex(), radii, options);
  }
  // Whether x lies in no probe-inflated ball.
  bool free(const Vec3& x) const {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double dx = x.x - points[i].x, dy = x.y - points[i].y, dz = x.z - points[i].z;
      const double rr = radii[i] + probe;
      if (dx * dx + dy * dy + dz * dz < rr * rr) return false;
    }
    return true;
  }
};

// n points spread evenly on the sphere of radius R about the origin.
std::vector<Vec3> fibonacci_sphere(int n, double R) {
  std::vector<Vec3> pts;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (i + 0.5) * 2 / n, rho = std::sqrt(1 - z * z), phi = golden * i;
    pts.push_back({R * rho * std::cos(phi), R * rho * std::sin(phi), R * z});
  }
  return pts;
}

double tetra_volume(const alpha::Triangulation& t, Index c) {
  const auto& v = t.cell(c).v;
  return alpha::tetrahedron_volume(t.point(v[0]), t.point(v[1]), t.point(v[2]), t.point(v[3]));
}

// The cells connected to the outside at `level`: reached from the infinite
// cells through triangles absent there (entry >= level), by search.
std::vector<char> open_cells(const alpha::AlphaComplex& ac, Index level) {
  const alpha::Triangulation& t = ac.triangulation();
  const alpha::Simplices& s = ac.simplices();
  std::vector<char> reached(t.num_cells(), 0);
  std::vector<Index> stack;
  for (Index c = 0; c < t.num_cells(); ++c)
    if (t.is_infinite(c)) reached[c] = 1, stack.push_back(c);
  while (!stack.empty()) {
    const Index c = stack.back();
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const Index n = t.cell(c).n[k];
      if (reached[n]) continue;  // infinite cells too: only their finite facet leads in
      const Index f = s.cell_triangle(c, k);
      if (ac.triangle_interval(f).entry >= level) reached[n] = 1, stack.push_back(n);
    }
  }
  return reached;
}

// Distance from p to the triangle abc: to its plane when p projects
// inside it, else to the nearest of its sides.
double triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto segment = [&](const Vec3& u, const Vec3& v) {
    const double l = std::clamp(dot(p - u, v - u) / dot(v - u, v - u), 0.0, 1.0);
    return alpha::norm(p - (u + l * (v - u)));
  };
  const Vec3 n = alpha::cross(b - a, c - a);
  const Vec3 q = p - (dot(p - a, n) / dot(n, n)) * n;
  const bool inside = dot(alpha::cross(b - a, q - a), n) >= 0 && dot(alpha::cross(c - b, q - b), n) >= 0 &&
                      dot(alpha::cross(a - c, q - c), n) >= 0;
  return inside ? alpha::norm(p - q) : std::min({segment(a, b), segment(b, c), segment(c, a)});
}

// Properties every result must have, whatever the input.
void check_invariants(const Balls& b, const Cavities& cav) {
  const alpha::AlphaComplex& ac = b.complex();
  const alpha::Triangulation& t = b.triangulation();
  const alpha::Simplices& s = ac.simplices();
  const Index level = ac.level(0.0);
  CHECK(cav.voids.size() == ac.betti(level)[2]);
  // Per flow region, its empty triangles to the outside (a pocket's depth
  // is measured from those of its region).
  const alpha::DiscreteFlow flow(ac, level);
  std::vector<std::vector<Index>> region_mouths(flow.num_regions());
  for (Index c = 0; c < t.num_cells(); ++c)
    for (int k = 0; k < 4; ++k)
      if (flow.region(c) != alpha::kNone && flow.outside(t.cell(c).n[k]) &&
          ac.triangle_interval(s.cell_triangle(c, k)).entry >= level)
        region_mouths[flow.region(c)].push_back(s.cell_triangle(c, k));
  std::set<Index> seen;
  auto check_cavity = [&](const Cavity& c, bool pocket) {
    REQUIRE(!c.cells.empty());
    REQUIRE(std::is_sorted(c.cells.begin(), c.cells.end()));
    std::set<Index> vertices;
    double volume = 0;
    for (Index cell : c.cells) {
      REQUIRE(!t.is_infinite(cell));
      REQUIRE(ac.cell_entry(cell) >= level);  // empty
      REQUIRE(seen.insert(cell).second);      // in one cavity only
      for (Index v : t.cell(cell).v) vertices.insert(v);
      volume += tetra_volume(t, cell);
    }
    for (Index a : c.lining_atoms) CHECK(vertices.count(a) == 1);
    CHECK(c.sa_volume >= 0);
    CHECK(c.sa_volume <= volume * (1 + 1e-9));
    CHECK(c.sa_area >= 0);
    CHECK(c.ms_volume >= c.sa_volume);
    CHECK(c.ms_area >= 0);
    CHECK(c.max_alpha_sq > 0);
    CHECK(c.fill_alpha_sq == c.max_alpha_sq);
    // The probe at the orthocentre of the last cell to fill, against every atom.
    Index last = c.cells.front();
    for (Index cell : c.cells)
      if (ac.cell_entry(cell) > ac.cell_entry(last) || (ac.cell_entry(cell) == ac.cell_entry(last) && cell > last))
        last = cell;
    const auto& lv = t.cell(last).v;
    const Vec3 z = alpha::SizeKernel(t.points().data(), t.weights().data()).center(alpha::Simplex(lv[0], lv[1], lv[2], lv[3]));
    double clearance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < b.points.size(); ++i)
      clearance = std::min(clearance, std::sqrt(alpha::dot(z - b.points[i], z - b.points[i])) - b.radii[i]);
    CHECK(c.max_probe_radius == Approx(clearance).epsilon(1e-12));
    CHECK(c.max_probe_radius > b.probe);  // empty at alpha_sq = 0: the probe fits
    // Burial: the atoms near the centre, counted over all (the tests search
    // with the default burial radius).
    const double burial_sq = std::pow(molecule::CavityOptions{}.burial_radius, 2);
    CHECK(c.burial_atoms == std::size_t(std::count_if(b.points.begin(), b.points.end(), [&](const Vec3& x) {
            return alpha::dot(x - c.center, x - c.center) <= burial_sq;
          })));
    CHECK(c.close_alpha_sq <= c.fill_alpha_sq);
    // Cut off from the outside from close_alpha_sq on, not just below it.
    // The ranks whose value rounds to close_alpha_sq (level() compares
    // exactly, and a value may round down): [below, sealed).
    Index below = ac.level(c.close_alpha_sq), sealed = below;
    while (below > 0 && ac.spectrum_value(below - 1) == c.close_alpha_sq) --below;
    while (sealed < ac.spectrum_size() && ac.spectrum_value(sealed) == c.close_alpha_sq) ++sealed;
    REQUIRE(below < sealed);
    const std::vector<char> open_at = open_cells(ac, sealed), open_below = open_cells(ac, below);
    CHECK(std::none_of(c.cells.begin(), c.cells.end(), [&](Index x) { return open_at[x]; }));
    CHECK(std::any_of(c.cells.begin(), c.cells.end(), [&](Index x) { return open_below[x]; }));
    CHECK((pocket ? c.close_alpha_sq > 0 : c.close_alpha_sq <= 0));
    CHECK(c.mouths.empty() == !pocket);
    double mouth_area = 0;
    const std::set<Index> cells(c.cells.begin(), c.cells.end());
    for (const auto& m : c.mouths) {
      REQUIRE(!m.triangles.empty());
      CHECK(m.area >= 0);
      mouth_area += m.area;
      for (Index f : m.triangles) {
        REQUIRE(ac.triangle_interval(f).entry >= level);  // an empty facet
        const auto& tc = s.triangle_cells(f);
        CHECK(cells.count(tc[0]) + cells.count(tc[1]) == 1);  // between the pocket and the outside
      }
    }
    CHECK(c.mouth_area == Approx(mouth_area));
    // Mouths are maximal: no two of one kind share an edge.
    for (std::size_t m = 0; m < c.mouths.size(); ++m)
      for (std::size_t n = m + 1; n < c.mouths.size(); ++n) {
        if (c.mouths[m].to_outside != c.mouths[n].to_outside) continue;
        std::set<Index> edges;
        for (Index f : c.mouths[m].triangles)
          for (Index e : s.triangle_edges(f)) edges.insert(e);
        for (Index f : c.mouths[n].triangles)
          for (Index e : s.triangle_edges(f)) CHECK(edges.count(e) == 0);
      }
    CHECK(c.buriedness >= 0);
    CHECK(c.buriedness <= 1);
    if (!pocket) CHECK(c.depth == 0);
    // Depth: the farthest cell centroid's distance to its nearest mouth
    // triangle of the region, by scan.
    double depth = 0;
    for (Index cell : c.cells) {
      const auto& v = t.cell(cell).v;
      const Vec3 x = 0.25 * (t.point(v[0]) + t.point(v[1]) + t.point(v[2]) + t.point(v[3]));
      double nearest = pocket ? std::numeric_limits<double>::infinity() : 0;
      for (Index f : region_mouths[flow.region(cell)]) {
        const auto& fv = s.triangle(f);
        nearest = std::min(nearest, triangle_distance(x, t.point(fv[0]), t.point(fv[1]), t.point(fv[2])));
      }
      depth = std::max(depth, nearest);
    }
    CHECK(c.depth == Approx(depth).epsilon(1e-12).margin(1e-12));
  };
  for (const Cavity& c : cav.pockets) check_cavity(c, true);
  for (const Cavity& c : cav.voids) check_cavity(c, false);
  for (const auto* list : {&cav.pockets, &cav.voids})
    for (std::size_t k = 1; k < list->size(); ++k) CHECK((*list)[k - 1].score >= (*list)[k].score);
  // Sites: each pocket once and each void that holds a ligand (a
  // drug-sized one by free space, or about six heavy atoms by MS volume),
  // best first; among equal scores pockets first, each kind in its list's
  // order.
  std::vector<std::pair<bool, std::size_t>> expected, sites;
  for (std::size_t k = 0; k < cav.pockets.size(); ++k) expected.emplace_back(false, k);
  for (std::size_t k = 0; k < cav.voids.size(); ++k)
    if (cav.voids[k].sa_volume >= molecule::kLigandSiteVolume || cav.voids[k].ms_volume >= molecule::kLigandVoidVolume)
      expected.emplace_back(true, k);
  for (const molecule::Site& site : cav.sites) sites.emplace_back(site.is_void, site.index);
  std::sort(sites.begin(), sites.end());
  CHECK(sites == expected);
  for (std::size_t k = 1; k < cav.sites.size(); ++k) {
    const molecule::Site &a = cav.sites[k - 1], &b = cav.sites[k];
    CHECK(cav.cavity(a).score >= cav.cavity(b).score);
    if (cav.cavity(a).score == cav.cavity(b).score)
      CHECK(std::tie(a.is_void, a.index) < std::tie(b.is_void, b.index));
  }
  for (std::size_t k = 0; k < cav.tunnels.size(); ++k) {
    const auto& tn = cav.tunnels[k];
    CHECK(tn.birth_alpha_sq <= 0);
    CHECK(tn.death_alpha_sq > 0);
    CHECK(tn.bottleneck_radius >= b.probe);  // alive at alpha_sq = 0: the probe passes
    REQUIRE(tn.bottleneck_triangle < s.num_triangles());
    const auto triangle = s.triangle(tn.bottleneck_triangle);
    std::vector<Index> tri(triangle.begin(), triangle.end());
    std::sort(tri.begin(), tri.end());
    CHECK(tn.lining_atoms == tri);
    // The killing triangle is critical (not attached), and the bottleneck's
    // probe centre, its orthocentre, has power death_alpha_sq to each of
    // the three balls (grown, they meet there).
    CHECK(!b.complex().triangle_interval(tn.bottleneck_triangle).attached);
    for (Index a : tri) {
      const Vec3 d = tn.bottleneck_center - b.points[a];
      const double w = molecule::ball_weight(b.radii[a], b.probe);
      CHECK(dot(d, d) - w == Approx(tn.death_alpha_sq).margin(1e-9 * (w + dot(d, d))));
    }
    if (k > 0) CHECK(cav.tunnels[k - 1].death_alpha_sq >= tn.death_alpha_sq);
  }
}

// Bit for bit: every field of the two cavities (a NaN equal to itself).
bool same(const Cavity& a, const Cavity& b) {
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  const auto numbers = [&](const Cavity& c) {
    return std::array{bits(c.sa_volume),    bits(c.sa_area),      bits(c.ms_volume),        bits(c.ms_area),
                      bits(c.depth),        bits(c.center.x),     bits(c.center.y),         bits(c.center.z),
                      bits(c.max_alpha_sq), bits(c.max_probe_radius), bits(c.close_alpha_sq), bits(c.fill_alpha_sq),
                      bits(c.mouth_area),   bits(c.buriedness),   bits(c.score),            bits(c.ligandability),
                      bits(c.probability),  bits(c.rank_score)};
  };
  const auto mouths = [&](const Cavity& c) {
    std::vector<std::tuple<std::vector<Index>, std::uint64_t, bool>> m;
    for (const molecule::Mouth& x : c.mouths) m.emplace_back(x.triangles, bits(x.area), x.to_outside);
    return m;
  };
  return a.cells == b.cells && a.lining_atoms == b.lining_atoms && a.sinks == b.sinks &&
         a.burial_atoms == b.burial_atoms && mouths(a) == mouths(b) && numbers(a) == numbers(b);
}

}  // namespace

TEST_CASE("Cavities: the widest probe far from every atom, and with zero radii and probe", "[cavities]") {
  // A shell of radius 40 A: the void's widest probe (38 A) lies beyond
  // the first few cubes the clearance searches (radii 2 A: closed).
  const Balls shell(fibonacci_sphere(3000, 40), std::vector<double>(3000, 2.0), 0.3);
  const Cavities cav = shell.cavities();
  check_invariants(shell, cav);  // clearance against every atom
  REQUIRE(cav.voids.size() == 1);
  CHECK(cav.voids.front().max_probe_radius == Approx(40 - 2.0).epsilon(1e-9));
  // Points (radius 0) and no probe: the search must still grow.
  const auto pts = testing::random_points(300, 41, 100.0);
  const Balls bare(pts, std::vector<double>(pts.size(), 0.0), 0.0);
  check_invariants(bare, bare.cavities());
}

TEST_CASE("Cavities: a hollow shell of balls holds exactly one void", "[cavities]") {
  const double R = 8, r = 1.2, probe = 0.3, rho = r + probe;
  const Balls b(fibonacci_sphere(400, R), std::vector<double>(400, r), probe);
  const Cavities cav = b.cavities();
  check_invariants(b, cav);
  REQUIRE(cav.voids.size() == 1);
  CHECK(cav.pockets.empty());
  const Cavity& v = cav.voids.front();
  // Large enough for a drug-sized ligand: a binding site.
  REQUIRE(cav.sites.size() == 1);
  CHECK(cav.sites.front().is_void);
  // The inner cells share (up to rounding) the sphere centred at the
  // origin, orthogonal to every inflated ball: size R^2 - rho^2.
  CHECK(v.fill_alpha_sq == Approx(R * R - rho * rho).epsilon(1e-9));
  CHECK(v.max_probe_radius == Approx(R - r).epsilon(1e-9));  // a probe at the origin touches every atom
  CHECK(std::hypot(v.center.x, v.center.y, v.center.z) < 0.05 * R);
  // Its free volume against a midpoint-rule integration of the ball of
  // radius R minus the inflated balls.
  const double h = 0.1;
  double free_volume = 0;
  for (double x = -R + h / 2; x < R; x += h)
    for (double y = -R + h / 2; y < R; y += h)
      for (double z = -R + h / 2; z < R; z += h) {
        const double d2 = x * x + y * y + z * z;
        if (d2 >= R * R) continue;
        if (d2 < (R - rho) * (R - rho) || b.free({x, y, z})) free_volume += h * h * h;
      }
  CHECK(v.sa_volume == Approx(free_volume).epsilon(0.02));
  CHECK(v.sa_area > 0);
  // Its molecular-surface volume adds the probe layer under its wall: the
  // layer of the whole shell less that of the shell filled by a ball that
  // stays inside (the outer layer is the same).
  const auto layer = [&](bool filled) {
    std::vector<Vec3> p = b.points;
    std::vector<double> w = Balls::inflated(b.radii, probe);
    if (filled) p.push_back({0, 0, 0}), w.push_back(R * R);
    const alpha::Triangulation t(p, w);
    const alpha::AlphaComplex ac(t);
    const alpha::UnionOfBalls u(ac);
    return alpha::ErodedUnion(u, probe).layer();
  };
  const alpha::LayerShare hollow = layer(false), filled = layer(true);
  CHECK(v.ms_volume - v.sa_volume == Approx(hollow.volume - filled.volume).epsilon(1e-6));
  CHECK(v.ms_area == Approx(hollow.area - filled.area).epsilon(1e-6));
}

TEST_CASE("Cavities: a shell with a hole is one pocket with one mouth", "[cavities]") {
  const double R = 8, r = 1.2, probe = 0.3;
  std::vector<Vec3> pts;
  for (const Vec3& p : fibonacci_sphere(400, R))
    if (p.z < 0.8 * R) pts.push_back(p);  // a hole of radius 0.6 R = 4.8 about the north pole
  const Balls b(pts, std::vector<double>(pts.size(), r), probe);
  const Cavities cav = b.cavities();
  check_invariants(b, cav);
  CHECK(cav.voids.empty());
  REQUIRE(cav.pockets.size() == 1);
  const Cavity& p = cav.pockets.front();
  REQUIRE(p.mouths.size() == 1);
  const double hole = 0.6 * R;
  CHECK(p.mouth_area > 0);
  CHECK(p.mouth_area < M_PI * hole * hole);
  CHECK(p.buriedness > 0.5);  // mostly wall
  // The deepest cells lie near the south pole, about 1.8 R below the mouth.
  CHECK(p.depth > 1.4 * R);
  CHECK(p.depth < 1.8 * R);
  // Through the hole the pocket never closes before it fills.
  CHECK(p.close_alpha_sq > 0);
}

TEST_CASE("Cavities: a ring of balls is a tunnel with its analytic bottleneck", "[cavities]") {
  // The 12 integer points of the circle x^2 + y^2 = 25 (cocircular
  // exactly), and two far poles so that the input is not coplanar.
  std::vector<Vec3> pts;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      if (x * x + y * y == 25) pts.push_back({double(x), double(y), 0});
  REQUIRE(pts.size() == 12);
  pts.push_back({0, 0, 10});
  pts.push_back({0, 0, -10});
  const double r = 1.5, probe = 0.25, rho = r + probe;  // neighbours (at most sqrt(10) apart) overlap
  const Balls b(pts, std::vector<double>(pts.size(), r), probe);
  const Cavities cav = b.cavities();
  check_invariants(b, cav);
  REQUIRE(cav.tunnels.size() == 1);
  const auto& tn = cav.tunnels.front();
  // The hole's disc fills when the plane's triangles (circumradius 5) enter,
  // and the largest probe through the ring's centre touches all 12 atoms.
  CHECK(tn.death_alpha_sq == Approx(25 - rho * rho).epsilon(1e-12));
  CHECK(tn.bottleneck_radius == Approx(5 - r).epsilon(1e-12));
  CHECK(norm(tn.bottleneck_center) < 1e-12);  // the ring's centre
  for (Index a : tn.lining_atoms) CHECK(a < 12);
  CHECK(cav.voids.empty());
  // Without tunnels (as track asks): none, and the pockets as before.
  molecule::CavityOptions options;
  options.probe = probe;
  options.min_volume = 0;
  options.tunnels = false;
  const Cavities without = molecule::find_cavities(b.complex(), b.radii, options);
  CHECK(without.tunnels.empty());
  REQUIRE(without.pockets.size() == cav.pockets.size());
  for (std::size_t k = 0; k < cav.pockets.size(); ++k) CHECK(without.pockets[k].cells == cav.pockets[k].cells);
}

TEST_CASE("Cavities: a grid of balls has one void per cube, with analytic spectrum values", "[cavities]") {
  // Radius 0.5 + probe 0.25: neighbours and face diagonals overlap (faces
  // closed: circumradius^2 of a face half is 1/2 < 0.5625), cube centres
  // stay free (circumradius^2 3/4). Exact binary values: no rounding.
  const std::vector<Vec3> pts = testing::grid_points(5);
  const Balls b(pts, std::vector<double>(pts.size(), 0.5), 0.25);
  const Cavities cav = b.cavities();
  check_invariants(b, cav);
  REQUIRE(cav.voids.size() == 64);
  CHECK(cav.pockets.empty());
  CHECK(cav.sites.empty());  // each void far too small for a ligand
  // The void's free volume, by a midpoint rule over the unit cube (only
  // its 8 corner balls reach it).
  const double h = 0.005;
  double free_volume = 0;
  for (double x = h / 2; x < 1; x += h)
    for (double y = h / 2; y < 1; y += h)
      for (double z = h / 2; z < 1; z += h) {
        bool covered = false;
        for (int c = 0; c < 8 && !covered; ++c) {
          const double dx = x - (c & 1), dy = y - ((c >> 1) & 1), dz = z - ((c >> 2) & 1);
          covered = dx * dx + dy * dy + dz * dz < 0.5625;
        }
        if (!covered) free_volume += h * h * h;
      }
  for (const Cavity& v : cav.voids) {
    CHECK(v.fill_alpha_sq == 0.75 - 0.5625);
    CHECK(v.close_alpha_sq == 0.5 - 0.5625);
    CHECK(v.max_probe_radius == Approx(std::sqrt(0.75) - 0.5).epsilon(1e-12));  // to a cube's corners
    CHECK(v.sa_volume == Approx(free_volume).epsilon(0.01));
    CHECK(v.lining_atoms.size() == 8);
    // The centre of a cube.
    CHECK(v.center.x - std::floor(v.center.x) == Approx(0.5));
    CHECK(v.center.y - std::floor(v.center.y) == Approx(0.5));
    CHECK(v.center.z - std::floor(v.center.z) == Approx(0.5));
  }
  // The same, bit for bit, measured on 3 threads.
  const molecule::CavityOptions defaults;
  const Cavities cav2 = b.cavities(defaults.split_persistence, defaults.split_volume, 3);
  REQUIRE(cav2.voids.size() == cav.voids.size());
  for (std::size_t k = 0; k < cav.voids.size(); ++k) CHECK(same(cav.voids[k], cav2.voids[k]));
}

TEST_CASE("Cavities: degenerate and small inputs", "[cavities]") {
  // A grid whose balls do not touch: every orthocenter is a cube centre,
  // on a facet or inside the cell, so nothing flows out through the hull:
  // all the space is one open region (split into pockets), nothing closed.
  const std::vector<Vec3> pts = testing::grid_points(4);
  const Balls sparse(pts, std::vector<double>(pts.size(), 0.2), 0.1);
  const Cavities open = sparse.cavities();
  check_invariants(sparse, open);
  CHECK(open.voids.empty());
  std::size_t cells = 0;
  for (const Cavity& p : open.pockets) cells += p.cells.size();
  CHECK(cells == sparse.triangulation().num_finite_cells());
  // Balls of radius 0.6 with a zero probe: faces open, centres free; every
  // grid level in between keeps the invariants.
  for (double r : {0.45, 0.55, 0.65, 0.75, 0.85, 0.95}) {
    const Balls g(pts, std::vector<double>(pts.size(), r), 0.0);
    check_invariants(g, g.cavities());
  }
  // Random weighted balls, a hundred or so atoms.
  const std::vector<Vec3> rnd = testing::random_points(150, 3, 12.0);
  const std::vector<double> radii = testing::random_weights(150, 4, 1.0, 2.0);
  const Balls r(rnd, radii, 1.4);
  check_invariants(r, r.cavities());
}

TEST_CASE("Cavities: inconsistent input is refused", "[cavities]") {
  const std::vector<Vec3> pts = testing::grid_points(3);
  const Balls b(pts, std::vector<double>(pts.size(), 0.5), 0.25);
  molecule::CavityOptions options;
  options.probe = 0.25;
  CHECK_THROWS_AS(molecule::find_cavities(b.complex(), std::vector<double>(3, 0.5), options), alpha::Error);
  options.probe = 1.4;  // not the probe the complex was built with
  CHECK_THROWS_AS(molecule::find_cavities(b.complex(), b.radii, options), alpha::Error);
  options.probe = -1;
  CHECK_THROWS_AS(molecule::find_cavities(b.complex(), b.radii, options), alpha::Error);
  options.probe = 0.25;
  options.split_volume = std::nan("");
  CHECK_THROWS_AS(molecule::find_cavities(b.complex(), b.radii, options), alpha::Error);
}

TEST_CASE("Cavities: an enclosed ligand site is a void and a site (3stdA)", "[cavities]") {
  // Scytalone dehydratase closes over its inhibitor MQ0: without it, the
  // site is a void of some 165 A^3 of free space, the best site of all.
  const molecule::Structure st = molecule::read_structure(ALPHAPOCKET_TEST_DATA "/3stdA.pdb");
  const auto ligand = std::find_if(st.hetero_groups.begin(), st.hetero_groups.end(),
                                   [](const molecule::HeteroGroup& g) { return g.residue_name == "MQ0"; });
  REQUIRE(ligand != st.hetero_groups.end());
  const molecule::PocketSearch search = molecule::search_pockets(st, molecule::CavityOptions{});
  const Cavities& cav = search.cavities;
  REQUIRE(!cav.sites.empty());
  REQUIRE(cav.sites.front().is_void);
  const Cavity& site = cav.cavity(cav.sites.front());
  CHECK(site.sa_volume >= molecule::kLigandSiteVolume);
  double nearest = std::numeric_limits<double>::infinity();
  for (const molecule::Atom& a : ligand->atoms) nearest = std::min(nearest, alpha::norm(a.position - site.center));
  CHECK(nearest < 4);  // a hit by the DCA criterion
  // No pocket comes within 4 A of the ligand: as pockets only, it is missed.
  for (const Cavity& p : cav.pockets)
    for (const molecule::Atom& a : ligand->atoms) CHECK(alpha::norm(a.position - p.center) > 4);
}

TEST_CASE("Cavities: a real protein (1a26A)", "[cavities]") {
  const molecule::Structure st = molecule::read_structure(ALPHAPOCKET_EXAMPLES_DATA "/1a26A.pdb");
  std::vector<Vec3> pts;
  std::vector<double> radii;
  for (const auto& a : st.atoms) pts.push_back(a.position), radii.push_back(a.radius);
  const Balls b(pts, radii, 1.4);
  const Cavities cav = b.cavities();
  check_invariants(b, cav);
  REQUIRE(!cav.pockets.empty());
  for (const Cavity& p : cav.pockets) {
    CHECK(p.sa_volume > 0);
    CHECK(p.depth > 0);
    CHECK(!p.lining_atoms.empty());
  }
  // The best pocket is a real one: large and well buried.
  CHECK(cav.pockets.front().sa_volume > 100);
  for (const Cavity& p : cav.pockets) CHECK(p.score == molecule::cavity_score(p));

  // Infinite split_persistence and split_volume give CASTp's pockets: one
  // per region of the flow with a mouth; the split pockets partition the
  // same cells.
  const double inf = std::numeric_limits<double>::infinity();
  const Cavities castp = b.cavities(inf, inf);
  check_invariants(b, castp);
  // The size rule splits what persistence alone leaves whole: without it
  // fewer pockets, and a larger largest one.
  const Cavities by_persistence = b.cavities(molecule::CavityOptions{}.split_persistence, inf);
  check_invariants(b, by_persistence);
  const auto largest = [](const Cavities& c) {
    double v = 0;
    for (const Cavity& p : c.pockets) v = std::max(v, p.sa_volume);
    return v;
  };
  CHECK(by_persistence.pockets.size() < cav.pockets.size());
  CHECK(largest(by_persistence) > largest(cav));
  const Index level = b.complex().level(0.0);
  const alpha::DiscreteFlow flow(b.complex(), level);
  std::set<Index> with_mouth;
  const alpha::Triangulation& t = b.triangulation();
  for (Index c = 0; c < t.num_cells(); ++c)
    for (int k = 0; k < 4; ++k)
      if (flow.region(c) != alpha::kNone && flow.outside(t.cell(c).n[k]) &&
          b.complex().triangle_interval(b.complex().simplices().cell_triangle(c, k)).entry >= level)
        with_mouth.insert(flow.region(c));
  CHECK(castp.pockets.size() == with_mouth.size());
  // Depth by brute force: a whole region's outside mouths are its pocket's,
  // so depth is the largest distance from a cell centroid to the nearest of
  // their triangles (a point-triangle distance of its own here).
  const auto segment_distance = [](const Vec3& p, const Vec3& a, const Vec3& b) {
    const double u = std::clamp(dot(b - a, p - a) / dot(b - a, b - a), 0.0, 1.0);
    return norm(p - a - u * (b - a));
  };
  const auto triangle_distance = [&](const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (1 / norm(cross(b - a, c - a))) * cross(b - a, c - a);
    const double h = dot(p - a, n);
    const Vec3 q = p - h * n;  // projection on the plane
    const auto left = [&](const Vec3& u, const Vec3& v) { return dot(cross(v - u, q - u), n) >= 0; };
    if (left(a, b) && left(b, c) && left(c, a)) return std::fabs(h);
    return std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
  };
  for (const Cavity& p : castp.pockets) {
    double depth = 0;
    for (Index c : p.cells) {
      const auto& v = t.cell(c).v;
      const Vec3 g = 0.25 * (t.point(v[0]) + t.point(v[1]) + t.point(v[2]) + t.point(v[3]));
      double nearest = std::numeric_limits<double>::infinity();
      for (const molecule::Mouth& m : p.mouths)
        for (Index f : m.triangles) {
          const auto& fv = b.complex().simplices().triangle(f);
          nearest = std::min(nearest, triangle_distance(g, t.point(fv[0]), t.point(fv[1]), t.point(fv[2])));
        }
      depth = std::max(depth, nearest);
    }
    CHECK(p.depth == Approx(depth).epsilon(1e-9));
  }
  // Each cavity's sinks are exactly its cells where the flow ends; the
  // molecule totals are the union of the inflated balls.
  for (const auto* list : {&cav.pockets, &cav.voids})
    for (const Cavity& c : *list) {
      std::vector<Index> sinks;
      for (Index cell : c.cells)
        if (flow.is_sink(cell)) sinks.push_back(cell);
      CHECK(c.sinks == sinks);
      CHECK(!c.sinks.empty());
    }
  const alpha::UnionOfBalls sa_model(b.complex());
  CHECK(cav.sa_area == sa_model.area());
  CHECK(cav.sa_volume == sa_model.volume());
  auto all_cells = [](const std::vector<Cavity>& list) {
    std::vector<Index> cells;
    for (const Cavity& c : list) cells.insert(cells.end(), c.cells.begin(), c.cells.end());
    std::sort(cells.begin(), cells.end());
    return cells;
  };
  CHECK(all_cells(castp.pockets) == all_cells(cav.pockets));
  CHECK(cav.pockets.size() > castp.pockets.size());
  CHECK(castp.voids.size() == cav.voids.size());
  // The same, bit for bit, measured on 3 threads.
  const molecule::CavityOptions defaults;
  const Cavities cav2 = b.cavities(defaults.split_persistence, defaults.split_volume, 3);
  REQUIRE(cav2.pockets.size() == cav.pockets.size());
  for (std::size_t k = 0; k < cav.pockets.size(); ++k) CHECK(same(cav.pockets[k], cav2.pockets[k]));
}

TEST_CASE("Cavities: openings of one kind around an edge form one mouth", "[cavities]") {
  // Random balls where a split pocket has two outside openings and two
  // openings into a neighbouring part around one edge: grouped by edge
  // alone, the outside ones came apart (3 mouths instead of 2).
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> pts;
  std::vector<double> radii;
  for (int i = 0; i < 77; ++i) {
    const double x = 10 * u(rng), y = 10 * u(rng), z = 10 * u(rng);
    pts.push_back({x, y, z});
    radii.push_back(0.5 + u(rng));
  }
  const Balls b(pts, radii, 0.3);
  const Cavities cav = b.cavities(0, std::numeric_limits<double>::infinity());
  check_invariants(b, cav);
  std::size_t inner = 0;
  for (const Cavity& c : cav.pockets)
    for (const auto& m : c.mouths) inner += !m.to_outside;
  CHECK(inner > 0);  // split pockets: the case arises
}
