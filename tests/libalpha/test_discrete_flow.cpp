// SPDX-License-Identifier: Apache-2.0
// alpha::DiscreteFlow: the flow relation against its geometric definition
// (orthocenter beyond the facet, in floating point where that is clear),
// its order properties (monotone, acyclic, one direction per facet), the
// outside set against a forward search, and regions without mouths against
// b2.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/discrete_flow.hpp"
#include "point_sets.hpp"
#include "threaded_complexes.hpp"

using namespace alpha;

namespace {

// Signed distance-like value of p from the plane of facet k of cell c,
// positive on the side of the opposite vertex (floating point).
double facet_side(const Triangulation& t, Index c, int k, const Vec3& p) {
  const auto& v = t.cell(c).v;
  const auto& f = kFacet[k];
  const Vec3 &a = t.point(v[f[0]]), &b = t.point(v[f[1]]), &d = t.point(v[f[2]]);
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  const double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
  const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
  return (nx * (p.x - a.x) + ny * (p.y - a.y) + nz * (p.z - a.z)) / len;
}

// Every property the flow must have at one level.
void check_flow(const AlphaComplex& ac, Index level, bool check_geometry) {
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  const DiscreteFlow flow(ac, level);
  SizeKernel sizes(t.points().data(), t.weighted() ? t.weights().data() : nullptr);
  const Index nc = Index(t.num_cells());
  std::size_t sinks = 0;
  for (Index c = 0; c < nc; ++c) {
    const bool infinite = t.is_infinite(c);
    REQUIRE(flow.empty(c) == (infinite || ac.cell_entry(c) >= level));
    if (infinite) {
      REQUIRE(flow.outside(c));
      REQUIRE(flow.flow_facets(c) == 0);
      continue;
    }
    if (!flow.empty(c)) {
      REQUIRE(flow.flow_facets(c) == 0);
      REQUIRE(!flow.outside(c));
      REQUIRE(flow.region(c) == kNone);
      continue;
    }
    sinks += flow.is_sink(c);
    const auto& v = t.cell(c).v;
    const Vec3 z = sizes.center(Simplex(v[0], v[1], v[2], v[3]));
    for (int k = 0; k < 4; ++k) {
      const Index f = s.cell_triangle(c, k);
      const Index n = t.cell(c).n[k];
      const bool flows = flow.flow_facets(c) & (1u << k);
      if (!flows) continue;
      // Only through empty facets, and never back.
      REQUIRE(ac.triangle_interval(f).entry >= level);
      REQUIRE(flow.empty(n));
      if (!t.is_infinite(n)) REQUIRE(!(flow.flow_facets(n) & (1u << t.mirror_index(c, k))));
      // Uphill: the neighbour's orthosphere is not smaller.
      if (!t.is_infinite(n)) REQUIRE(ac.cell_entry(n) >= ac.cell_entry(c));
      // An outside cell's flow stays outside... and a region cell's flow stays in its region.
      if (flow.region(c) != kNone) REQUIRE(flow.region(n) == flow.region(c));
    }
    if (check_geometry)
      for (int k = 0; k < 4; ++k) {
        const double side = facet_side(t, c, k, z);
        const bool empty_facet = ac.triangle_interval(s.cell_triangle(c, k)).entry >= level;
        const bool flows = flow.flow_facets(c) & (1u << k);
        if (side < -1e-9) CHECK(flows == empty_facet);  // orthocenter clearly beyond
        if (side > 1e-9) CHECK(!flows);
      }
  }

  // Forward search from every empty cell: outside exactly when an infinite
  // cell is reachable; otherwise every path ends in a finite sink. A
  // three-colour DFS also proves the flow graph acyclic.
  std::vector<char> colour(nc, 0), reaches(nc, 0);
  std::vector<std::pair<Index, int>> stack;
  for (Index root = 0; root < nc; ++root) {
    if (!flow.empty(root) || colour[root]) continue;
    stack.push_back({root, 0});
    colour[root] = 1;
    while (!stack.empty()) {
      auto& [c, k] = stack.back();
      if (t.is_infinite(c)) reaches[c] = 1;
      if (k == 4) {
        colour[c] = 2;
        const Index done = c;
        stack.pop_back();
        if (!stack.empty()) reaches[stack.back().first] |= reaches[done];
        continue;
      }
      const int kk = k++;
      if (!(flow.flow_facets(c) & (1u << kk))) continue;
      const Index n = t.cell(c).n[kk];
      REQUIRE(colour[n] != 1);  // a back edge would be a cycle
      if (colour[n] == 2) {
        reaches[c] |= reaches[n];
        continue;
      }
      colour[n] = 1;
      stack.push_back({n, 0});
    }
  }
  std::size_t regions_without_mouth = 0;
  std::vector<char> has_mouth(flow.num_regions(), 0);
  for (Index c = 0; c < nc; ++c) {
    if (!flow.empty(c)) continue;
    REQUIRE(flow.outside(c) == bool(reaches[c]));
    REQUIRE((flow.region(c) != kNone) == (!flow.outside(c)));
    if (flow.region(c) == kNone) continue;
    REQUIRE(flow.region(c) < flow.num_regions());
    for (int k = 0; k < 4; ++k) {
      const Index n = t.cell(c).n[k];
      const bool empty_facet = ac.triangle_interval(s.cell_triangle(c, k)).entry >= level;
      if (!empty_facet) continue;
      if (flow.outside(n)) has_mouth[flow.region(c)] = 1;
      else REQUIRE(flow.region(n) == flow.region(c));  // regions are closed under empty facets
    }
  }
  for (char m : has_mouth) regions_without_mouth += !m;
  CHECK(regions_without_mouth == ac.betti(level)[2]);
  if (flow.num_regions() > 0) CHECK(sinks > 0);
}

}  // namespace

TEST_CASE("Discrete flow: random weighted points at many levels", "[flow]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Triangulation t(testing::random_points(300, seed, 10.0), testing::random_weights(300, seed + 7, 0.5, 2.0));
    const AlphaComplex ac(t);
    for (double alpha_sq : {-0.5, 0.0, 0.5, 1.5, 4.0})
      check_flow(ac, ac.level(alpha_sq), true);
    check_flow(ac, 0, true);                             // nothing in the complex
    check_flow(ac, Index(ac.spectrum_size()), false);    // everything
  }
}

TEST_CASE("Discrete flow: unweighted points", "[flow]") {
  const Triangulation t(testing::random_points(400, 11, 1.0));
  const AlphaComplex ac(t);
  for (double alpha_sq : {0.0, 0.001, 0.003, 0.01}) check_flow(ac, ac.level(alpha_sq), true);
}

TEST_CASE("Discrete flow: degenerate grid and cospherical points", "[flow]") {
  // Cospherical cube corners put orthocenters exactly on facets: those
  // facets are not crossed, and the flow stays acyclic.
  const Triangulation grid(testing::grid_points(5));
  const AlphaComplex g(grid);
  for (Index level = 0; level <= g.spectrum_size(); ++level) check_flow(g, level, false);
  // A grid of balls whose neighbours overlap but leave each cube's centre
  // free: every inner cube is a void, filled by its cells' common sphere.
  const std::vector<Vec3> pts = testing::grid_points(4);
  const Triangulation balls(pts, std::vector<double>(pts.size(), 0.5625));  // radius 0.75
  const AlphaComplex b(balls);
  const Index level = b.level(0.0);
  check_flow(b, level, false);
  CHECK(b.betti(level)[2] == 27);
  const DiscreteFlow flow(b, level);
  CHECK(flow.num_regions() == 27);

  const Triangulation sphere(testing::sphere_points(50));
  const AlphaComplex sp(sphere);
  for (Index level = 0; level <= sp.spectrum_size(); ++level) check_flow(sp, level, false);
}

TEST_CASE("Discrete flow: the same for a complex built on 2 or 3 threads", "[flow]") {
  const testing::ThreadedComplexes c(5);
  REQUIRE(c.t2.num_vertices() >= AlphaComplex::kThreadsFrom);
  REQUIRE(c.t2.num_cells() == c.t3.num_cells());
  const DiscreteFlow f2(c.a2, c.a2.level(0.0)), f3(c.a3, c.a3.level(0.0));
  REQUIRE(f2.num_regions() == f3.num_regions());
  REQUIRE(f2.num_regions() > 10);
  std::size_t differ = 0;
  for (Index k = 0; k < c.t2.num_cells(); ++k)
    differ += f2.flow_facets(k) != f3.flow_facets(k) || f2.outside(k) != f3.outside(k) || f2.region(k) != f3.region(k);
  CHECK(differ == 0);
}
