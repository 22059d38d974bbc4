// SPDX-License-Identifier: Apache-2.0
// Where the hetero groups of a structure (ligands, ions, cofactors) lie
// among its binding sites (Cavities::sites): molecule::analyse finds them
// (Analysis::ligands) for report.json's ligands[], the sites' ligands in
// report.json and sites.csv, and the summary ("ligand CNA A:200 in site 1").
//
// A site's SPACE is the union of its cavity's empty tetrahedra (the cells
// of Cavity::cells, spanned by atom centres): the free space the search
// found there, which a bound ligand that was left out of the search fills.
// A ligand's DISTANCE to a site is that of its nearest heavy atom centre to
// the site's space: 0 when an atom lies inside one of the tetrahedra.
//
// The site of a dropped group is its nearest site (the best-ranked one at
// that distance: a large ligand often lies in two sites, say its buried
// end in site 1 and the rest in a shallow site 9, and the better site is
// where it binds) when that is within kLigandSiteDistance, else none. Every
// site holding some of its heavy atoms is listed too. A kept group (--keep-hetero,
// --keep-cofactors) is part of the protein, so it has no distance: its
// site is the best-ranked site it lines (one of its atoms among the site's
// lining atoms), if any.
#pragma once
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "molecule/pocket_search.hpp"
#include "molecule/structure.hpp"

namespace molecule {

// A, as the DCA criterion of the ligand-site benchmarks (bench/README.md):
// a ligand this close to a site's space is that site's.
inline constexpr double kLigandSiteDistance = 4;

struct LigandSite {
  std::size_t group = 0;         // index into Structure::hetero_groups
  std::size_t site = 0;          // its site's rank (from 1); 0: none
  std::size_t nearest_site = 0;  // dropped groups: the nearest site's rank; 0 when there are no sites
  double distance = 0;           // dropped groups: to the nearest site's space, A
  std::size_t atoms_in_site = 0; // heavy atoms inside the site's space (kept: among its lining atoms)
  // Dropped groups: (rank, heavy atoms inside) of every site holding some, by rank.
  std::vector<std::pair<std::size_t, std::size_t>> holding;

  // Site `rank` is its site or holds some of its heavy atoms.
  bool lies_in(std::size_t rank) const {
    return site == rank || std::any_of(holding.begin(), holding.end(), [&](const auto& h) { return h.first == rank; });
  }
};

// One entry per hetero group, in Structure::hetero_groups' order. `search`
// must be the search of `structure`'s atoms.
std::vector<LigandSite> ligand_sites(const Structure& structure, const PocketSearch& search);

}  // namespace molecule
