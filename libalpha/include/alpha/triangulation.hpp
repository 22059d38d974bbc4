// SPDX-License-Identifier: Apache-2.0
// Regular (weighted Delaunay) triangulation of points in 3D; the Delaunay
// triangulation is the special case of no weights.
//
// Built incrementally in a BRIO/Hilbert order: locate by a visibility walk,
// remove the cells in conflict with the new point and join the point to the
// boundary of that cavity. All decisions go through the exact, perturbed
// predicates of Kernel, so any input (grids, cospherical or coplanar subsets,
// duplicates) gives a valid triangulation, the same on every run.
//
// Storage is flat: each cell holds 4 vertex and 4 neighbour indices; the
// neighbour k lies across the facet opposite vertex k. A vertex id is the
// index of its input point. Hull facets are joined to the vertex kInfinite,
// so every cell has exactly 4 neighbours. Cells are positively oriented:
// orient3d(v0,v1,v2,v3) > 0, with kInfinite read as a point beyond the hull.
#pragma once
#include <array>
#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

#include "alpha/geometry.hpp"
#include "alpha/predicates.hpp"
#include "alpha/uninitialized_allocator.hpp"

namespace alpha {

enum class PointStatus : std::uint8_t {
  vertex,     // a vertex of the triangulation
  duplicate,  // same coordinates as another input point (see representative)
  hidden,     // a weighted point whose ball is redundant: no cell uses it
};

// For a cell with vertices v0..v3, kFacet[i] lists the local indices of the
// facet opposite vertex i in an order that sees vertex i on its positive side.
inline constexpr std::array<std::array<int, 3>, 4> kFacet{{{2, 1, 3}, {0, 2, 3}, {1, 0, 3}, {0, 1, 2}}};

struct Cell {
  std::array<Index, 4> v;  // vertices
  std::array<Index, 4> n;  // neighbours, n[k] opposite v[k]
};

// The dimension of the points' affine hull: -1 for none, 0 (all equal), 1
// (on a line), 2 (on a plane) or 3, when they have a triangulation. Exact.
int affine_dimension(const std::vector<Vec3>& points);

// What a dynamic update did.
struct UpdateReport {
  bool rebuilt = false;         // built afresh (duplicates involved, or the repair could not be local)
  bool foretold = false;        // rebuilt at once: a sample of the cells to check failed too often to mend
  std::size_t relocated = 0;    // vertices taken out and inserted again at their new place
  std::size_t reinserted = 0;   // points inserted, the relocated ones included (hidden ones rechecked too)
  std::size_t returned = 0;     // vertices sent back (a cell of theirs failed) that reached their new place by flips
  std::size_t flips23 = 0;      // 2-3 flips: two cells around a facet became three around an edge
  std::size_t flips32 = 0;      // 3-2 flips: the reverse
  std::size_t flips41 = 0;      // 4-1 flips: a weighted vertex of four cells became redundant (hidden)
};

class Triangulation {
public:
  // Throws alpha::Error for unusable input: non-finite or out-of-range
  // values (|coordinate| > 1e15, |weight| > 1e30, points spanning less
  // than 1e-100), weights not matching points, fewer than 4 distinct
  // points, all points collinear or coplanar. Duplicates are merged: the
  // point with the largest weight (then the smallest index) represents the
  // others.
  //
  // With threads > 1 (at most 254 are used) and at least 2^15 distinct
  // points, the construction runs on that many threads. It gives the same
  // cells as the sequential one, numbered canonically (each cell's vertices
  // in insertion order, the cells by their last vertex in that order, then
  // by their vertex lists) instead of in the order the sequential
  // insertions happened to leave them: the same numbers for any thread
  // count above 1 and on every run.
  explicit Triangulation(std::vector<Vec3> points, std::vector<double> weights = {}, unsigned threads = 1);

  // Input points.
  std::size_t num_points() const { return points_.size(); }
  std::span<const Vec3> points() const { return points_; }
  const Vec3& point(Index i) const { return points_[i]; }
  bool weighted() const { return !weights_.empty(); }
  std::span<const double> weights() const { return weights_; }
  double weight(Index i) const { return weights_.empty() ? 0.0 : weights_[i]; }
  PointStatus status(Index i) const { return status_[i]; }
  // For a duplicate, the point that represents it; otherwise the point itself.
  Index representative(Index i) const { return representative_[i]; }
  std::size_t num_vertices() const { return num_vertices_; }  // finite ones
  std::size_t num_duplicates() const { return num_duplicates_; }
  std::size_t num_hidden() const { return num_hidden_; }

  // Cells, finite and infinite.
  std::size_t num_cells() const { return cells_.size(); }
  std::size_t num_finite_cells() const { return num_finite_cells_; }
  const Cell& cell(Index c) const {
    assert(c < cells_.size());
    return cells_[c];
  }
  std::span<const Cell> cells() const { return cells_; }
  bool is_infinite(Index c) const { return infinite_position(c) >= 0; }
  // Position of kInfinite in cell c, or -1 for a finite cell.
  int infinite_position(Index c) const { return index_of(c, kInfinite); }
  // Local index of vertex v in cell c, or -1.
  int index_of(Index c, Index v) const {
    const auto& cv = cell(c).v;
    return cv[0] == v ? 0 : cv[1] == v ? 1 : cv[2] == v ? 2 : cv[3] == v ? 3 : -1;
  }
  // The local index of c in cell(c).n[k], i.e. the facet seen from the other side.
  int mirror_index(Index c, int k) const { return index_of_neighbor(cells_[c].n[k], c); }
  // One cell incident to vertex v (v a vertex), kNone otherwise.
  Index incident_cell(Index v) const { return vertex_cell_[v]; }

  // How often each predicate stage decided during construction.
  const PredicateStats& predicate_stats() const { return stats_; }
  // A kernel on the same points, for callers that need exact predicates.
  Kernel kernel() const { return Kernel(points_.data(), weights_.empty() ? nullptr : weights_.data()); }
  // Heap bytes held by this object.
  std::size_t memory_bytes() const;

  // Dynamic update (dynamic_update.cpp): each call leaves the regular
  // triangulation of the points as they then are, the same cells as a fresh
  // build of points() and weights() (numbered differently), repaired in
  // place where the points changed; see docs/dynamic_update.md.
  //
  // Point ids[k] moves to to[k] (with weight weights[k]: given exactly when
  // the triangulation is weighted). Throws alpha::Error as the constructor
  // does (bad values, coplanar result), leaving the triangulation as it was.
  UpdateReport move_points(std::span<const Index> ids, std::span<const Vec3> to, std::span<const double> weights = {});
  // Every point moves: to[i] is point i's new position.
  UpdateReport move_points(std::span<const Vec3> to, std::span<const double> weights = {});
  // New points get the ids num_points(), num_points() + 1, ...
  UpdateReport insert_points(std::span<const Vec3> points, std::span<const double> weights = {});
  // The points ids leave; the others keep their order, ids closing the gaps.
  UpdateReport remove_points(std::span<const Index> ids);

private:
  class Builder;
  class Updater;
  std::vector<Vec3> points_;
  std::vector<double> weights_;
  std::vector<PointStatus> status_;
  std::vector<Index> representative_;
  // Written before read: growing it (or sizing it for the threads) zeroes nothing.
  std::vector<Cell, UninitializedAllocator<Cell>> cells_;
  std::vector<Index> vertex_cell_;
  std::size_t num_vertices_ = 0, num_duplicates_ = 0, num_hidden_ = 0, num_finite_cells_ = 0;
  PredicateStats stats_;

  // Inserts points (each with status vertex, its coordinates in points_)
  // into the cells, whose unused ids are `free_cells`, walking from the
  // live cell `hint`; then compacts the cells and redoes the counts.
  void insert_into(std::span<const Index> order, std::vector<Index> free_cells, Index hint);

  int index_of_neighbor(Index c, Index n) const {
    const auto& cn = cell(c).n;
    return cn[0] == n ? 0 : cn[1] == n ? 1 : cn[2] == n ? 2 : cn[3] == n ? 3 : -1;
  }
};

}  // namespace alpha
