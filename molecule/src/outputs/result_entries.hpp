// SPDX-License-Identifier: Apache-2.0
// The lists several outputs show, made from a run by one function each:
// the sites (report.json, sites.csv and batch's, report.html), the
// tunnels (report.json, tunnels.csv and batch's, tunnel_profiles.csv,
// report.html), and the values their entries share, rounded as
// report.json has them (outputs/report_numbers.hpp). The writers only
// format them. Each writer makes the list it shows from the run, which does
// not keep them: a kept list would go stale when a field of the run changes,
// and making them is cheap (docs/architecture.md).
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "molecule/pocket_run.hpp"

namespace molecule {

// One site as the outputs list them, in rank order.
struct SiteEntry {
  std::size_t rank;         // from 1
  const char* kind;         // "pocket" or "void"
  std::size_t cavity_rank;  // its rank among the pockets or the voids
  const Cavity* cavity;     // the pocket or void
  alpha::Vec3 center;       // the site's (its cluster's), not always its cavity's
  nlohmann::ordered_json mean_plddt;  // of the lining residues (mean_plddt)
  std::vector<alpha::Index> residues;  // of the lining atoms (residues_of)
  std::vector<std::string> ligands;    // the ids of the hetero groups that lie in it (LigandSite::lies_in)
};
std::vector<SiteEntry> site_entries(const PocketRun& run);

// One tunnel as the outputs list them: the cycles first (rank = their
// tunnel_N in pockets.pml and pockets.pdb), then the tunnels and pores.
struct TunnelEntry {
  std::size_t rank;  // from 1
  const char* kind;  // "cycle", "tunnel" or "pore"
  // Null where the kind has none; rounded as report.json has them.
  nlohmann::ordered_json start;  // a tunnel's start (its label)
  double bottleneck_radius;
  alpha::Vec3 bottleneck;
  nlohmann::ordered_json length, curvature, cost, birth_alpha_sq, death_alpha_sq;
  nlohmann::ordered_json path;  // a cycle's: the rank of the first tunnel or pore through it (path_through)
  const std::vector<alpha::Index>* lining_atoms;
  std::vector<alpha::Index> residues;  // of the lining atoms (residues_of)
  const TunnelPath* way;  // its radius profile's: a cycle's way through (null: none found), the path itself

  bool is_cycle() const;
};
std::vector<TunnelEntry> tunnel_entries(const PocketRun& run);

// A probability as report.json and the tables have it: 4 decimals; null
// where none was computed (find_cavities alone).
nlohmann::ordered_json report_probability(double p);

// Predicted models: the mean pLDDT (B-factor) of the residues of these
// atoms, one value per residue (its first atom's: a model gives all atoms
// of a residue the same), rounded to 3 decimals; null for other structures.
nlohmann::ordered_json mean_plddt(const Structure& structure, const std::vector<alpha::Index>& atoms);
// The same over all atoms.
nlohmann::ordered_json mean_plddt(const Structure& structure);

// A hetero group's id, e.g. "A:HEM:201".
std::string ligand_id(const HeteroGroup& group);
// The run's ligand sites, one per hetero group (Misuse when a structure
// with hetero groups has none).
std::span<const LigandSite> ligands_of(const PocketRun& run);

}  // namespace molecule
