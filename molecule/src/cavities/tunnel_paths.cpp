// SPDX-License-Identifier: Apache-2.0
#include "molecule/tunnel_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

#include "alpha/error.hpp"
#include "alpha/nearest_ball.hpp"
#include "alpha/point_grid.hpp"
#include "alpha/void_graph.hpp"
#include "alpha/void_paths.hpp"

namespace molecule {
namespace {

using alpha::Index;
using alpha::kNone;
using alpha::Vec3;

constexpr double kInf = std::numeric_limits<double>::infinity();

// A path on the void graph: from node `start` along `edges`.
struct GraphPath {
  Index start = kNone;
  std::vector<Index> edges;
  double cost = 0;
};

class TunnelSearch {
public:
  TunnelSearch(const alpha::AlphaComplex& ac, const std::vector<double>& radii, const TunnelOptions& options)
      : g_(ac, radii), nearest_(ac.triangulation().points(), radii, options.probe), radii_(radii), opt_(options) {
    // The bulk solvent: outside, what a shell-radius probe reaches from
    // there, and what lies within shell_depth of that along ways the probe
    // passes (the depth of a node: the length of the shortest such way).
    const Index outside[] = {g_.outside()};
    const alpha::PathTree from_outside = alpha::widest_paths(g_, outside, {}, opt_.shell_radius);
    std::vector<Index> shell;
    for (Index n = 0; n < g_.num_nodes(); ++n)
      if (g_.is_node(n) && from_outside.reached(n)) shell.push_back(n);
    depth_ = alpha::cheapest_paths(g_, shell, {opt_.probe, 0}).value;
    solvent_.assign(g_.num_nodes(), false);
    for (Index n = 0; n < g_.num_nodes(); ++n) solvent_[n] = g_.is_node(n) && depth_[n] <= opt_.shell_depth;
  }

  // The node tunnels from `start` begin at, or kNone.
  Index start_node(const TunnelStart& start) const {
    Index best = kNone;
    double best_key = -kInf;
    const auto consider = [&](Index n, double key) {
      if (!g_.is_node(n) || n == g_.outside() || solvent_[n] || std::isnan(depth_[n]) ||
          !(g_.node_clearance(n) >= opt_.probe))
        return;
      if (key > best_key) best_key = key, best = n;
    };
    if (!start.cells.empty()) {
      for (const Index c : start.cells) consider(c, depth_[c]);
    } else {
      for (Index n = 0; n < g_.num_nodes(); ++n)
        if (g_.is_node(n) && n != g_.outside()) consider(n, -norm(g_.position(n) - start.point));
    }
    return best;
  }

  // The tunnels from node s: the widest, then the cheapest to other mouths.
  std::vector<GraphPath> tunnels(Index s) const {
    const Index sources[] = {s};
    const alpha::PathTree widest = alpha::widest_paths(g_, sources, solvent_, opt_.probe);
    double width = -kInf;
    for (Index n = 0; n < g_.num_nodes(); ++n)
      if (solvent_[n] && widest.reached(n)) width = std::max(width, widest.value[n]);
    std::vector<GraphPath> out;
    if (!(width >= opt_.probe)) return out;
    out.push_back(cheapest_to_solvent(sources, alpha::cheapest_paths(g_, sources, cost(width), solvent_)).front());
    const alpha::PathTree tree = alpha::cheapest_paths(g_, sources, cost(opt_.probe), solvent_);
    for (const GraphPath& p : cheapest_to_solvent(sources, tree)) {
      if (out.size() >= opt_.max_per_start) break;
      if (distinct(p, out)) out.push_back(p);
    }
    return out;
  }

  // Pores: per pair of openings far enough apart, the widest path between
  // them (the cheapest of that width), by decreasing width, merged.
  std::vector<GraphPath> pores() {
    const std::vector<std::vector<Index>> openings = find_openings();
    struct Pair {
      double width;
      std::size_t a, b;
    };
    std::vector<alpha::PointGrid> grids;
    for (const std::vector<Index>& o : openings) {
      alpha::PointGrid& grid = grids.emplace_back(opt_.pore_span);
      for (std::size_t j = 0; j < o.size(); ++j) grid.add(g_.narrowest(o[j]), Index(j));
      grid.finish();
    }
    std::vector<Pair> pairs;
    for (std::size_t a = 0; a < openings.size(); ++a) {
      std::vector<std::size_t> partners;
      for (std::size_t b = a + 1; b < openings.size(); ++b)
        if (same_set(openings[a], openings[b]) && apart(openings[a], grids[b], openings[b])) partners.push_back(b);
      if (partners.empty()) continue;
      const std::vector<Index> from = opening_solvent(openings[a]);
      const alpha::PathTree widest = alpha::widest_paths(g_, from, solvent_, opt_.probe);
      for (const std::size_t b : partners) {
        double width = -kInf;
        for (const Index f : openings[b]) {
          const Index u = interior_end(f);
          if (widest.reached(u)) width = std::max(width, std::min(widest.value[u], g_.clearance(f)));
        }
        if (width >= opt_.probe) pairs.push_back({width, a, b});
      }
    }
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.width > y.width; });
    std::vector<GraphPath> out;
    for (const Pair& p : pairs) {
      if (out.size() >= opt_.max_pores) break;
      const std::vector<Index> from = opening_solvent(openings[p.a]);
      const alpha::PathTree tree = alpha::cheapest_paths(g_, from, cost(p.width), solvent_);
      GraphPath best;
      best.cost = kInf;
      for (const Index f : openings[p.b]) {
        const Index u = interior_end(f);
        if (!tree.reached(u) || !(g_.clearance(f) >= p.width)) continue;
        const double c = tree.value[u] + alpha::edge_length(g_, f) / std::pow(g_.clearance(f), opt_.cost_exponent);
        if (c < best.cost) {
          best.edges = alpha::path_edges(g_, tree, u);
          best.edges.push_back(f);
          best.cost = c;
        }
      }
      if (best.edges.size() < 3) continue;  // at least one interior node between the mouths
      best.start = g_.other_end(best.edges.front(), interior_end(best.edges.front()));
      if (distinct(best, out)) out.push_back(best);
    }
    return out;
  }

  // The way through a cycle's killing triangle f (an edge), or nothing
  // when the probe does not pass it.
  std::optional<GraphPath> through(Index f) const {
    if (f == kNone || f >= g_.num_edges() || !(g_.clearance(f) >= opt_.probe)) return std::nullopt;
    const auto ends = g_.ends(f);
    GraphPath out;
    out.start = ends[0];
    out.cost = alpha::edge_length(g_, f) / std::pow(g_.clearance(f), opt_.cost_exponent);
    std::vector<Index> after;  // from ends[1] to its mouth
    for (const int side : {0, 1}) {
      if (solvent_[ends[side]]) continue;
      // The search stops at the other end (reached through f, never left).
      std::vector<bool> stop = solvent_;
      stop[ends[1 - side]] = true;
      const Index sources[] = {ends[side]};
      const alpha::PathTree widest = alpha::widest_paths(g_, sources, stop, opt_.probe);
      double width = -kInf;
      for (Index n = 0; n < g_.num_nodes(); ++n)
        if (solvent_[n] && widest.reached(n)) width = std::max(width, widest.value[n]);
      if (!(width >= opt_.probe)) return std::nullopt;
      const GraphPath way = cheapest_to_solvent(sources, alpha::cheapest_paths(g_, sources, cost(width), stop)).front();
      out.cost += way.cost;
      if (side == 1) {
        after = way.edges;
      } else {  // travelled from its mouth
        out.edges.assign(way.edges.rbegin(), way.edges.rend());
        out.start = alpha::path_nodes(g_, ends[0], way.edges).back();
      }
    }
    out.edges.push_back(f);
    out.edges.insert(out.edges.end(), after.begin(), after.end());
    return out;
  }

  TunnelPath measure(const GraphPath& p, bool pore) const {
    // The centreline: node, narrowest point, node, ...; solvent nodes at
    // the ends are left out (a path ends at its mouths).
    std::vector<Vec3> line;
    Index at = p.start;
    if (!pore) line.push_back(g_.position(at));
    for (std::size_t k = 0; k < p.edges.size(); ++k) {
      line.push_back(g_.narrowest(p.edges[k]));
      at = g_.other_end(p.edges[k], at);
      if (k + 1 < p.edges.size()) line.push_back(g_.position(at));
    }
    return measure(p, pore, std::move(line));
  }

  // The way through a cycle: from mouth to mouth, or, a single edge (the
  // solvent on both sides), from node to node (outside() has no position).
  TunnelPath measure_cycle(const GraphPath& p) const {
    if (p.edges.size() > 1) return measure(p, true);
    return measure(p, true, alpha::path_points(g_, p.start, p.edges));
  }

  TunnelPath measure(const GraphPath& p, bool pore, std::vector<Vec3> line) const {
    TunnelPath out;
    out.pore = pore;
    out.cost = p.cost;
    out.triangles = p.edges;
    // The bottleneck: the narrowest of the edges' narrowest points.
    double bottleneck = kInf, where_at = 0;
    Vec3 where{};
    for (const Index f : p.edges) {
      const double r = nearest_.distance(g_.narrowest(f));
      if (r < bottleneck) bottleneck = r, where = g_.narrowest(f);
    }
    // Samples every step along the line and at its end, and the
    // bottleneck (a vertex of the line) among them.
    std::vector<double> at_length{0};
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      at_length.push_back(at_length.back() + norm(line[k + 1] - line[k]));
      if (line[k + 1] == where) where_at = at_length.back();
    }
    out.length = at_length.back();
    std::vector<double> samples{where_at, out.length};
    for (double d = 0; d < out.length; d += opt_.step) samples.push_back(d);
    std::sort(samples.begin(), samples.end());
    std::size_t k = 0;
    for (const double d : samples) {
      if (!out.profile.empty() && d - out.profile.back().distance < 1e-9) continue;
      while (k + 2 < line.size() && at_length[k + 1] < d) ++k;
      const double len = at_length[k + 1] - at_length[k];
      const Vec3 x = d == where_at ? where : len > 0 ? line[k] + ((d - at_length[k]) / len) * (line[k + 1] - line[k]) : line[k];
      out.profile.push_back({d, x, nearest_.distance(x)});
    }
    out.bottleneck_radius = bottleneck;
    out.bottleneck = where;
    for (const ProfilePoint& q : out.profile)
      if (q.radius < out.bottleneck_radius) out.bottleneck_radius = q.radius, out.bottleneck = q.x;
    out.centreline = line;
    out.start_point = line.front();
    out.mouth = line.back();
    const double straight = norm(out.mouth - out.start_point);
    out.curvature = straight > 0 ? out.length / straight : kInf;
    for (const ProfilePoint& q : out.profile)
      nearest_.visit_near(q.x, q.radius + opt_.contact, [&](Index i) {
        if (norm(q.x - g_.triangulation().point(i)) - radii_[i] <= q.radius + opt_.contact) out.lining_atoms.push_back(i);
      });
    std::sort(out.lining_atoms.begin(), out.lining_atoms.end());
    out.lining_atoms.erase(std::unique(out.lining_atoms.begin(), out.lining_atoms.end()), out.lining_atoms.end());
    return out;
  }

private:
  alpha::VoidGraph g_;
  alpha::NearestBall nearest_;
  const std::vector<double>& radii_;
  const TunnelOptions& opt_;
  std::vector<bool> solvent_;
  std::vector<double> depth_;
  std::vector<Index> set_;  // per non-solvent node: its connected set (find_openings)

  alpha::PathCost cost(double min_clearance) const { return {min_clearance, opt_.cost_exponent}; }

  // Paths from the sources to each solvent node reached, by increasing cost.
  std::vector<GraphPath> cheapest_to_solvent(std::span<const Index> sources, const alpha::PathTree& tree) const {
    std::vector<Index> ends;
    for (Index n = 0; n < g_.num_nodes(); ++n)
      if (solvent_[n] && tree.reached(n) && tree.via[n] != kNone) ends.push_back(n);
    std::stable_sort(ends.begin(), ends.end(), [&](Index a, Index b) { return tree.value[a] < tree.value[b]; });
    std::vector<GraphPath> out;
    for (const Index n : ends) out.push_back({sources.front(), alpha::path_edges(g_, tree, n), tree.value[n]});
    return out;
  }

  double length_of(std::span<const Index> edges) const {
    double l = 0;
    for (const Index f : edges) l += alpha::edge_length(g_, f);
    return l;
  }

  // Whether p shares at most `similarity` of the shorter one's length with every kept path.
  bool distinct(const GraphPath& p, const std::vector<GraphPath>& kept) const {
    std::vector<Index> mine = p.edges;
    std::sort(mine.begin(), mine.end());
    const double length = length_of(p.edges);
    for (const GraphPath& k : kept) {
      std::vector<Index> theirs = k.edges, shared;
      std::sort(theirs.begin(), theirs.end());
      std::set_intersection(mine.begin(), mine.end(), theirs.begin(), theirs.end(), std::back_inserter(shared));
      const double shorter = std::min(length, length_of(k.edges));
      if (length_of(shared) > opt_.similarity * shorter) return false;
    }
    return true;
  }

  Index interior_end(Index f) const {
    const auto e = g_.ends(f);
    return solvent_[e[0]] ? e[1] : e[0];
  }
  Index solvent_end(Index f) const { return g_.other_end(f, interior_end(f)); }

  // Mouths (edges from a non-solvent node into the solvent that the probe
  // passes), grouped into openings: single linkage of their narrowest
  // points within opening_gap, among mouths of one connected set of
  // non-solvent nodes.
  std::vector<std::vector<Index>> find_openings() {
    // Connected sets of non-solvent nodes through probe-passable edges.
    std::vector<Index>& set = set_;
    set.assign(g_.num_nodes(), kNone);
    std::vector<Index> mouths;
    Index sets = 0;
    for (Index n = 0; n < g_.num_nodes(); ++n) {
      if (!g_.is_node(n) || solvent_[n] || set[n] != kNone) continue;
      std::vector<Index> stack{n};
      set[n] = sets;
      while (!stack.empty()) {
        const Index m = stack.back();
        stack.pop_back();
        g_.for_each_edge(m, [&](Index f, Index o) {
          if (!(g_.clearance(f) >= opt_.probe)) return;
          if (solvent_[o]) {
            mouths.push_back(f);
          } else if (set[o] == kNone) {
            set[o] = sets;
            stack.push_back(o);
          }
        });
      }
      ++sets;
    }
    // Single linkage within each set: union-find over the pairs of mouths
    // within opening_gap, found through a grid of that spacing.
    std::vector<std::size_t> parent(mouths.size());
    for (std::size_t i = 0; i < mouths.size(); ++i) parent[i] = i;
    const auto root = [&](std::size_t x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    alpha::PointGrid grid(opt_.opening_gap);
    for (std::size_t i = 0; i < mouths.size(); ++i) grid.add(g_.narrowest(mouths[i]), Index(i));
    grid.finish();
    for (std::size_t i = 0; i < mouths.size(); ++i) {
      const Vec3& x = g_.narrowest(mouths[i]);
      grid.visit(x, opt_.opening_gap, [&](Index j) {
        if (set[interior_end(mouths[j])] == set[interior_end(mouths[i])] &&
            norm(g_.narrowest(mouths[j]) - x) <= opt_.opening_gap)
          parent[root(i)] = root(j);
      });
    }
    std::vector<std::size_t> order(mouths.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::vector<std::vector<Index>> openings;
    std::vector<std::size_t> opening_of(mouths.size(), kNone);
    for (const std::size_t i : order) {
      std::size_t& o = opening_of[root(i)];
      if (o == kNone) o = openings.size(), openings.emplace_back();
      openings[o].push_back(mouths[i]);
    }
    return openings;
  }

  bool same_set(const std::vector<Index>& a, const std::vector<Index>& b) const {
    return set_[interior_end(a.front())] == set_[interior_end(b.front())];
  }

  // The solvent nodes of an opening's mouths, the sources of a pore search.
  std::vector<Index> opening_solvent(const std::vector<Index>& opening) const {
    std::vector<Index> nodes;
    for (const Index f : opening) nodes.push_back(solvent_end(f));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }

  // Whether every mouth of a is at least pore_span from every mouth of b.
  bool apart(const std::vector<Index>& a, const alpha::PointGrid& b_grid, const std::vector<Index>& b) const {
    for (const Index f : a) {
      bool close = false;
      b_grid.visit(g_.narrowest(f), opt_.pore_span, [&](Index j) {
        close = close || norm(g_.narrowest(f) - g_.narrowest(b[j])) < opt_.pore_span;
      });
      if (close) return false;
    }
    return true;
  }
};

}  // namespace

TunnelNetwork find_tunnels(const alpha::AlphaComplex& ac, const std::vector<double>& radii,
                           const std::vector<TunnelStart>& starts, const std::vector<Tunnel>& cycles,
                           const TunnelOptions& options) {
  if (radii.size() != ac.triangulation().num_points()) throw alpha::Error("tunnels: one radius per atom needed", alpha::ErrorKind::Misuse);
  if (!(options.probe > 0) || !(options.step > 0)) throw alpha::Error("tunnels: the probe and the step must be positive", alpha::ErrorKind::Misuse);
  TunnelSearch search(ac, radii, options);
  TunnelNetwork out;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Index s = search.start_node(starts[i]);
    if (s == kNone) continue;
    for (const GraphPath& p : search.tunnels(s)) {
      out.paths.push_back(search.measure(p, false));
      out.paths.back().start = i;
    }
  }
  if (options.pores)
    for (const GraphPath& p : search.pores()) out.paths.push_back(search.measure(p, true));
  for (const Tunnel& c : cycles) {
    const std::optional<GraphPath> p = search.through(c.bottleneck_triangle);
    out.cycles.push_back(p ? search.measure_cycle(*p) : TunnelPath{});
  }
  return out;
}

std::vector<TunnelPath> find_tunnel_paths(const alpha::AlphaComplex& ac, const std::vector<double>& radii,
                                          const std::vector<TunnelStart>& starts, const TunnelOptions& options) {
  return find_tunnels(ac, radii, starts, {}, options).paths;
}

}  // namespace molecule
