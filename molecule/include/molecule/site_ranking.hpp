// SPDX-License-Identifier: Apache-2.0
// The ranking stage: which of the cavities are candidate binding sites, and
// in what order. Each pocket and void is described by its site features
// (molecule/site_features.hpp) and given a probability by the ligandability
// model (molecule/ligandability_model.hpp).
#pragma once
#include <string>

#include "molecule/cavities.hpp"
#include "molecule/structure.hpp"

namespace molecule {

// How Cavities::sites are ordered: by the ligandability model's
// probability (its margin; ties in the geometric order), or by the
// geometric score as find_cavities ranks them.
enum class SiteRanking { probability, geometric };
// "probability" or "geometric" -> the ranking; throws alpha::Error (misuse)
// naming anything else.
SiteRanking parse_site_ranking(const std::string& name);

// The probability below which a pocket is no site: on pockets-train
// (cross-validated), 0.04 leaves a median of 7 sites per structure of 16
// candidates and loses no ligand from the top 3 (0.03: 9 sites; 0.05: 6,
// losing 3 of 225 ligands at DCC and DCA top-3).
inline constexpr double kMinSiteProbability = 0.04;

// Every pocket and void of `cavities` (found on `structure`'s atoms) gets
// its ligandability and probability from the default model; the pockets
// below kMinSiteProbability are left out (a void that holds a ligand is a
// site whatever its probability) and the sites ordered as
// `ranking` says (by probability: with their clusters' centres,
// site_clusters.hpp, moved onto the buried surface, site_recentering.hpp).
void rank_sites(const Structure& structure, Cavities& cavities, SiteRanking ranking = SiteRanking::probability);

}  // namespace molecule
