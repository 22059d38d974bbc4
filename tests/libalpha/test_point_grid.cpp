// SPDX-License-Identifier: Apache-2.0
// alpha::PointGrid against brute force: every point within the radius is
// visited, nothing outside the cube's cells is, each once; far, infinite
// and NaN queries and far-apart points neither misbehave nor walk the
// empty cells between them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "alpha/point_grid.hpp"
#include "point_sets.hpp"

using alpha::Index;
using alpha::Vec3;

namespace {

std::vector<Index> visited(const alpha::PointGrid& g, const Vec3& c, double r) {
  std::vector<Index> ids;
  g.visit(c, r, [&](Index i) { ids.push_back(i); });
  return ids;
}

}  // namespace

TEST_CASE("PointGrid visits a superset of the points within the radius, each once", "[point_grid]") {
  // Random points, a grid (points on cell borders), duplicates and two far
  // outliers (keys saturate).
  std::vector<Vec3> pts = testing::random_points(500, 31, 20.0);
  for (const Vec3& p : testing::grid_points(4, 2.5)) pts.push_back(p);
  pts.push_back(pts[3]);
  pts.push_back({1e200, -3, 4});
  pts.push_back({-1e300, 1e300, 0});
  const double spacing = 2.5;
  alpha::PointGrid g(spacing);
  for (Index i = 0; i < Index(pts.size()); ++i) g.add(pts[i], i);
  g.finish();

  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> coord(-5, 25);
  std::vector<std::pair<Vec3, double>> queries;
  for (int k = 0; k < 200; ++k) queries.push_back({{coord(rng), coord(rng), coord(rng)}, std::fabs(coord(rng)) / 3});
  queries.push_back({pts[7], 0.0});                // radius 0 at a point
  queries.push_back({{5, 5, 5}, 1e6});             // more cells than points: scanned
  queries.push_back({{1e200, -3, 4}, 1.0});        // at the far outlier
  queries.push_back({{0, 0, 0}, std::numeric_limits<double>::infinity()});
  for (const auto& [c, r] : queries) {
    INFO("centre " << c.x << " " << c.y << " " << c.z << ", radius " << r);
    std::vector<Index> ids = visited(g, c, r);
    std::vector<Index> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());  // each once
    for (Index i = 0; i < Index(pts.size()); ++i) {
      const Vec3 d = pts[i] - c;
      const bool in_cube = std::fabs(d.x) <= r && std::fabs(d.y) <= r && std::fabs(d.z) <= r;
      if (in_cube) CHECK(std::binary_search(sorted.begin(), sorted.end(), i));
    }
    // Nothing beyond the cells that meet the cube (one cell of slack).
    for (Index i : ids) {
      const Vec3 d = pts[i] - c;
      CHECK(std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)}) <= r + 2 * spacing);
    }
  }
  CHECK(g.covers_all({0, 0, 0}, std::numeric_limits<double>::infinity()));
  CHECK(visited(g, {0, 0, 0}, std::numeric_limits<double>::infinity()).size() == pts.size());
  CHECK_FALSE(g.covers_all({5, 5, 5}, 100.0));  // the outliers lie beyond
}

TEST_CASE("PointGrid visits exactly the points of the cells meeting the cube, in key order", "[point_grid]") {
  // Compact points (cells found by index) and the same with a far outlier
  // (too many empty cells for an index: found by binary search) must visit
  // alike: the cells' points ordered by cell (x, then y, then z), then id,
  // whatever the order they were added in (here shuffled).
  const double spacing = 1.7;
  const std::vector<Vec3> compact = testing::random_points(2000, 33, 30.0);
  std::vector<Vec3> sparse = compact;
  sparse.push_back({1e9, 0, 0});
  const auto cell = [&](double v) { return std::int64_t(std::floor(v / spacing)); };
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> coord(-3, 33), radius(0, 6);
  for (const std::vector<Vec3>* pts : {&compact, static_cast<const std::vector<Vec3>*>(&sparse)}) {
    alpha::PointGrid g(spacing);
    std::vector<Index> order(pts->size());
    std::iota(order.begin(), order.end(), Index(0));
    std::shuffle(order.begin(), order.end(), rng);
    for (const Index i : order) g.add((*pts)[i], i);
    g.finish();
    for (int k = 0; k < 100; ++k) {
      const Vec3 c{coord(rng), coord(rng), coord(rng)};
      const double r = radius(rng);
      std::vector<std::pair<std::array<std::int64_t, 3>, Index>> expected;
      for (Index i = 0; i < Index(compact.size()); ++i) {
        const Vec3& p = compact[i];
        const std::array<std::int64_t, 3> key{cell(p.x), cell(p.y), cell(p.z)};
        if (key[0] >= cell(c.x - r) && key[0] <= cell(c.x + r) && key[1] >= cell(c.y - r) && key[1] <= cell(c.y + r) &&
            key[2] >= cell(c.z - r) && key[2] <= cell(c.z + r))
          expected.emplace_back(key, i);
      }
      std::sort(expected.begin(), expected.end());
      std::vector<Index> ids;
      for (const auto& e : expected) ids.push_back(e.second);
      INFO("points " << pts->size() << ", centre " << c.x << " " << c.y << " " << c.z << ", radius " << r);
      CHECK(visited(g, c, r) == ids);
    }
  }
}

TEST_CASE("PointGrid: NaN, infinite and far queries; sparse points far apart", "[point_grid]") {
  alpha::PointGrid g(1.0);
  g.add({0, 0, 0}, 0);
  g.add({1e6, 1e6, 1e6}, 1);  // 10^18 empty cells between the two
  g.finish();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  CHECK(visited(g, {nan, 0, 0}, 1.0).empty());
  CHECK(visited(g, {0, 0, 0}, nan).empty());
  CHECK(visited(g, {inf, 0, 0}, 1.0).empty());
  CHECK(visited(g, {1e300, 1e300, 1e300}, 1.0).empty());
  CHECK(visited(g, {0.5, 0.5, 0.5}, 1.0) == std::vector<Index>{0});
  // A cube over both: answered by a scan, at once (walking its cells would not end).
  CHECK(visited(g, {5e5, 5e5, 5e5}, 1e6) == std::vector<Index>{0, 1});
  CHECK(g.covers_all({5e5, 5e5, 5e5}, 1e6));
  CHECK_FALSE(g.covers_all({0, 0, 0}, 10.0));
  alpha::PointGrid empty(1.0);
  empty.finish();
  CHECK(visited(empty, {0, 0, 0}, 1.0).empty());
  CHECK(empty.covers_all({0, 0, 0}, 1.0));
}

TEST_CASE("PointGrid::any stops at the first visited point its test accepts", "[point_grid]") {
  // Indexed cells, binary-searched cells (a far outlier) and a scan (a cube
  // of more cells than points): the test sees the visit's prefix up to the
  // first accepted point, and any() says whether there was one.
  const std::vector<Vec3> compact = testing::random_points(800, 35, 20.0);
  std::vector<Vec3> sparse = compact;
  sparse.push_back({1e9, 0, 0});
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> coord(-3, 23), radius(0, 5);
  for (const std::vector<Vec3>* pts : {&compact, static_cast<const std::vector<Vec3>*>(&sparse)}) {
    alpha::PointGrid g(1.3);
    for (Index i = 0; i < Index(pts->size()); ++i) g.add((*pts)[i], i);
    g.finish();
    for (int k = 0; k < 100; ++k) {
      const Vec3 c{coord(rng), coord(rng), coord(rng)};
      const double r = k == 0 ? 1e6 : radius(rng);
      const Index modulus = 1 + Index(k % 40);  // accepts ids divisible by it
      const std::vector<Index> all = visited(g, c, r);
      const auto first = std::find_if(all.begin(), all.end(), [&](Index i) { return i % modulus == 0; });
      std::vector<Index> seen;
      const bool found = g.any(c, r, [&](Index i) {
        seen.push_back(i);
        return i % modulus == 0;
      });
      INFO("centre " << c.x << " " << c.y << " " << c.z << ", radius " << r << ", modulus " << modulus);
      CHECK(found == (first != all.end()));
      CHECK(seen == std::vector<Index>(all.begin(), first == all.end() ? first : first + 1));
    }
  }
}
