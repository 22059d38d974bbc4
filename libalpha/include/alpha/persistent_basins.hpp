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
// Components of persistence up to `threshold` are merged into their
// elder; the others stay apart (ToMATo clustering, Chazal, Guibas, Oudot &
// Skraba 2013, on the dual graph). A cell that flows into a neighbour (see
// alpha/discrete_flow.hpp) meets it at persistence 0 through the attached
// facet, so a threshold of 0 leaves one basin per sink of the flow among
// the cells (in general position), and an infinite one the connected
// components.
#pragma once
#include <span>
#include <vector>

#include "alpha/alpha_complex.hpp"

namespace alpha {

// `cells`: finite cells not in the complex at `level`, sorted; they are
// joined only through triangles not in the complex at `level` whose two
// cells are both in `cells`. Returns the basins: each sorted, ordered by
// smallest cell. Deterministic; O(n log n) for n cells. Throws
// alpha::Error for cells that are not sorted, empty and finite, and for a
// threshold that is not >= 0.
std::vector<std::vector<Index>> persistent_basins(const AlphaComplex& ac, Index level, std::span<const Index> cells,
                                                  double threshold);

}  // namespace alpha
