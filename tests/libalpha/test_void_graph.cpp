// SPDX-License-Identifier: Apache-2.0
// alpha::VoidGraph and alpha/void_paths: the narrowest point of every
// power-diagram edge against dense sampling of the edge, widest paths
// against a brute-force maximin over all simple paths and against
// threshold connectivity, cheapest paths against Bellman-Ford, and the
// bottlenecks of configurations with closed forms (a ring of n equal
// balls, a straight channel of rings, a closed cage with one window).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/void_graph.hpp"
#include "alpha/void_paths.hpp"
#include "point_sets.hpp"

using namespace alpha;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Balls {
  std::vector<Vec3> points;
  std::vector<double> radii;
  std::vector<double> weights() const {
    std::vector<double> w;
    for (const double r : radii) w.push_back(r * r);
    return w;
  }
};

struct Built {
  Triangulation t;
  AlphaComplex ac;
  VoidGraph g;
  explicit Built(const Balls& b, std::vector<double> clearance_radii = {})
      : t(b.points, b.weights()), ac(t), g(ac, clearance_radii.empty() ? b.radii : clearance_radii) {}
};

double clearance_to(const Triangulation& t, const std::vector<double>& radii, const Vec3& x,
                    const std::array<Index, 3>& tri) {
  double d = kInf;
  for (const Index v : tri) d = std::min(d, norm(x - t.point(v)) - radii[v]);
  return d;
}

// Every edge: its narrowest point lies on its dual segment (ray) and no
// sample of the segment is narrower.
void check_narrowest(const Built& b, const std::vector<double>& radii) {
  const Triangulation& t = b.t;
  const Simplices& s = b.ac.simplices();
  for (Index f = 0; f < s.num_triangles(); ++f) {
    const auto tri = s.triangle(f);
    const auto ends = b.g.ends(f);
    const Vec3 m = b.g.narrowest(f);
    REQUIRE(b.g.clearance(f) == Approx(clearance_to(t, radii, m, tri)).margin(1e-12));
    std::vector<Vec3> samples;
    if (ends[0] != b.g.outside() && ends[1] != b.g.outside()) {
      const Vec3 a = b.g.position(ends[0]), c = b.g.position(ends[1]);
      // m on the segment: |a - m| + |m - c| = |a - c|.
      REQUIRE(norm(a - m) + norm(m - c) == Approx(norm(a - c)).margin(1e-7));
      for (int i = 0; i <= 400; ++i) samples.push_back(a + (i / 400.0) * (c - a));
    } else {
      const Index inner = ends[0] == b.g.outside() ? ends[1] : ends[0];
      const Vec3 a = b.g.position(inner);
      const Vec3 p0 = t.point(tri[0]), p1 = t.point(tri[1]), p2 = t.point(tri[2]);
      Vec3 n = cross(p1 - p0, p2 - p0);
      n = (1 / norm(n)) * n;
      // The ray leaves away from the finite cell's fourth vertex.
      Index q = kNone;
      for (const Index v : t.cell(inner).v)
        if (v != tri[0] && v != tri[1] && v != tri[2]) q = v;
      if (dot(t.point(q) - p0, n) > 0) n = -1.0 * n;
      // m on the ray: m - a is a non-negative multiple of n.
      const double along = dot(m - a, n);
      REQUIRE(along >= -1e-9);
      REQUIRE(norm(m - a - along * n) <= 1e-7 * (1 + norm(a)));
      for (int i = 0; i <= 400; ++i) samples.push_back(a + (i / 40.0) * n);
    }
    for (const Vec3& x : samples) REQUIRE(clearance_to(t, radii, x, tri) >= b.g.clearance(f) - 1e-9);
  }
}

// Brute-force maximin: every simple path from s, depth first.
std::vector<double> brute_widest(const VoidGraph& g, Index s, const std::vector<bool>& stop) {
  std::vector<double> best(g.num_nodes(), -kInf);
  std::vector<bool> on(g.num_nodes(), false);
  std::function<void(Index, double)> walk = [&](Index n, double width) {
    best[n] = std::max(best[n], width);
    if (!stop.empty() && stop[n] && n != s) return;
    on[n] = true;
    g.for_each_edge(n, [&](Index f, Index m) {
      if (!on[m]) walk(m, std::min(width, g.clearance(f)));
    });
    on[n] = false;
  };
  walk(s, kInf);
  return best;
}

Balls random_balls(std::size_t n, std::uint64_t seed, double max_weight = 4) {
  Balls b;
  b.points = testing::random_points(n, seed, 10.0);
  for (const double w : testing::random_weights(n, seed + 1, 0.25, max_weight)) b.radii.push_back(std::sqrt(w));
  return b;
}

// A ring of n balls of radius r (testing::ring_points).
void add_ring(Balls& b, int n, double R, double r, double h, double phase = 0) {
  for (const Vec3& p : testing::ring_points(n, R, h, phase)) b.points.push_back(p), b.radii.push_back(r);
}

// The finite node nearest to x.
Index node_near(const VoidGraph& g, const Vec3& x) {
  Index best = kNone;
  double d = kInf;
  for (Index n = 0; n < g.num_nodes(); ++n)
    if (n != g.outside() && g.is_node(n) && norm(g.position(n) - x) < d) d = norm(g.position(n) - x), best = n;
  return best;
}

// Width of the widest path from node a to node b that does not pass outside.
double widest_between(const VoidGraph& g, Index a, Index b) {
  std::vector<bool> stop(g.num_nodes(), false);
  stop[g.outside()] = true;
  const Index sources[] = {a};
  const PathTree tree = widest_paths(g, sources, stop);
  // The tree path's own bottleneck is its label.
  double width = kInf;
  for (const Index f : path_edges(g, tree, b)) width = std::min(width, g.clearance(f));
  REQUIRE(width == tree.value[b]);
  return tree.value[b];
}

}  // namespace

TEST_CASE("void graph: the narrowest point of every edge (random weighted balls, other radii, a grid)", "[void_graph]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Balls b = random_balls(40, seed);
    check_narrowest(Built(b), b.radii);
    // Clearances to balls other than the diagram's (atoms' vdW spheres in a
    // diagram of probe-grown balls): the same argument holds.
    std::vector<double> smaller;
    for (const double r : b.radii) smaller.push_back(std::max(0.0, r - 0.7));
    check_narrowest(Built(b, smaller), smaller);
  }
  Balls grid;  // degenerate: every cube's corners cospherical
  grid.points = testing::grid_points(4, 2.0);
  grid.radii.assign(grid.points.size(), 0.8);
  const Built g(grid);
  check_narrowest(g, grid.radii);
  // Every triangle lies in a face of a grid cube (narrowest at the face's
  // centre, sqrt(2) from its corners: the fourth corner is on its
  // orthosphere and does not attach it) or inside one (attached: narrowest
  // at the cube's centre, the orthocentre of all its cells, sqrt(3) away).
  std::size_t faces = 0;
  for (Index f = 0; f < g.g.num_edges(); ++f) {
    const double c = g.g.clearance(f);
    const bool face = std::abs(c - (std::sqrt(2.0) - 0.8)) < 1e-12;
    REQUIRE((face || std::abs(c - (std::sqrt(3.0) - 0.8)) < 1e-12));
    faces += face;
  }
  REQUIRE(faces == 2 * 3 * 4 * 3 * 3);  // 3 orientations x 4 planes x 3 x 3 squares, 2 triangles each
}

TEST_CASE("void paths: widest paths equal brute-force maximin over all simple paths", "[void_graph]") {
  for (std::uint64_t seed = 10; seed < 22; ++seed) {
    const Balls b = random_balls(7 + seed % 3, seed);
    const Built built(b);
    const VoidGraph& g = built.g;
    for (const bool with_stop : {false, true}) {
      std::vector<bool> stop;
      if (with_stop) stop.assign(g.num_nodes(), false), stop[g.outside()] = true;
      for (Index s = 0; s < g.num_nodes(); ++s) {
        if (!g.is_node(s)) continue;
        const Index sources[] = {s};
        const PathTree tree = widest_paths(g, sources, stop);
        const std::vector<double> brute = brute_widest(g, s, stop);
        for (Index n = 0; n < g.num_nodes(); ++n) {
          if (!g.is_node(n)) continue;
          REQUIRE(tree.reached(n) == (brute[n] > -kInf));
          if (n == s || !tree.reached(n)) continue;
          REQUIRE(tree.value[n] == brute[n]);
          double width = kInf;
          for (const Index f : path_edges(g, tree, n)) width = std::min(width, g.clearance(f));
          REQUIRE(width == tree.value[n]);
        }
        // Leaving out the edges narrower than a threshold keeps the widths
        // that reach it and leaves the other nodes unreached.
        const double threshold = 0.2;
        const PathTree cut = widest_paths(g, sources, stop, threshold);
        for (Index n = 0; n < g.num_nodes(); ++n)
          if (g.is_node(n) && n != s) REQUIRE((brute[n] >= threshold ? cut.value[n] == brute[n] : !cut.reached(n)));
      }
    }
  }
}

TEST_CASE("void paths: widest paths equal the threshold of connectivity (200 balls)", "[void_graph]") {
  const Balls b = random_balls(200, 99);
  const Built built(b);
  const VoidGraph& g = built.g;
  const Index s = node_near(g, {5, 5, 5});
  const Index sources[] = {s};
  const PathTree tree = widest_paths(g, sources);
  // Union-find over the edges by decreasing clearance: n joins s's set at
  // the clearance of the edge that first connects them.
  std::vector<Index> parent(g.num_nodes());
  std::iota(parent.begin(), parent.end(), Index(0));
  const std::function<Index(Index)> root = [&](Index x) { return parent[x] == x ? x : parent[x] = root(parent[x]); };
  std::vector<Index> edges(g.num_edges());
  std::iota(edges.begin(), edges.end(), Index(0));
  std::sort(edges.begin(), edges.end(), [&](Index a, Index c) { return g.clearance(a) > g.clearance(c); });
  std::vector<double> joined(g.num_nodes(), -kInf);
  joined[s] = kInf;
  for (std::size_t i = 0; i < edges.size();) {
    const double level = g.clearance(edges[i]);
    for (; i < edges.size() && g.clearance(edges[i]) == level; ++i) {
      const auto e = g.ends(edges[i]);
      parent[root(e[0])] = root(e[1]);
    }
    for (Index n = 0; n < g.num_nodes(); ++n)
      if (g.is_node(n) && joined[n] == -kInf && root(n) == root(s)) joined[n] = level;
  }
  for (Index n = 0; n < g.num_nodes(); ++n)
    if (g.is_node(n)) REQUIRE(tree.value[n] == joined[n]);
}

TEST_CASE("void paths: cheapest paths equal Bellman-Ford", "[void_graph]") {
  for (std::uint64_t seed = 30; seed < 34; ++seed) {
    const Balls b = random_balls(60, seed, 1);
    const Built built(b);
    const VoidGraph& g = built.g;
    const PathCost cost{0.3, 2};
    std::vector<bool> stop(g.num_nodes(), false);
    stop[g.outside()] = true;
    const Index s = node_near(g, {5, 5, 5});
    const Index sources[] = {s};
    const PathTree tree = cheapest_paths(g, sources, cost, stop);
    std::vector<double> d(g.num_nodes(), kInf);
    d[s] = 0;
    for (bool changed = true; changed;) {
      changed = false;
      for (Index f = 0; f < g.num_edges(); ++f) {
        if (!(g.clearance(f) >= cost.min_clearance)) continue;
        const double w = edge_length(g, f) / std::pow(g.clearance(f), cost.exponent);
        const auto e = g.ends(f);
        for (int k = 0; k < 2; ++k) {
          if (stop[e[k]] || d[e[k]] == kInf) continue;
          if (d[e[k]] + w < d[e[1 - k]] * (1 - 1e-14)) d[e[1 - k]] = d[e[k]] + w, changed = true;
        }
      }
    }
    std::size_t reached = 0;
    for (Index n = 0; n < g.num_nodes(); ++n) {
      if (!g.is_node(n)) continue;
      REQUIRE(tree.reached(n) == (d[n] < kInf));
      if (!tree.reached(n)) continue;
      REQUIRE(tree.value[n] == Approx(d[n]).epsilon(1e-12));
      ++reached;
    }
    REQUIRE(reached > 10);
  }
}

TEST_CASE("void paths: the hole of a ring of n equal balls is R - r", "[void_graph]") {
  for (int n = 3; n <= 9; ++n)
    for (const double r : {0.5, 1.0, 1.4}) {
      const double R = 3;
      Balls b;
      add_ring(b, n, R, r, 0, 0.3 * n);
      // Two balls far above and below close the ring's two sides into cells.
      b.points.push_back({0, 0, 3 * R}), b.radii.push_back(r);
      b.points.push_back({0, 0, -3 * R}), b.radii.push_back(r);
      const Built built(b);
      const VoidGraph& g = built.g;
      const double width = widest_between(g, node_near(g, {0, 0, R}), node_near(g, {0, 0, -R}));
      REQUIRE(std::abs(width - (R - r)) < 1e-9);
    }
}

TEST_CASE("void paths: a straight channel of rings has its bottleneck R - r", "[void_graph]") {
  // Rings of 8 balls of radius 1.6 on a circle of radius 3, 1.5 apart
  // along the axis: the wall is closed (neighbours overlap in and between
  // rings, the gap between four is 1.37 < 1.6 from each), so the widest
  // way from one end to the other runs inside and crosses every ring plane
  // at best at its centre, R - r from the ring's balls. Aligned rings are
  // degenerate (every 2n balls of two rings cospherical), staggered not.
  const double R = 3, r = 1.6, h = 1.5;
  for (const bool staggered : {false, true}) {
    Balls b;
    const int rings = 5;
    for (int k = 0; k < rings; ++k) add_ring(b, 8, R, r, k * h, staggered && k % 2 ? kPi / 8 : 0);
    const Built built(b);
    const VoidGraph& g = built.g;
    const double width = widest_between(g, node_near(g, {0, 0, 0.5 * h}), node_near(g, {0, 0, (rings - 1.5) * h}));
    REQUIRE(std::abs(width - (R - r)) < 1e-9);
    // Across the wall (from inside to outside with the ends closed off)
    // there is no way a probe of positive radius could go, so the widest
    // path from the middle to outside leaves through an end, R - r again.
    const Index sources[] = {node_near(g, {0, 0, 2 * h})};
    const PathTree out = widest_paths(g, sources);
    REQUIRE(std::abs(out.value[g.outside()] - (R - r)) < 1e-9);
  }
}

TEST_CASE("void paths: a closed cage with one window lets out a probe of the window's radius", "[void_graph]") {
  // 200 balls of radius 1.6 spread over a sphere of radius 6 (Fibonacci
  // points, neighbours ~1.5 apart: closed), but for a cap of half-angle 30
  // degrees replaced by a ring of 8 balls on its rim (circle radius 3):
  // the ring's balls are the nearest to its centre, the widest way out
  // from the centre of the cage passes there, 3 - 1.6 from them.
  const double S = 6, r = 1.6, cap = kPi / 6;
  Balls b;
  b.points = testing::cage_points(200, S, cap, 8);
  b.radii.assign(b.points.size(), r);
  const Built built(b);
  const VoidGraph& g = built.g;
  const Index sources[] = {node_near(g, {0, 0, 0})};
  const PathTree out = widest_paths(g, sources);
  REQUIRE(std::abs(out.value[g.outside()] - (S * std::sin(cap) - r)) < 1e-9);
  // The bottleneck edge's narrowest point is the window's centre.
  const std::vector<Index> path = path_edges(g, out, g.outside());
  const auto narrowest = *std::min_element(path.begin(), path.end(), [&](Index a, Index c) {
    return g.clearance(a) < g.clearance(c);
  });
  REQUIRE(norm(g.narrowest(narrowest) - Vec3{0, 0, S * std::cos(cap)}) < 1e-9);
}
