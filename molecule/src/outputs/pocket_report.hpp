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
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "molecule/ligand_sites.hpp"
#include "molecule/structure.hpp"
#include "molecule/tunnel_paths.hpp"
#include "molecule/pocket_run.hpp"

namespace molecule {

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

}  // namespace molecule
