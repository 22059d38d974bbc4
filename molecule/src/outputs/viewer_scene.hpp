// SPDX-License-Identifier: Apache-2.0
// What the viewer scripts (pockets.pml for PyMOL, pockets.cxc for
// ChimeraX) show, computed once for both: the structure object, each
// cavity with its site rank, colour, lining atoms (as atom ids of
// structure.cif, outputs/structure_copy.hpp) and the spheres of its space,
// the ligands, the tunnels' bottlenecks and the paths of tunnels and pores. Only names we make (pocket_3, void_1, an
// object name of letters, digits and '_') and numbers are in it: nothing
// from the input file reaches a script.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "alpha/geometry.hpp"
#include "molecule/mesh_export.hpp"
#include "outputs/pocket_pdb.hpp"
#include "outputs/pocket_report.hpp"

namespace molecule {

// Sites shown when a script opens; the others are there, hidden. Their
// colours never repeat (molecule::rank_color).
inline constexpr std::size_t kShownSites = 12;

struct SceneCavity {
  std::string name;            // "pocket_3", "void_1"
  std::size_t site_rank = 0;   // its rank among the binding sites; 0: not a site (a small void, an unlikely pocket)
  Rgb color;                   // cavity_colors
  bool shown = false;          // a site of rank <= kShownSites
  std::vector<std::size_t> lining_ids;  // atom ids in structure.cif
  alpha::Vec3 center;
  std::vector<SinkSphere> space;  // its sinks' orthospheres (pockets.pdb's SNK atoms)
  std::string cast;  // its cast mesh relative to the scripts ("meshes/pocket_3.ply"); empty: no meshes
};

struct SceneTunnel {
  std::string name;  // "tunnel_1"
  std::vector<std::size_t> lining_ids;
  SinkSphere bottleneck;  // the largest probe passing it
};

// A tunnel or pore (TunnelPath): its centreline as spheres of the radius
// profile, coloured by tunnel (tunnel_color), and its lining residues.
struct ScenePath {
  std::string name;  // "tunnel_R", R its rank in report.json tunnels (after the cycles)
  Rgb color;
  std::vector<std::size_t> lining_ids;  // every atom of its lining residues
  std::vector<SinkSphere> spheres;      // one per profile point
};

struct ViewerScene {
  std::string object;  // the structure's object name, from the file name
  std::vector<SceneCavity> cavities;  // in site order, then the pockets and voids that are no site
  std::vector<std::size_t> ligand_ids;
  std::vector<SceneTunnel> tunnels;  // the cycles (report.json tunnels of kind "cycle")
  std::vector<ScenePath> paths;      // the tunnels and pores that follow them
};

// The structure file's object name in the viewers: FILE's name up to its
// first '.', letters, digits and '_' only ("1a26A").
std::string viewer_object_name(const std::string& file);

ViewerScene viewer_scene(const PocketRun& run, const std::vector<std::size_t>& ligand_ids);

// Ascending ids as runs of consecutive ids, (first, last) each.
std::vector<std::pair<std::size_t, std::size_t>> id_runs(const std::vector<std::size_t>& ids);

// A length or coordinate for a script: 3 decimals.
std::string script_number(double x);

}  // namespace molecule
