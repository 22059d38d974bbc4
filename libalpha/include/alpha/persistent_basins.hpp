// SPDX-License-Identifier: Apache-2.0
// The basins of the empty space of an alpha complex, simplified by
// persistence: a region of empty cells split where it narrows.
//
// Going down the spectrum, the complement of the complex grows: an empty
// cell appears at its size, a triangle opens at its entry value and joins
// the cells on its two sides. Components are born at local maxima (the
// largest empty spheres, the flow's sinks) and merge at saddle triangles.
// When two components meet at a triangle of value s, the younger one (its
// largest cell is the smaller, by rank then id) has persistence
// r(size of its largest cell) - r(s), with r(v) = sqrt(v) the radius of an
// orthosphere of size v (extended as -sqrt(-v) below 0): by how much the
// radius of its widest sphere exceeds that of the passage into its elder.
// Components of persistence up to the threshold are merged into their
// elder; the others stay apart (ToMATo clustering, Chazal, Guibas, Oudot &
// Skraba 2013, on the dual graph). A cell that flows into a neighbour (see
// alpha/discrete_flow.hpp) meets it at persistence 0 through the attached
// facet, so a threshold of 0 leaves one basin per sink of the flow among
// the cells (in general position), and an infinite one the connected
// components.
//
// A size rule can keep large basins apart even where the passage between
// them is wide: given a mass per cell (e.g. its empty volume), two
// components that both weigh at least `min_mass` and together more than
// `max_mass` are not merged, unless they meet at persistence 0 (the
// younger's largest cell flows through the passage). So a component grows
// past max_mass only by pieces lighter than min_mass or by the flow.
#pragma once
#include <limits>
#include <span>
#include <vector>

#include "alpha/alpha_complex.hpp"

namespace alpha {

struct BasinMerging {
  double threshold = 0;  // persistence up to which the younger is merged (orthosphere radius)
  // Per cell of `cells` (>= 0), or empty for no size rule.
  std::span<const double> mass = {};
  double min_mass = std::numeric_limits<double>::infinity();
  double max_mass = std::numeric_limits<double>::infinity();
};

// `cells`: finite cells not in the complex at `level`, sorted; they are
// joined only through triangles not in the complex at `level` whose two
// cells are both in `cells`. Returns the basins: each sorted, ordered by
// smallest cell. Deterministic; O(n log n) for n cells. Throws
// alpha::Error for cells that are not sorted, empty and finite, for a
// threshold that is not >= 0, and for masses that are not one finite
// value >= 0 per cell.
std::vector<std::vector<Index>> persistent_basins(const AlphaComplex& ac, Index level, std::span<const Index> cells,
                                                  const BasinMerging& merging);

}  // namespace alpha
