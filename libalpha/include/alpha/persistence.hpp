// SPDX-License-Identifier: Apache-2.0
// Persistent homology (Z/2) of a filtration of a 3D triangulation's finite
// simplices: each simplex enters at an integer rank, and faces never enter
// after their cofaces. Ties are broken by dimension, then id (the order of
// the "filtration order": faces before cofaces).
//
// Dimension 0 pairs come from union-find on vertices and edges (elder rule);
// dimension 2 pairs from union-find on the complement (cells and the outside,
// in reverse order; Alexander duality in the 3-sphere); dimension 1 pairs from
// column reduction of the remaining triangles, with each column restricted to
// the edges that create cycles (compression: other rows are never pivots).
#pragma once
#include <cstdint>
#include <vector>

#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"

namespace alpha {

inline constexpr Index kNever = kNone;  // rank of a simplex that never enters

// Entry rank of every simplex, indexed like Simplices / Triangulation ids;
// infinite cells have kNever.
struct FiltrationRanks {
  std::vector<Index> vertex, edge, triangle, cell;
};

struct PersistencePair {
  int dim;               // 0, 1 or 2
  Index birth, death;    // ranks; death == kNever for classes that never die
  Index birth_simplex;   // id of the creating simplex (dimension dim)
  Index death_simplex;   // id of the killing simplex (dimension dim+1), or kNone
};

// The pairs sorted by (dim, birth, death), with or without the zero-length
// ones (birth == death: they never change a Betti number). With threads > 1,
// dimensions 0 and 2 are paired side by side; the pairs are the same.
std::vector<PersistencePair> persistence_pairs(const Triangulation& t, const Simplices& s,
                                               const FiltrationRanks& ranks, bool keep_zero_length = false,
                                               unsigned threads = 1);

// Betti numbers b0, b1, b2 of the sub-complex of simplices with rank <= r.
std::array<std::size_t, 3> betti_at(const std::vector<PersistencePair>& pairs, Index r);

}  // namespace alpha
