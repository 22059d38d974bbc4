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

// How Cavities::sites are ordered: by the ligandability model
// (its rank_score; ties in the geometric order; the probability, which
// decides which pockets are sites, comes from its classifier and need not
// fall with the rank), or by the geometric score as find_cavities ranks
// them.
enum class SiteRanking { probability, geometric };
// "probability" or "geometric" -> the ranking; throws alpha::Error (misuse)
// naming anything else.
SiteRanking parse_site_ranking(const std::string& name);

// The probability below which a pocket is no site: with the model fitted on
// pockets-train and pockets-train-pb, 0.08 leaves a median of 5 sites per
// structure of 21 candidates (cross-validated) and 5 / 6.5 on pockets-dev /
// pockets-dev-pb, with the top-1 and top-3 figures of the cut at 0.04 of before
// (docs/ranking.md; candidates under it hold a ligand in 1-9 % of cases).
inline constexpr double kMinSiteProbability = 0.08;

// Every pocket and void of `cavities` (found on `structure`'s atoms) gets
// its ligandability, probability and rank_score from the default model; the pockets
// below kMinSiteProbability are left out (a void that holds a ligand is a
// site whatever its probability) and the sites ordered as
// `ranking` says (by the model: with their clusters' centres,
// site_clusters.hpp, moved onto the buried surface, site_recentering.hpp,
// unless `place_centers` is false).
void rank_sites(const Structure& structure, Cavities& cavities, SiteRanking ranking = SiteRanking::probability,
                bool place_centers = true);

}  // namespace molecule
