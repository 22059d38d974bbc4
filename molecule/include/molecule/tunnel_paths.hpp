// SPDX-License-Identifier: Apache-2.0
// Tunnels and pores as tunnel programs (CAVER, MOLE, HOLE) report them:
// paths a probe can travel, with a centreline, a radius profile, a length,
// a bottleneck and the residues lining them; computed on the void graph of
// the atoms (alpha/void_graph.hpp: the power diagram of the probe-grown
// balls of the pocket search, with clearances to the van der Waals
// spheres). That diagram is the medial axis of the atoms (their additively
// weighted Voronoi diagram) exactly where the clearance equals the search
// probe (1.4 A by default: (t - p)(2 r_i + t + p) is the power of a point
// at clearance t from ball i grown by p, the same for every atom when t =
// p) and close to it elsewhere; with equal radii it is exactly the medial
// axis.
//
// - The BULK SOLVENT is the space beyond the convex hull, every node a
//   probe of TunnelOptions::shell_radius (3 A, CAVER's shell radius) can
//   reach from there, and every node within TunnelOptions::shell_depth (4
//   A, CAVER's shell depth) of those along ways the tunnel probe passes
//   (so shallow grooves of the surface are solvent, not tunnels); paths
//   end where they enter it (their MOUTH: the narrowest point of the edge
//   into it). A node's DEPTH is the length of that shortest way.
// - A TUNNEL runs from a start to the solvent. From each start: first the
//   widest path (the largest bottleneck, exactly; among the paths of that
//   bottleneck the cheapest), then the cheapest path to each other mouth
//   by increasing cost, cost = sum over edges of length / clearance^2
//   (TunnelOptions::cost_exponent; CAVER's cost likewise weights length by
//   an inverse power of the radius), each kept unless it shares more than
//   TunnelOptions::similarity of the shorter one's length with a tunnel
//   already kept (it is merged into that one), up to
//   TunnelOptions::max_per_start.
// - A PORE crosses the molecule from solvent to solvent: within one
//   connected set of non-solvent nodes (joined by edges the probe passes)
//   its mouths are grouped into openings (mouths within
//   TunnelOptions::opening_gap of each other), and each pair of openings
//   at least TunnelOptions::pore_span apart gives the widest path between
//   them (the cheapest of that bottleneck); pores are merged as tunnels.
// - A CYCLE of the union of balls (Cavities::tunnels: a ring of atoms with
//   a hole through it, no start of its own) is crossed through its killing
//   triangle: from each of the triangle's two nodes the widest way to the
//   solvent that does not cross it back (the cheapest of that bottleneck),
//   joined there, from mouth to mouth; a ring with the solvent on both
//   sides is crossed from node to node.
//
// Every edge used has clearance >= TunnelOptions::probe. The centreline is
// the chain of power-diagram edges a path runs along, sampled every
// TunnelOptions::step A; the radius at a sample is its exact distance to
// the nearest atom's van der Waals sphere (alpha::NearestBall). The
// bottleneck is the narrowest of the path's edges' narrowest points (the
// minimum of the clearance along each power-diagram edge, see
// void_graph.hpp) by the same exact radius, and is a profile point.
#pragma once
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/geometry.hpp"
#include "molecule/cavities.hpp"
#include "molecule/structure.hpp"

namespace molecule {

struct TunnelOptions {
  double probe = 0.9;          // A, the narrowest probe a path must let through (CAVER's default)
  double shell_radius = 3;     // A, the probe that defines the bulk solvent (CAVER's shell radius)
  double shell_depth = 4;      // A, how far below the shell probe's reach the solvent extends (CAVER's shell depth)
  double cost_exponent = 2;    // cost = length / clearance^cost_exponent per edge
  double similarity = 0.7;     // share of the shorter path's length above which two paths are one
  std::size_t max_per_start = 5;
  bool pores = false;
  double pore_span = 15;       // A, smallest distance between a pore's two openings
  double opening_gap = 6;      // A, mouths nearer than this are one opening
  std::size_t max_pores = 10;
  double step = 0.5;           // A, centreline sampling
  double contact = 3;          // A, lining: atoms within this of the probe's surface (CAVER's contact distance)
};

// Where tunnels start: candidate cells (a site's empty tetrahedra: the
// deepest one, farthest from the solvent along probe-passable edges, is
// taken) or a point (the nearest node the probe fits in is taken).
struct TunnelStart {
  std::string label;                // "site 1", "A:45,A:67", "1.0,2.0,3.0"
  std::vector<alpha::Index> cells;  // triangulation cell ids; empty: use point
  alpha::Vec3 point{};
};

struct ProfilePoint {
  double distance = 0;  // along the centreline from its start, A
  alpha::Vec3 x;
  double radius = 0;    // distance to the nearest atom's van der Waals sphere, A
};

struct TunnelPath {
  bool pore = false;             // false: a tunnel from a start; true: a pore or the way through a cycle
  std::size_t start = 0;         // index of its TunnelStart (tunnels)
  std::vector<alpha::Vec3> centreline;     // the power-diagram edges' chain: nodes and edges' narrowest points
  std::vector<ProfilePoint> profile;
  double length = 0;             // of the centreline, A
  double bottleneck_radius = 0;  // smallest radius along it, A
  alpha::Vec3 bottleneck{};      // where
  double curvature = 1;          // length / distance between its ends
  double cost = 0;               // sum of length / clearance^exponent over its edges
  alpha::Vec3 start_point{}, mouth{};  // ends of the centreline (a pore: its two mouths)
  std::vector<alpha::Index> lining_atoms;  // sorted atom indices
  std::vector<alpha::Index> triangles;     // the void-graph edges (Simplices triangle ids) it crosses, in order
};

struct TunnelNetwork {
  std::vector<TunnelPath> paths;   // tunnels of each start in order, then the pores by decreasing bottleneck
  std::vector<TunnelPath> cycles;  // per cycle given, the way through it (no profile: the probe finds none)
};

// `radii` are the atoms' van der Waals radii (the complex is of the balls
// r_i + p); `cycles` the complex's (find_cavities). Throws alpha::Error on
// inconsistent input.
TunnelNetwork find_tunnels(const alpha::AlphaComplex& ac, const std::vector<double>& radii,
                           const std::vector<TunnelStart>& starts, const std::vector<Tunnel>& cycles,
                           const TunnelOptions& options);

// find_tunnels' paths alone.
std::vector<TunnelPath> find_tunnel_paths(const alpha::AlphaComplex& ac, const std::vector<double>& radii,
                                          const std::vector<TunnelStart>& starts, const TunnelOptions& options);

}  // namespace molecule
