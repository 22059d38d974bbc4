// SPDX-License-Identifier: Apache-2.0
// Dynamic update: after every move, insertion or removal the triangulation
// must hold the cells of a fresh build of the same points (compared as
// sorted vertex lists) and pass the exact validation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "alpha/error.hpp"
#include "alpha/triangulation.hpp"
#include "alpha/validation.hpp"
#include "point_sets.hpp"

using namespace alpha;

namespace {

std::vector<std::array<Index, 4>> sorted_cells(const Triangulation& t) {
  std::vector<std::array<Index, 4>> cells;
  for (const Cell& c : t.cells()) {
    std::array<Index, 4> v = c.v;
    std::sort(v.begin(), v.end());
    cells.push_back(v);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

void require_fresh(const Triangulation& t) {
  const ValidationReport r = validate(t);
  INFO((r.problems.empty() ? std::string() : r.problems.front()));
  REQUIRE(r.valid);
  const Triangulation fresh(std::vector<Vec3>(t.points().begin(), t.points().end()),
                            std::vector<double>(t.weights().begin(), t.weights().end()));
  REQUIRE(sorted_cells(t) == sorted_cells(fresh));
  for (Index i = 0; i < t.num_points(); ++i) {
    REQUIRE(t.status(i) == fresh.status(i));
    REQUIRE(t.representative(i) == fresh.representative(i));
    // The update keeps each vertex's link to a cell of its own.
    if (t.status(i) == PointStatus::vertex) REQUIRE(t.index_of(t.incident_cell(i), i) >= 0);
    else REQUIRE(t.incident_cell(i) == kNone);
  }
  REQUIRE(t.num_vertices() == fresh.num_vertices());
  REQUIRE(t.num_hidden() == fresh.num_hidden());
  REQUIRE(t.num_finite_cells() == fresh.num_finite_cells());
}

// Mean distance to the nearest other point (brute force).
double mean_nearest(const std::vector<Vec3>& p) {
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    double best = INFINITY;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i) best = std::min(best, norm(p[i] - p[j]));
    sum += best;
  }
  return sum / double(p.size());
}

}  // namespace

TEST_CASE("moving random points gives the fresh build's cells", "[dynamic]") {
  const std::vector<Vec3> start = testing::random_points(1500, 11);
  const double nn = mean_nearest(start);
  for (const double step : {0.02, 0.05, 0.2, 0.5, 2.0}) {
    INFO("step " << step);
    // Every point: flipped and repaired in place at 0.02, rebuilt from
    // some step on (taking out and inserting a large share costs more);
    // the same cells.
    Triangulation t(start);
    const UpdateReport all = t.move_points(testing::jitter(start, step * nn, 7));
    if (step == 0.02) REQUIRE_FALSE(all.rebuilt);
    require_fresh(t);
    // One point in 50: repaired in place.
    Triangulation part(start);
    const std::vector<Vec3> to = testing::jitter(start, step * nn, 8);
    std::vector<Index> ids;
    std::vector<Vec3> where;
    for (Index i = 0; i < start.size(); i += 50) ids.push_back(i), where.push_back(to[i]);
    const UpdateReport r = part.move_points(ids, where);
    REQUIRE_FALSE(r.rebuilt);
    if (step >= 0.5) REQUIRE(r.relocated > 0);
    require_fresh(part);
  }
}

TEST_CASE("moves too large to mend are foretold by a sample of the cells and rebuilt at once", "[dynamic]") {
  const std::vector<Vec3> start = testing::random_points(3000, 61);
  const double nn = mean_nearest(start);
  for (const double step : {0.01, 0.02, 0.3, 0.5}) {
    INFO("step " << step);
    Triangulation t(start);
    const UpdateReport r = t.move_points(testing::jitter(start, step * nn, 62));
    // Every point moved: small steps are mended, large ones rebuilt
    // before anything is flipped (the sample's rate, not the limit).
    REQUIRE(r.rebuilt == (step > 0.1));
    REQUIRE(r.foretold == (step > 0.1));
    require_fresh(t);
  }
  // A few points moved far: too few cells to judge, mended.
  Triangulation t(start);
  const std::vector<Vec3> far = testing::jitter(start, 2 * nn, 63);
  std::vector<Index> ids;
  std::vector<Vec3> where;
  for (Index i = 0; i < start.size(); i += 300) ids.push_back(i), where.push_back(far[i]);
  const UpdateReport r = t.move_points(ids, where);
  REQUIRE_FALSE(r.rebuilt);
  REQUIRE_FALSE(r.foretold);
  require_fresh(t);
}

TEST_CASE("small moves of every point are mended by 2-3, 3-2 and 4-1 flips", "[dynamic]") {
  for (const bool weighted : {false, true}) {
    INFO("weighted " << weighted);
    const std::vector<Vec3> start = testing::random_points(2000, 81);
    const std::vector<double> w0 = weighted ? testing::random_weights(start.size(), 82, 0.0, 0.02) : std::vector<double>{};
    Triangulation t(start, w0);
    std::vector<double> w = w0;
    if (weighted)
      for (std::size_t i = 0; i < w.size(); ++i) w[i] = std::max(0.0, w[i] + 0.0003 * std::sin(double(i)));
    const UpdateReport r = t.move_points(testing::jitter(start, 0.02 * mean_nearest(start), 83), w);
    REQUIRE_FALSE(r.rebuilt);
    CHECK(r.flips23 > 0);
    CHECK(r.flips32 > 0);
    // Some vertices sent back for an inverted cell reach their new place
    // alone, once the others have moved and flipped.
    CHECK(r.returned > 0);
    // Weights that shrink make some balls redundant: 4-1 flips hide them.
    CHECK((r.flips41 > 0) == weighted);
    require_fresh(t);
  }
}

TEST_CASE("weights that change more: facets no flip mends send a vertex back", "[dynamic]") {
  const std::vector<Vec3> start = testing::random_points(3000, 5);
  const std::vector<double> w0 = testing::random_weights(start.size(), 6, 0.0, 0.02);
  Triangulation t(start, w0);
  std::vector<double> w = w0;
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = std::max(0.0, w[i] + 0.0004 * std::sin(3.0 * double(i)));
  const UpdateReport r = t.move_points(testing::jitter(start, 0.0006, 7), w);
  REQUIRE_FALSE(r.rebuilt);
  CHECK(r.flips41 > 0);
  CHECK(r.relocated > 0);
  require_fresh(t);
}

TEST_CASE("repeated moves of part of the points", "[dynamic]") {
  std::vector<Vec3> p = testing::random_points(1200, 3);
  const double nn = mean_nearest(p);
  Triangulation t(p);
  std::mt19937_64 rng(5);
  for (int round = 0; round < 8; ++round) {
    std::vector<Index> ids;
    std::vector<Vec3> to;
    const std::vector<Vec3> moved = testing::jitter(p, 0.3 * nn, 100 + round);
    for (Index i = 0; i < p.size(); ++i)
      if (rng() % 10 == 0) ids.push_back(i), to.push_back(moved[i]), p[i] = moved[i];
    const UpdateReport r = t.move_points(ids, to);
    REQUIRE_FALSE(r.rebuilt);
    require_fresh(t);
  }
}

TEST_CASE("weighted points with hidden ones: positions and weights move", "[dynamic]") {
  const std::vector<Vec3> start = testing::random_points(1500, 21);
  const std::vector<double> w0 = testing::random_weights(start.size(), 22, 0.0, 0.02);
  Triangulation t(start, w0);
  REQUIRE(t.num_hidden() > 20);
  const double nn = mean_nearest(start);
  std::vector<Vec3> p = start;
  std::vector<double> w = w0;
  // A tenth of the points each round (a moved point's new place is
  // often a hidden one's), then only weights.
  for (int round = 0; round < 5; ++round) {
    const std::vector<Vec3> to = testing::jitter(p, 0.15 * nn, 40 + round);
    const std::vector<double> dw = testing::random_weights(w.size(), 50 + round, -0.002, 0.002);
    std::vector<Index> ids;
    std::vector<Vec3> where;
    std::vector<double> ws;
    for (Index i = Index(round); i < p.size(); i += 10) {
      if (round < 4) p[i] = to[i];
      w[i] = round < 4 ? std::max(0.0, w[i] + dw[i]) : (i % 20 ? w[i] * 0.75 : 0.015);
      ids.push_back(i), where.push_back(p[i]), ws.push_back(w[i]);
    }
    const UpdateReport r = t.move_points(ids, where, ws);
    REQUIRE_FALSE(r.rebuilt);
    require_fresh(t);
    REQUIRE(t.num_hidden() > 0);
  }
}

TEST_CASE("degenerate inputs: grid, cospherical, coplanar", "[dynamic]") {
  SECTION("integer grid, points moved to free grid places") {
    std::vector<Vec3> all = testing::grid_points(7);
    std::vector<Vec3> p;  // every other place is free
    std::vector<Vec3> free;
    for (std::size_t i = 0; i < all.size(); ++i) (i % 3 == 0 ? free : p).push_back(all[i]);
    Triangulation t(p);
    std::mt19937_64 rng(9);
    for (int round = 0; round < 30; ++round) {  // a few points a round: far moves of many are rebuilt
      std::vector<Index> ids;
      std::vector<Vec3> to;
      for (int k = 0; k < 3; ++k) {
        const Index i = Index(rng() % p.size());
        if (std::find(ids.begin(), ids.end(), i) != ids.end()) continue;
        const std::size_t f = rng() % free.size();
        ids.push_back(i), to.push_back(free[f]);
        std::swap(p[i], free[f]);
      }
      REQUIRE_FALSE(t.move_points(ids, to).rebuilt);
      require_fresh(t);
    }
    // The whole grid shifted by one unit: every cube still cospherical.
    for (Vec3& q : p) q.x += 1;
    REQUIRE_FALSE(t.move_points(p).rebuilt);
    require_fresh(t);
  }
  SECTION("cospherical points, some moved onto a larger sphere") {
    std::vector<Vec3> p = testing::sphere_points(50);
    Triangulation t(p);
    std::vector<Index> ids;
    std::vector<Vec3> to;
    for (Index i = 0; i < p.size(); i += 9) ids.push_back(i), to.push_back(2.0 * p[i]), p[i] = 2.0 * p[i];
    REQUIRE_FALSE(t.move_points(ids, to).rebuilt);
    require_fresh(t);
  }
  SECTION("points moved into a plane of others") {
    std::vector<Vec3> p;
    for (int x = 0; x < 6; ++x)
      for (int y = 0; y < 6; ++y) p.push_back({double(x), double(y), 0});
    const std::vector<Vec3> above = testing::random_points(60, 31, 5.0);
    p.insert(p.end(), above.begin(), above.end());
    Triangulation t(p);
    for (Index i = 36; i < p.size(); i += 8) {  // one at a time: far moves of many are rebuilt
      p[i].z = 0, p[i].x += 0.25;  // onto the plane, off the grid lines
      const Index ids[] = {i};
      REQUIRE_FALSE(t.move_points(ids, std::span<const Vec3>(&p[i], 1)).rebuilt);
      require_fresh(t);
    }
  }
}

TEST_CASE("duplicates: made, split and moved", "[dynamic]") {
  std::vector<Vec3> p = testing::random_points(400, 41);
  p[10] = p[20];  // a duplicate from the start
  Triangulation t(p);
  REQUIRE(t.num_duplicates() == 1);
  SECTION("a point moves onto another: rebuilt, merged") {
    const Index ids[] = {5};
    const Vec3 to[] = {p[6]};
    REQUIRE(t.move_points(ids, to).rebuilt);
    REQUIRE(t.num_duplicates() == 2);
    require_fresh(t);
  }
  SECTION("a duplicate leaves its group: rebuilt, split") {
    const Index ids[] = {20};
    const Vec3 to[] = {Vec3{0.5, 0.5, 0.5}};
    REQUIRE(t.move_points(ids, to).rebuilt);
    REQUIRE(t.num_duplicates() == 0);
    require_fresh(t);
  }
  SECTION("other points move: local, the group stays") {
    std::vector<Index> ids;
    std::vector<Vec3> to;
    const std::vector<Vec3> moved = testing::jitter(p, 0.02, 3);
    for (Index i = 30; i < 70; ++i) ids.push_back(i), to.push_back(moved[i]);
    REQUIRE_FALSE(t.move_points(ids, to).rebuilt);
    require_fresh(t);
  }
}

TEST_CASE("moves onto another point's place are found without a full scan: rebuilt, merged", "[dynamic]") {
  const std::vector<Vec3> p = testing::random_points(1500, 21);
  const std::vector<double> w = testing::random_weights(p.size(), 22, 0.0, 0.02);
  Triangulation t(p, w);
  Index hidden = kNone, vertex = kNone, far = kNone;
  for (Index i = 0; i < p.size(); ++i) {
    if (t.status(i) == PointStatus::hidden && hidden == kNone) hidden = i;
    else if (t.status(i) == PointStatus::vertex) (vertex == kNone ? vertex : far) = i;
  }
  REQUIRE(hidden != kNone);
  const auto move_one = [&](Index i, Vec3 to) {
    const Index ids[] = {i};
    const Vec3 where[] = {to};
    const double weight[] = {w[i]};
    return t.move_points(ids, where, weight);
  };
  SECTION("a vertex onto a hidden point") {
    REQUIRE(move_one(far, p[hidden]).rebuilt);
    REQUIRE(t.num_duplicates() == 1);
    require_fresh(t);
  }
  SECTION("a hidden point onto a vertex") {
    REQUIRE(move_one(hidden, p[vertex]).rebuilt);
    REQUIRE(t.num_duplicates() == 1);
    require_fresh(t);
  }
  SECTION("two points onto one new place") {
    const Index ids[] = {vertex, far};
    const Vec3 where[] = {Vec3{0.5, 0.5, 0.5}, Vec3{0.5, 0.5, 0.5}};
    const double weights[] = {w[vertex], w[far]};
    REQUIRE(t.move_points(ids, where, weights).rebuilt);
    REQUIRE(t.num_duplicates() == 1);
    require_fresh(t);
  }
  SECTION("a vertex next to another, not onto it: local") {
    REQUIRE_FALSE(move_one(far, p[vertex] + Vec3{1e-9, 0, 0}).rebuilt);
    require_fresh(t);
  }
}

TEST_CASE("insert and remove points", "[dynamic]") {
  for (const bool weighted : {false, true}) {
    INFO("weighted " << weighted);
    const std::vector<Vec3> p = testing::random_points(1000, 61);
    const std::vector<double> w = weighted ? testing::random_weights(p.size(), 62, 0, 0.02) : std::vector<double>{};
    Triangulation t(p, w);
    const std::vector<Vec3> more = testing::random_points(200, 63);
    const std::vector<double> more_w = weighted ? testing::random_weights(more.size(), 64, 0, 0.02) : std::vector<double>{};
    REQUIRE_FALSE(t.insert_points(more, more_w).rebuilt);
    REQUIRE(t.num_points() == 1200);
    require_fresh(t);
    std::vector<Index> gone;
    for (Index i = 0; i < t.num_points(); i += 7) gone.push_back(i);
    const UpdateReport r = t.remove_points(gone);
    REQUIRE_FALSE(r.rebuilt);
    REQUIRE(r.relocated > 100);
    REQUIRE(t.num_points() == 1200 - gone.size());
    require_fresh(t);
  }
  SECTION("removing hull vertices of a grid") {
    Triangulation t(testing::grid_points(4));
    const Index corners[] = {0, 3, 12, 15, 48, 51, 60, 63};
    REQUIRE_FALSE(t.remove_points(corners).rebuilt);
    require_fresh(t);
  }
}

TEST_CASE("dynamic update: bad calls leave the triangulation as it was", "[dynamic]") {
  std::vector<Vec3> p = testing::random_points(50, 71);
  Triangulation t(p);
  const auto cells = sorted_cells(t);
  const Index one[] = {3};
  const Vec3 far[] = {Vec3{1e16, 0, 0}};
  REQUIRE_THROWS_AS(t.move_points(one, far), Error);
  const double weight[] = {1.0};
  REQUIRE_THROWS_AS(t.move_points(one, std::span<const Vec3>(far, 1), weight), Error);
  // Every point onto one plane: no 3D triangulation.
  std::vector<Vec3> flat = p;
  for (Vec3& q : flat) q.z = 0;
  REQUIRE_THROWS_AS(t.move_points(flat), Error);
  REQUIRE(sorted_cells(t) == cells);
  std::vector<Index> all(p.size() - 2);
  std::iota(all.begin(), all.end(), Index(0));
  REQUIRE_THROWS_AS(t.remove_points(all), Error);
  REQUIRE(sorted_cells(t) == cells);
  require_fresh(t);
}
