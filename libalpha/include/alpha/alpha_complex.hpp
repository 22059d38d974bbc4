// SPDX-License-Identifier: Apache-2.0
// The family of alpha complexes of a (weighted) point set (Edelsbrunner &
// Muecke 1994; weighted: Edelsbrunner 1992), computed once for all alpha.
//
// Every finite simplex of the regular triangulation gets an interval record:
// the rank at which it enters the complex, and the ranks mu_low / mu_high at
// which it stops being singular / becomes interior. Ranks index the alpha
// spectrum: the sorted distinct critical values (squared radii of smallest
// orthogonal spheres, compared exactly), so every later query is integer
// work. A simplex whose value equals alpha is present (CGAL's convention).
//
// Values are squared radii ("alpha_sq"); with weights they can be negative.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "alpha/persistence.hpp"
#include "alpha/simplices.hpp"
#include "alpha/sizes.hpp"
#include "alpha/triangulation.hpp"

namespace alpha {

enum class Classification : std::uint8_t { exterior, singular, regular, interior };
const char* to_string(Classification c);

// Interval record of one simplex, in spectrum ranks. kNever: never happens
// (mu_high of a hull simplex; everything of an infinite cell).
struct Interval {
  Index entry = kNever;
  Index mu_low = kNever;
  Index mu_high = kNever;
  bool attached = false;
};

// Classification counts at one alpha: [dimension][Classification].
using ClassCounts = std::array<std::array<std::size_t, 4>, 4>;

// The alpha shape boundary at one alpha: regular triangles oriented outward
// (their normal (b-a)x(c-a) points out of the shape), and the singular
// simplices kept apart.
struct ShapeBoundary {
  std::vector<std::array<Index, 3>> triangles;          // regular, outward
  std::vector<std::array<Index, 3>> singular_triangles;
  std::vector<std::array<Index, 2>> singular_edges;
  std::vector<Index> singular_vertices;
};

class AlphaComplex {
public:
  // The size and attachment tests run on `threads` threads; the complex is
  // the same for any number. At most kMaxThreads (each keeps a copy of the
  // attached flags), and only from kThreadsFrom vertices on (below, starting
  // them costs about what they save).
  static constexpr unsigned kMaxThreads = 64;
  static constexpr std::size_t kThreadsFrom = std::size_t(1) << 15;
  explicit AlphaComplex(const Triangulation& t, unsigned threads = 1);

  const Triangulation& triangulation() const { return *t_; }
  const Simplices& simplices() const { return simplices_; }

  // The alpha spectrum: critical values in increasing order.
  std::size_t spectrum_size() const { return spectrum_.size(); }
  double spectrum_value(Index rank) const;  // nearest double to the exact value
  // spectrum_value of each rank, into values (as long as ranks). For many
  // ranks at random places (a persistence diagram's): their simplices and
  // points are read a block at a time, with the reads of later ranks under
  // way while earlier ones are used.
  void spectrum_values(std::span<const Index> ranks, std::span<double> values) const;
  // Number of critical values <= alpha_sq (exact): simplices whose entry
  // rank is below this level are present at alpha_sq. Throws alpha::Error
  // for NaN.
  Index level(double alpha_sq) const;
  // Exact sizes and orthocentres of simplices of this complex's points.
  SizeKernel size_kernel() const;

  // Interval records, returned by value: they are stored by field.
  Interval vertex_interval(Index v) const {
    return {ranks_.vertex[v], vertex_bounds_[v].low, vertex_bounds_[v].high, vertex_attached_[v]};
  }
  Interval edge_interval(Index e) const {
    return {ranks_.edge[e], edge_bounds_[e].low, edge_bounds_[e].high, edge_attached_[e]};
  }
  Interval triangle_interval(Index f) const;
  Index cell_entry(Index c) const { return ranks_.cell[c]; }

  static Classification classify(const Interval& i, Index level);
  Classification classify_cell(Index c, Index level) const {
    return ranks_.cell[c] < level ? Classification::interior : Classification::exterior;
  }
  ClassCounts counts(Index level) const;

  // Filtration by entry rank, and its persistence pairs (ranks) of
  // positive length. The pairs are computed on the first call (thread-safe),
  // so users of the intervals alone (areas, shapes) do not pay for them;
  // betti() and optimal_level() need them too.
  FiltrationRanks filtration() const;
  const std::vector<PersistencePair>& persistence() const;
  std::array<std::size_t, 3> betti(Index level) const;
  // Smallest level at which every vertex is present in one component.
  Index optimal_level() const;

  double volume(Index level) const;  // of the interior cells
  double area(Index level) const;    // of the regular and singular triangles
  ShapeBoundary boundary(Index level) const;

  const SizeStats& size_stats() const { return size_stats_; }
  std::size_t memory_bytes() const;

private:
  // The interval records, by field: entry ranks (the filtration), mu_low and
  // mu_high of vertices and edges, attached flags. A triangle's mu_low and
  // mu_high are the ranks of its two cells, read from there.
  struct Bounds {
    Index low = kNever, high = kNever;
  };

  const Triangulation* t_;
  unsigned threads_;
  Simplices simplices_;
  FiltrationRanks ranks_;
  std::vector<Bounds> vertex_bounds_, edge_bounds_;
  std::vector<bool> vertex_attached_, edge_attached_, triangle_attached_;
  // Global simplex ids: vertices, then edges from ids_.edges, triangles, cells.
  struct {
    Index edges = 0, triangles = 0, cells = 0;
  } ids_;
  std::vector<Index> spectrum_;  // global id of a simplex realizing each critical value
  struct LazyPairs {
    std::once_flag once;
    std::vector<PersistencePair> pairs;
  };
  std::unique_ptr<LazyPairs> pairs_ = std::make_unique<LazyPairs>();  // a pointer: keeps the class movable
  SizeStats size_stats_;

  Simplex simplex(Index global_id) const;
  // Construction: the attached flags, the entry ranks of the simplices that
  // enter at their own size, and the spectrum; then the bounds of the faces
  // and the entries of the attached ones.
  void rank_critical();
  void bound_faces();
};

}  // namespace alpha
