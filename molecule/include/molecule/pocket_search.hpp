// SPDX-License-Identifier: Apache-2.0
// The whole cavity search on a structure, as `alphapocket pockets` runs it:
// atom i becomes the weighted point (x_i, (r_i + probe)^2), r_i its ProtOr
// radius; their regular triangulation and alpha complex give the cavities
// (find_cavities, with the solvent-accessible model's area and volume),
// whose candidate binding sites are then ranked (rank_sites).
#pragma once
#include <optional>
#include <string>

#include "alpha/point_set_complex.hpp"
#include "molecule/cavities.hpp"
#include "molecule/site_ranking.hpp"
#include "molecule/structure.hpp"

namespace molecule {

struct PocketSearch {
  // The atoms' weighted points: their triangulation and alpha complex
  // (empty in a search not run).
  std::optional<alpha::PointSetComplex> shape;
  // The union of the probe-inflated balls and its erosion find_cavities
  // measured with, kept for the meshes (they refer to shape's complex);
  // empty unless asked for (search_pockets' keep_bodies).
  SolventBodies bodies;
  Cavities cavities;  // atom indices are indices into Structure::atoms
  // Wall-clock seconds of the stages, for logs and benchmarks.
  double complex_seconds = 0;
  double cavities_seconds = 0;
  double ranking_seconds = 0;  // site features and ligandability model
};

// The complex, its cavities (find_cavities), then the sites ranked
// (rank_sites, molecule/site_ranking.hpp). With keep_bodies the search keeps
// its two solvent bodies for pocket_meshes; without, they are freed as soon
// as the cavities are measured (they are a quarter of the peak memory).
// Throws alpha::Error for unusable input (e.g. all atoms in one plane) or
// options (negative probe).
PocketSearch search_pockets(const Structure& structure, const CavityOptions& options,
                            SiteRanking ranking = SiteRanking::probability, bool keep_bodies = false);

}  // namespace molecule
