// SPDX-License-Identifier: Apache-2.0
// One structure's run as the writers take it: the options it was run with
// and everything it found, owned. molecule::Analysis (analysis.hpp) is one,
// with how it went and the report; the outputs stage formats it as it is.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "alphapocket/version.hpp"
#include "molecule/cavities.hpp"
#include "molecule/ligand_sites.hpp"
#include "molecule/output_selection.hpp"
#include "molecule/pocket_meshes.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/site_ranking.hpp"
#include "molecule/structure.hpp"
#include "molecule/tunnel_paths.hpp"

namespace molecule {

struct AnalysisOptions {
  StructureOptions structure;
  CavityOptions cavities;
  std::string version = alphapocket::kVersion;  // written into the report
  // More atoms after the selection: LimitExceeded before the search. 0: no limit.
  std::size_t max_atoms = 0;
  OutputSelection outputs;
  std::string mesh_format = "ply";  // "ply", "obj", "off", "stl"
  std::string radii_file;           // --radii (molecule/radius_file.hpp); empty: ProtOr
  std::string tunnels_from = "auto";  // --tunnels-from (molecule/tunnel_start.hpp)
  TunnelOptions tunnels;            // --tunnel-probe, --pores
  SiteRanking ranking = SiteRanking::probability;
  double mesh_resolution = kDefaultMeshResolution;  // triangle size of the surface mesh, A (PocketRun::meshes)
  bool report = true;  // Analysis::report made, and the ligands' sites (read by it and the writers only)
};

// Atom indices (Cavity::lining_atoms, a path's lining atoms) are indices
// into structure.atoms.
struct PocketRun {
  std::string file;  // the input, as given
  AnalysisOptions options;
  Structure structure;
  PocketSearch search;
  // Where each hetero group lies (ligand_sites), by Structure::hetero_groups.
  std::vector<LigandSite> ligands;
  std::vector<std::string> tunnel_starts;  // label of each start, by TunnelPath::start
  std::vector<TunnelPath> paths;           // tunnels and pores (find_tunnels)
  std::vector<TunnelPath> cycle_paths;     // the way through each of search.cavities.tunnels (find_tunnels)
  // The surface and casts (pocket_meshes) when options.outputs.meshes, made
  // of the search's solvent-excluded body, which is then freed
  // (search.bodies is empty); none otherwise.
  std::optional<PocketMeshes> meshes;

  // The format the meshes are written in (options.mesh_format); empty
  // when there are none.
  std::string mesh_format() const;
  // The radius table the report names: ProtOr, or options.radii_file.
  std::string radii() const;
};

}  // namespace molecule
