// SPDX-License-Identifier: Apache-2.0
// What the writers take: one run's results, as analysis.hpp's Analysis
// hands them on.
#pragma once
#include <string>
#include <vector>

#include "molecule/cavities.hpp"
#include "molecule/ligand_sites.hpp"
#include "molecule/pocket_meshes.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/radii.hpp"
#include "molecule/structure.hpp"
#include "molecule/tunnel_paths.hpp"

namespace molecule {

// Everything one run produced. Pointers are borrowed; atom indices of the
// cavities (Cavity::lining_atoms) are indices into structure->atoms.
struct PocketRun {
  std::string file;  // the input, as given
  const Structure* structure = nullptr;
  CavityOptions options;
  std::string version;  // of alphapocket
  const PocketSearch* search = nullptr;
  // Where each hetero group lies (ligand_sites): one per group of
  // structure->hetero_groups; null when the structure has none.
  const std::vector<LigandSite>* ligands = nullptr;
  std::string mesh_format;  // "ply", "obj", "off", "stl"; empty: no meshes written
  // The meshes written when mesh_format is given (pocket_meshes).
  const PocketMeshes* meshes = nullptr;
  double min_plddt = 0;     // StructureOptions::min_plddt the structure was read with
  std::string radii = std::string(kRadiusTable);  // the radius table, or the --radii file
  // Tunnels and pores (find_tunnels); null: none computed.
  const std::vector<TunnelPath>* paths = nullptr;
  // The way through each cycle of search->cavities.tunnels (find_tunnels);
  // null: none computed.
  const std::vector<TunnelPath>* cycle_paths = nullptr;
  std::vector<std::string> tunnel_starts;  // label of each start, by TunnelPath::start
  std::string tunnels_from = "auto";
  TunnelOptions tunnel_options;
};

}  // namespace molecule
