// SPDX-License-Identifier: Apache-2.0
// Sites ranked by probability as clusters: a ligand site is often split
// into several pockets (the size rule, molecule/cavities.hpp), and the best
// ranked piece's own centre lies beside the ligand's. Greedily, best first,
// a site that no better site has taken heads a cluster of the lower-ranked
// sites not yet taken within kSiteClusterRadius of its cavity's centre
// whose probability is at least kSiteClusterShare of its own; its centre
// becomes the mean of the cluster's cavity centres weighted by
// probability. The taken sites stay in the ranking at their own centres.
//
// Measured (bench/README.md, "Site clusters"): on pockets-train out of fold,
// DCC top-1 0.289 -> 0.333 and DCA top-1 0.578 -> 0.618 (225 ligands);
// radii 8-12 A and shares 0.4-0.8 were tried.
#pragma once
#include "molecule/cavities.hpp"

namespace molecule {

inline constexpr double kSiteClusterRadius = 10;  // A, between cavity centres
inline constexpr double kSiteClusterShare = 0.6;  // of the head's probability

// Sets each site's centre (cavities.sites, in rank order, with their
// cavities' probabilities set).
void cluster_site_centers(Cavities& cavities);

}  // namespace molecule
