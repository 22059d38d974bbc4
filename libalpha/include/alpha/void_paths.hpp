// SPDX-License-Identifier: Apache-2.0
// Paths on the void graph (alpha/void_graph.hpp): the widest paths (the
// largest probe that can travel from a source to each node) and the
// cheapest paths under a cost that favours short and wide ways (as tunnel
// programs such as CAVER rank tunnels).
//
// Both are label-setting searches (Dijkstra) from a set of sources, exact
// on the graph's clearances: a path's WIDTH is the smallest clearance of
// its edges (its bottleneck; the nodes need no term of their own, as the
// two edges a path uses at a node already see all four of its balls);
// widest_paths gives every node the largest width over all paths from the
// sources (the maximin, or bottleneck, path problem: Dijkstra with min in
// place of + and the largest label first is exact for it). Ties are
// broken by node id, so results are deterministic.
//
// A path's geometry is the chain of power-diagram edges it runs along:
// from a node's position through an edge's narrowest point to the next
// node's position (path_points). A path ends at outside() through a hull
// edge's narrowest point (outside() has no position).
//
// Nodes flagged in `stop` are reached but never left (unless they are
// sources): a search from a site to the solvent stops at the solvent's
// boundary, one from the solvent enters the molecule but does not return.
#pragma once
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "alpha/void_graph.hpp"

namespace alpha {

struct PathTree {
  std::vector<double> value;  // per node: width (widest) or cost (cheapest); NaN: not reached
  std::vector<Index> via;     // per node: the edge it is reached through; kNone for sources and unreached nodes
  bool reached(Index n) const { return !std::isnan(value[n]); }
};

// Cost of travelling edge f (from a node to its other end): the length of
// the edge's polyline (node - narrowest point - node; up to the narrowest
// point when an end is outside()) divided by clearance^exponent. Edges
// whose clearance is below min_clearance cannot be travelled.
struct PathCost {
  double min_clearance = 0;
  double exponent = 2;
};

// The edge's polyline length as used by PathCost.
double edge_length(const VoidGraph& g, Index f);

// Widest paths from the sources (their width is +inf). `stop` may be empty
// (no stops) or have one flag per node. Edges narrower than min_clearance
// are not travelled (nodes only reached through them stay unreached):
// the same widths where they reach it, for less work.
PathTree widest_paths(const VoidGraph& g, std::span<const Index> sources, const std::vector<bool>& stop = {},
                      double min_clearance = -std::numeric_limits<double>::infinity());

// Cheapest paths from the sources (cost 0) under `cost`.
PathTree cheapest_paths(const VoidGraph& g, std::span<const Index> sources, const PathCost& cost,
                        const std::vector<bool>& stop = {});

// The edges of the tree path from its source to node n, in order (empty
// for a source or an unreached node).
std::vector<Index> path_edges(const VoidGraph& g, const PathTree& tree, Index n);

// The nodes a path of edges runs through, from `start` (one more than edges).
std::vector<Index> path_nodes(const VoidGraph& g, Index start, std::span<const Index> edges);

// The polyline of a path from node `start` along `edges`: start's position,
// then per edge its narrowest point and the next node's position (none for
// outside()).
std::vector<Vec3> path_points(const VoidGraph& g, Index start, std::span<const Index> edges);

}  // namespace alpha
