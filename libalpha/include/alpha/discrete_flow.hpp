// SPDX-License-Identifier: Apache-2.0
// The discrete flow of the empty cells of an alpha complex at one level
// (Edelsbrunner, Facello & Liang 1998, "On the definition and the
// construction of pockets in macromolecules"; Giesen & John's flow complex).
//
// An EMPTY cell is one not in the complex at the level (infinite cells are
// always empty: they are the outside). A finite empty cell c flows into its
// neighbour across facet f when f is empty too and separates c from c's
// orthocenter. The flow follows the power distance to the weighted points
// uphill; its SINKS are the empty finite cells without outgoing facets (the
// orthocenter inside, or every separating facet in the complex).
//
// The separation test is exact and needs no orthocenter: the orthocenter
// of c lies strictly beyond facet f exactly when c's vertex opposite f has
// negative power distance to f's smallest orthogonal sphere, i.e. attaches
// f (along the line of orthogonal spheres of f the centre moves past the
// plane of f just when the apex enters that sphere). Hence a facet is
// crossed by the flow in at most one direction, and the flow is acyclic:
// the size (orthosphere radius) never decreases along it, and cells sharing
// one orthosphere are ordered by visibility from its centre.
//
// A cell is OUTSIDE when some flow path from it reaches an infinite cell.
// The other empty finite cells drain only into finite sinks; joined through
// empty facets they form the REGIONS (CASTp pockets and voids). A region
// MOUTH facet is an empty facet between a region cell and an outside cell;
// a region without one is a bounded component of the complement of the
// complex (a void, counted by b2).
#pragma once
#include <cstdint>
#include <vector>

#include "alpha/alpha_complex.hpp"

namespace alpha {

class DiscreteFlow {
public:
  // The flow of the cells of `ac` that are not in the complex at `level`
  // (a rank as returned by AlphaComplex::level). Linear time; deterministic.
  DiscreteFlow(const AlphaComplex& ac, Index level);

  Index level() const { return level_; }
  bool empty(Index c) const { return state_[c] & kEmpty; }
  // Bit k set: c flows into cell(c).n[k], across the facet opposite v[k].
  std::uint8_t flow_facets(Index c) const { return state_[c] & kFacets; }
  bool is_sink(Index c) const { return (state_[c] & (kEmpty | kOutside | kFacets)) == kEmpty; }
  bool outside(Index c) const { return state_[c] & kOutside; }

  // Region of an empty finite cell that is not outside, kNone otherwise.
  // Regions are numbered in order of their smallest cell id.
  Index region(Index c) const { return region_[c]; }
  std::size_t num_regions() const { return num_regions_; }

private:
  static constexpr std::uint8_t kFacets = 0x0f, kEmpty = 0x10, kOutside = 0x20;
  Index level_;
  std::vector<std::uint8_t> state_;
  std::vector<Index> region_;
  std::size_t num_regions_ = 0;
};

}  // namespace alpha
