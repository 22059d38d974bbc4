// SPDX-License-Identifier: Apache-2.0
// Sites ranked by probability are centred on the buried surface around
// them: a cavity's centre (or a cluster's, ranking/site_clusters.hpp) is
// the middle of its empty space, which for a shallow or elongated site
// lies beside the ligand; the ligand lines the buried surface. Each site's
// centre becomes the mean of the buried surface points
// (ranking/buried_surface.hpp) within kRecenteringRadius of it; a site
// with none keeps its centre.
//
// Measured (bench/README.md, "Site centres on the buried surface"):
// pockets-train out of fold, DCC top-1 0.333 -> 0.396 and top-3 0.480 ->
// 0.582 (225 ligands), DCA top-3 0.747 -> 0.764; pockets-dev unchanged.
// Radii 6-10 A, 75-95 atoms and moving halfway were tried. With the model
// of both training folders 6 A beats 7 A on both dev folders (docs/ranking.md,
// "Site centres"): pockets-dev-pb DCC top-1 0.450 -> 0.550.
#pragma once
#include "ranking/buried_surface.hpp"
#include "molecule/cavities.hpp"

namespace molecule {

inline constexpr double kRecenteringRadius = 6;  // A

// Moves each site's centre (cavities.sites, centres set).
void center_sites_on_buried_surface(Cavities& cavities, const BuriedSurface& surface);

}  // namespace molecule
