// SPDX-License-Identifier: Apache-2.0
// The machine-readable results of `alphapocket pockets`: report.json (every
// number of the run, schema documented in docs/outputs.md, "report.json");
// the tables (pockets.csv, sites.csv, tunnels.csv) are outputs/tables.hpp's.
//
// Lengths in A, areas in A^2, volumes in A^3, rounded to 3 decimals (1e-3 A
// is far below the precision of any structure); scores and buriedness to
// 4 significant digits; values named *_alpha_sq are squared radii, kept at
// full precision (they are critical values of the spectrum one may pass
// back to --alpha-sq).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "alpha/geometry.hpp"
#include "molecule/cavities.hpp"
#include "molecule/ligand_sites.hpp"
#include "molecule/pocket_meshes.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/radii.hpp"
#include "molecule/residues.hpp"
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

// A probability as report.json and the tables have it: 4 decimals; null
// where none was computed (find_cavities alone).
nlohmann::ordered_json report_probability(double p);

// Predicted models: the mean pLDDT (B-factor) of the residues of these
// atoms, one value per residue (its first atom's: a model gives all atoms
// of a residue the same), rounded to 3 decimals; null for other structures.
nlohmann::ordered_json mean_plddt(const Structure& structure, const std::vector<alpha::Index>& atoms);
// The same over all atoms.
nlohmann::ordered_json mean_plddt(const Structure& structure);

// Mesh file of a cavity inside the output directory, e.g.
// "meshes/pocket_1.ply"; kind is "pocket" or "void". The molecular
// surface's is "meshes/surface.<format>".
std::string cavity_mesh_path(const std::string& kind, std::size_t rank, const std::string& format);
std::string molecule_mesh_path(const std::string& format);

nlohmann::ordered_json pocket_report(const PocketRun& run);
// Its sections that report.html shows as they are: "input",
// "parameters", "molecule".
nlohmann::ordered_json report_input(const PocketRun& run);
nlohmann::ordered_json report_parameters(const PocketRun& run);
nlohmann::ordered_json report_molecule(const PocketRun& run);
// A hetero group's id, e.g. "A:HEM:201".
std::string ligand_id(const HeteroGroup& group);
// Where a hetero group lies as report.json's ligands say it: the rank of
// the site it lies in; for a group left out, the nearest site's and the
// distance to it; each null where there is none.
struct LigandPlace {
  nlohmann::ordered_json site, nearest_site, distance;
};
LigandPlace ligand_place(const HeteroGroup& group, const LigandSite& site);
// A radius profile as report.json's tunnels have it: [x, y, z, radius] per point.
nlohmann::ordered_json report_profile(const TunnelPath& path);
// The report as Analysis holds it (analysis.hpp keeps JSON out of its header).
struct Report {
  nlohmann::ordered_json json;
};
// report.json's text: indented by 2, invalid UTF-8 in names replaced (U+FFFD).
std::string report_file_text(const nlohmann::ordered_json& report);
// The way through cycle k of search->cavities.tunnels, or null when none
// was found.
const TunnelPath* cycle_path(const PocketRun& run, std::size_t k);
// The ids of the hetero groups that lie in the site of this rank (from 1),
// e.g. "A:HEM:201" (LigandSite::lies_in).
std::vector<std::string> site_ligands(const PocketRun& run, std::size_t rank);
// The index into *run.paths of the first path that runs through a cycle's
// bottleneck (crosses its killing triangle, or passes its bottleneck
// centre), or npos.
std::size_t path_through(const PocketRun& run, const Tunnel& cycle);

}  // namespace molecule
