// SPDX-License-Identifier: Apache-2.0
#include "alpha/void_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "alpha/error.hpp"

namespace alpha {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool stops(const std::vector<bool>& stop, Index n) { return !stop.empty() && stop[n]; }

// Label-setting search: `better(a, b)` orders labels (the best is settled
// first), `extend(label, edge)` is the label through an edge (NaN: the
// edge cannot be used). Ties: the smaller node id first.
template <class Better, class Extend>
PathTree search(const VoidGraph& g, std::span<const Index> sources, const std::vector<bool>& stop, double source_value,
                Better better, Extend extend) {
  if (!stop.empty() && stop.size() != g.num_nodes()) throw Error("void paths: one stop flag per node needed", ErrorKind::Misuse);
  PathTree tree{std::vector<double>(g.num_nodes(), kNaN), std::vector<Index>(g.num_nodes(), kNone)};
  using Entry = std::pair<double, Index>;
  const auto after = [&](const Entry& a, const Entry& b) {  // priority_queue puts the "largest" on top
    if (a.first != b.first) return better(b.first, a.first);
    return a.second > b.second;
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(after)> queue(after);
  for (const Index s : sources) {
    if (!g.is_node(s)) throw Error("void paths: a source is not a node", ErrorKind::Misuse);
    tree.value[s] = source_value;
    queue.emplace(source_value, s);
  }
  std::vector<bool> settled(g.num_nodes(), false);
  while (!queue.empty()) {
    // Not a structured binding: clang 14 (the fuzz and sanitizer builds)
    // cannot capture one in the lambda below.
    const double value = queue.top().first;
    const Index n = queue.top().second;
    queue.pop();
    if (settled[n]) continue;
    settled[n] = true;
    if (stops(stop, n) && tree.via[n] != kNone) continue;  // a source is always left
    g.for_each_edge(n, [&](Index f, Index m) {
      if (settled[m]) return;
      const double v = extend(value, f);
      if (std::isnan(v)) return;
      if (std::isnan(tree.value[m]) || better(v, tree.value[m])) {
        tree.value[m] = v;
        tree.via[m] = f;
        queue.emplace(v, m);
      }
    });
  }
  return tree;
}

}  // namespace

double edge_length(const VoidGraph& g, Index f) {
  double length = 0;
  for (const Index n : g.ends(f))
    if (n != g.outside()) length += norm(g.position(n) - g.narrowest(f));
  return length;
}

PathTree widest_paths(const VoidGraph& g, std::span<const Index> sources, const std::vector<bool>& stop,
                      double min_clearance) {
  return search(
      g, sources, stop, std::numeric_limits<double>::infinity(), [](double a, double b) { return a > b; },
      [&](double width, Index f) { return g.clearance(f) >= min_clearance ? std::min(width, g.clearance(f)) : kNaN; });
}

PathTree cheapest_paths(const VoidGraph& g, std::span<const Index> sources, const PathCost& cost,
                        const std::vector<bool>& stop) {
  return search(
      g, sources, stop, 0.0, [](double a, double b) { return a < b; },
      [&](double total, Index f) {
        const double c = g.clearance(f);
        if (!(c >= cost.min_clearance) || !(c > 0)) return kNaN;
        const double step = edge_length(g, f) / std::pow(c, cost.exponent);
        return std::isfinite(step) ? total + step : kNaN;
      });
}

std::vector<Index> path_edges(const VoidGraph& g, const PathTree& tree, Index n) {
  std::vector<Index> edges;
  if (!tree.reached(n)) return edges;
  for (Index at = n; tree.via[at] != kNone; at = g.other_end(tree.via[at], at)) edges.push_back(tree.via[at]);
  std::reverse(edges.begin(), edges.end());
  return edges;
}

std::vector<Index> path_nodes(const VoidGraph& g, Index start, std::span<const Index> edges) {
  std::vector<Index> nodes{start};
  for (const Index f : edges) nodes.push_back(g.other_end(f, nodes.back()));
  return nodes;
}

std::vector<Vec3> path_points(const VoidGraph& g, Index start, std::span<const Index> edges) {
  std::vector<Vec3> points;
  Index at = start;
  if (at != g.outside()) points.push_back(g.position(at));
  for (const Index f : edges) {
    points.push_back(g.narrowest(f));
    at = g.other_end(f, at);
    if (at != g.outside()) points.push_back(g.position(at));
  }
  return points;
}

}  // namespace alpha
