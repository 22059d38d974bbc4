// SPDX-License-Identifier: Apache-2.0
// alpha::persistent_basins: a partition of the cells, the connected
// components at an infinite threshold, one flow sink per basin at
// threshold 0, coarser with a larger threshold, and the exact answer on a
// grid whose cubes are equal basins joined by square passages; the size
// rule: cubes kept apart or paired by their volume, and the finest basins
// when every merge is too heavy.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/discrete_flow.hpp"
#include "alpha/error.hpp"
#include "alpha/geometry.hpp"
#include "alpha/persistent_basins.hpp"
#include "point_sets.hpp"
#include "threaded_complexes.hpp"

using namespace alpha;

namespace {

using Basins = std::vector<std::vector<Index>>;

// The empty finite cells at a level, sorted.
std::vector<Index> empty_cells(const AlphaComplex& ac, Index level) {
  std::vector<Index> cells;
  for (Index c = 0; c < ac.triangulation().num_cells(); ++c)
    if (!ac.triangulation().is_infinite(c) && ac.cell_entry(c) >= level) cells.push_back(c);
  return cells;
}

// basin number of each cell; checks that the basins partition `cells`.
std::map<Index, std::size_t> check_partition(const Basins& basins, const std::vector<Index>& cells) {
  std::map<Index, std::size_t> basin_of;
  Index previous_first = 0;
  for (std::size_t b = 0; b < basins.size(); ++b) {
    REQUIRE(!basins[b].empty());
    REQUIRE(std::is_sorted(basins[b].begin(), basins[b].end()));
    if (b > 0) REQUIRE(basins[b].front() > previous_first);  // ordered by smallest cell
    previous_first = basins[b].front();
    for (Index c : basins[b]) REQUIRE(basin_of.emplace(c, b).second);
  }
  REQUIRE(basin_of.size() == cells.size());
  for (Index c : cells) REQUIRE(basin_of.count(c) == 1);
  return basin_of;
}

// Components of the cells through triangles empty at the level, by search.
std::size_t components(const AlphaComplex& ac, Index level, const std::vector<Index>& cells) {
  const Triangulation& t = ac.triangulation();
  const std::set<Index> in(cells.begin(), cells.end());
  std::set<Index> seen;
  std::size_t n = 0;
  for (Index seed : cells) {
    if (!seen.insert(seed).second) continue;
    ++n;
    std::vector<Index> stack{seed};
    while (!stack.empty()) {
      const Index c = stack.back();
      stack.pop_back();
      for (int k = 0; k < 4; ++k) {
        const Index m = t.cell(c).n[k];
        if (in.count(m) && ac.triangle_interval(ac.simplices().cell_triangle(c, k)).entry >= level &&
            seen.insert(m).second)
          stack.push_back(m);
      }
    }
  }
  return n;
}

// Each cell's volume, in the order of `cells`.
std::vector<double> volumes(const Triangulation& t, const std::vector<Index>& cells) {
  std::vector<double> v;
  for (Index c : cells) {
    const auto& q = t.cell(c).v;
    v.push_back(tetrahedron_volume(t.point(q[0]), t.point(q[1]), t.point(q[2]), t.point(q[3])));
  }
  return v;
}

// The lowest corner of the unit cube holding each basin; checks that each
// basin's vertices span exactly one unit cube.
std::vector<Vec3> cube_corners(const Triangulation& t, const Basins& basins) {
  std::vector<Vec3> corners;
  for (const auto& b : basins) {
    Vec3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
    for (Index c : b)
      for (Index v : t.cell(c).v) {
        const Vec3& p = t.point(v);
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      }
    CHECK(hi.x - lo.x == 1);
    CHECK(hi.y - lo.y == 1);
    CHECK(hi.z - lo.z == 1);
    corners.push_back(lo);
  }
  return corners;
}

void check_basins(const AlphaComplex& ac, Index level) {
  const Triangulation& t = ac.triangulation();
  const std::vector<Index> cells = empty_cells(ac, level);
  if (cells.empty()) return;
  const double inf = std::numeric_limits<double>::infinity();
  const Basins whole = persistent_basins(ac, level, cells, {inf});
  check_partition(whole, cells);
  CHECK(whole.size() == components(ac, level, cells));

  // Threshold 0: every basin holds exactly one sink of the flow among the
  // cells (a cell that flows into no cell of the set); general position.
  const Basins finest = persistent_basins(ac, level, cells, {0.0});
  const auto basin_of = check_partition(finest, cells);
  const std::set<Index> in(cells.begin(), cells.end());
  const DiscreteFlow flow(ac, level);
  std::vector<int> sinks(finest.size(), 0);
  for (Index c : cells) {
    bool sink = true;
    for (int k = 0; k < 4; ++k)
      if ((flow.flow_facets(c) & (1u << k)) && in.count(t.cell(c).n[k])) sink = false;
    sinks[basin_of.at(c)] += sink;
  }
  for (int m : sinks) CHECK(m == 1);

  // The size rule with every merge too heavy (masses > 0, max_mass 0):
  // only the merges at persistence 0 are left, whatever the threshold.
  const std::vector<double> mass = volumes(t, cells);
  for (double threshold : {0.0, 0.5, inf}) CHECK(persistent_basins(ac, level, cells, {threshold, mass, 0.0, 0.0}) == finest);

  // Coarser with a larger threshold: every basin lies inside one coarser basin.
  Basins finer = finest;
  for (double threshold : {0.05, 0.2, 0.5, 2.0}) {
    const Basins coarser = persistent_basins(ac, level, cells, {threshold});
    const auto coarse_of = check_partition(coarser, cells);
    CHECK(coarser.size() <= finer.size());
    for (const auto& b : finer)
      for (Index c : b) CHECK(coarse_of.at(c) == coarse_of.at(b.front()));
    finer = coarser;
  }
}

}  // namespace

TEST_CASE("Persistent basins: partitions, components and maxima", "[basins]") {
  for (std::uint64_t seed : {1u, 2u}) {
    const Triangulation t(testing::random_points(300, seed, 10.0), testing::random_weights(300, seed + 3, 0.5, 2.0));
    const AlphaComplex ac(t);
    for (double alpha_sq : {0.0, 0.5, 2.0}) check_basins(ac, ac.level(alpha_sq));
  }
  const Triangulation u(testing::random_points(300, 9, 1.0));
  const AlphaComplex au(u);
  check_basins(au, au.level(0.002));
}

TEST_CASE("Persistent basins: a grid's cubes are basins of persistence sqrt(3/4) - sqrt(1/2)", "[basins]") {
  // Unweighted 4x4x4 grid: every cell of a unit cube has the cube's
  // circumsphere (size 3/4); neighbouring cubes meet at squares whose
  // triangles have size 1/2. Equal maxima: the younger cube persists
  // sqrt(3/4) - sqrt(1/2) = 0.1589.
  const Triangulation t(testing::grid_points(4));
  const AlphaComplex ac(t);
  const Index level = ac.level(0.0);
  const std::vector<Index> cells = empty_cells(ac, level);
  const Basins cubes = persistent_basins(ac, level, cells, {0.15});
  check_partition(cubes, cells);
  REQUIRE(cubes.size() == 27);
  cube_corners(t, cubes);
  CHECK(persistent_basins(ac, level, cells, {0.17}).size() == 1);
}

TEST_CASE("Persistent basins: the same for a complex built on 2 or 3 threads", "[basins]") {
  const testing::ThreadedComplexes c(8);
  REQUIRE(c.t2.num_vertices() >= AlphaComplex::kThreadsFrom);
  const std::vector<Index> cells = empty_cells(c.a2, c.a2.level(0.0));
  REQUIRE(cells == empty_cells(c.a3, c.a3.level(0.0)));
  const Basins basins = persistent_basins(c.a2, c.a2.level(0.0), cells, {0.2});
  REQUIRE(basins.size() > 10);
  CHECK(persistent_basins(c.a3, c.a3.level(0.0), cells, {0.2}) == basins);
}

TEST_CASE("Persistent basins: the size rule on a grid's cubes", "[basins]") {
  // Cubes of volume 1 (the mass: cell volumes) joined by passages of
  // persistence 0.1589 < threshold: without the size rule one basin.
  const Triangulation t(testing::grid_points(4));
  const AlphaComplex ac(t);
  const Index level = ac.level(0.0);
  const std::vector<Index> cells = empty_cells(ac, level);
  const std::vector<double> mass = volumes(t, cells);
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(persistent_basins(ac, level, cells, {inf, mass}).size() == 1);
  CHECK(persistent_basins(ac, level, cells, {inf, mass, 0.9, 2.5 * 27}).size() == 1);

  // Two cubes of at least 0.9 weigh 2 > 1.5: the 27 cubes stay apart.
  const Basins apart = persistent_basins(ac, level, cells, {inf, mass, 0.9, 1.5});
  check_partition(apart, cells);
  CHECK(apart == persistent_basins(ac, level, cells, {0.15}));

  // Up to 2.5: single cubes and pairs, and no two single cubes side by
  // side (they would have merged).
  const Basins paired = persistent_basins(ac, level, cells, {inf, mass, 0.9, 2.5});
  check_partition(paired, cells);
  std::map<Index, std::size_t> basin_of;
  std::size_t singles = 0;
  for (std::size_t b = 0; b < paired.size(); ++b) {
    double m = 0;
    for (Index c : paired[b]) {
      basin_of[c] = b;
      m += mass[std::lower_bound(cells.begin(), cells.end(), c) - cells.begin()];
    }
    const bool single = std::fabs(m - 1) < 1e-9;
    CHECK((single || std::fabs(m - 2) < 1e-9));
    singles += single;
  }
  CHECK(paired.size() < 27);
  const std::vector<Vec3> corner = cube_corners(t, apart);
  for (std::size_t a = 0; a < apart.size(); ++a)
    for (std::size_t b = a + 1; b < apart.size(); ++b) {
      const Vec3 d = corner[a] - corner[b];
      if (std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z) != 1) continue;  // not face neighbours
      const std::size_t pa = basin_of.at(apart[a].front()), pb = basin_of.at(apart[b].front());
      const bool single_a = paired[pa].size() == apart[a].size(), single_b = paired[pb].size() == apart[b].size();
      CHECK(!(single_a && single_b));
    }
  CHECK(singles < 27);
}

TEST_CASE("Persistent basins: bad input", "[basins]") {
  const Triangulation t(testing::grid_points(3));
  const AlphaComplex ac(t);
  const Index level = ac.level(0.0);
  std::vector<Index> cells = empty_cells(ac, level);
  std::reverse(cells.begin(), cells.end());
  CHECK_THROWS_AS(persistent_basins(ac, level, cells, {1.0}), Error);  // not sorted
  std::vector<Index> infinite;
  for (Index c = 0; c < t.num_cells(); ++c)
    if (t.is_infinite(c)) infinite.push_back(c);
  CHECK_THROWS_AS(persistent_basins(ac, level, infinite, {1.0}), Error);
  CHECK(persistent_basins(ac, level, {}, {1.0}).empty());
  std::sort(cells.begin(), cells.end());
  const std::vector<double> short_mass(cells.size() - 1, 1.0);
  CHECK_THROWS_AS(persistent_basins(ac, level, cells, {1.0, short_mass}), Error);
  std::vector<double> negative(cells.size(), 1.0);
  negative[0] = -1;
  CHECK_THROWS_AS(persistent_basins(ac, level, cells, {1.0, negative}), Error);
}
