// SPDX-License-Identifier: Apache-2.0
// report.html and scene.mvsj of `alphapocket pockets`: the run for a
// browser, opened from the file system with no network and no server.
//
// scene.mvsj is the 3D scene as MolViewSpec (the format of Mol* and PDBe):
// the structure (structure.cif beside it) as a cartoon under a see-through
// surface, pLDDT colours for predicted models, each site's lining residues
// and its space (its sinks' spheres, or its cast when meshes are given) in
// its rank colour, the ligands named, the tunnels as spheres of their
// radius profile. report.html holds that scene, structure.cif and the
// tables' data as one JSON block, and loads the viewer files copied into
// viewer/ beside it (report_assets.hpp): Mol* draws the scene and
// viewer/report.js the tables, the profiles and the links between them.
//
// Text from the input (file, chain, residue and ligand names) reaches the
// page only inside that JSON block, with every '<', '>' and '&' escaped,
// and report.js puts it into the page as text, never as markup.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "molecule/pocket_meshes.hpp"
#include "outputs/pocket_report.hpp"
#include "outputs/viewer_scene.hpp"

namespace molecule {

// The scene as a MolViewSpec document loading the structure from
// `structure_url`. `meshes` (null: none) gives the casts drawn instead of
// the spheres.
nlohmann::ordered_json molviewspec_scene(const PocketRun& run, const ViewerScene& scene,
                                         const std::string& structure_url, const PocketMeshes* meshes);

// The page, from the run (its tables' data as report.json and the tables
// have it: pocket_report's sections, tunnel_entries), the scene
// (molviewspec_scene), the text of structure.cif, the names of the files
// written beside it and the directory of the viewer files relative to it.
std::string report_page(const PocketRun& run, const nlohmann::ordered_json& mvs, const std::string& structure_cif,
                        const std::vector<std::string>& files, const std::string& viewer);

// JSON text safe inside an HTML <script> element: '<', '>' and '&' as
// \u escapes (the same JSON once parsed).
std::string script_json(const nlohmann::ordered_json& value);

// Text for HTML element content or a quoted attribute.
std::string html_text(const std::string& text);

}  // namespace molecule
