// SPDX-License-Identifier: Apache-2.0
// Which files of `alphapocket pockets` (pocket_outputs.hpp) a run writes.
#pragma once
#include <string>

namespace molecule {

// The defaults are what `alphapocket pockets` and Python's analyze() write
// unless told (output_list(OutputSelection{})): everything but the meshes,
// which cost 10-20 times the analysis, and report.html.
struct OutputSelection {
  bool report = true, csv = true, pdb = true;
  bool meshes = false;  // the surface and casts (Analysis::meshes), in AnalysisOptions::mesh_format
  bool pml = true;  // the viewer scripts: pockets.pml, pockets.cxc and structure.cif
  bool tunnels = true;  // tunnels.csv, tunnel_profiles.csv, tunnels.pdb
  // report.html, scene.mvsj, structure.cif and viewer/ (report_page.hpp):
  // off unless asked, as it needs the viewer files (report_assets.hpp).
  bool html = false;
};

// "report,csv,pml,pdb,meshes,tunnels,html" (any subset, any order; "all" for
// every one) -> a selection; throws alpha::Error naming an unknown item.
OutputSelection parse_output_selection(const std::string& list);

// The selection as a list in the order above ("report,meshes"): the same
// list for the same selection, however it was written.
std::string output_list(const OutputSelection& selection);

}  // namespace molecule
