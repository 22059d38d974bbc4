// SPDX-License-Identifier: Apache-2.0
// The whole cavity search on a structure, as `alphapocket pockets` runs it:
// atom i becomes the weighted point (x_i, (r_i + probe)^2), r_i its ProtOr
// radius; their regular triangulation and alpha complex give the cavities
// (find_cavities, with the solvent-accessible model's area and volume).
#pragma once
#include <memory>
#include <string>

#include "alpha/alpha_complex.hpp"
#include "alpha/triangulation.hpp"
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

struct PocketSearch {
  std::unique_ptr<alpha::Triangulation> triangulation;
  std::unique_ptr<alpha::AlphaComplex> complex;  // refers to *triangulation
  Cavities cavities;  // atom indices are indices into Structure::atoms
  // Wall-clock seconds of the stages, for logs and benchmarks.
  double complex_seconds = 0;
  double cavities_seconds = 0;
  double ranking_seconds = 0;  // site features and ligandability model
};

// The probability below which a candidate is no site: on pockets-train
// (cross-validated), 0.04 leaves a median of 7 sites per structure of 16
// candidates and loses no ligand from the top 3 (0.03: 9 sites; 0.05: 6,
// losing 3 of 225 ligands at DCC and DCA top-3).
inline constexpr double kMinSiteProbability = 0.04;

// Every pocket and void gets its ligandability and probability from the
// default model (molecule/ligandability_model.hpp); the sites below
// kMinSiteProbability are left out and the others ordered as `ranking` says
// (by probability: with their clusters' centres, molecule/site_clusters.hpp). Throws alpha::Error for unusable input (e.g.
// all atoms in one plane) or options (negative probe).
PocketSearch search_pockets(const Structure& structure, const CavityOptions& options,
                            SiteRanking ranking = SiteRanking::probability);

}  // namespace molecule
