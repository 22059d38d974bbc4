// SPDX-License-Identifier: Apache-2.0
// The output directory of `alphapocket pockets`:
//
//   report.json   every result (pocket_report), indented
//   pockets.csv   one row per pocket (pockets_csv, outputs/tables.hpp)
//   sites.csv     one row per binding site, pockets and voids: the rows
//                 of batch's sites table (sites_csv)
//   structure.cif the atoms searched and the ligands (structure_copy),
//                 which the viewer scripts load by a relative path
//   pockets.pml   PyMOL script (pymol_script)
//   pockets.cxc   ChimeraX script (chimerax_script)
//   pockets.pdb   cavity centres and sinks as pseudo-atoms (pocket_pdb)
//   meshes/       surface.<fmt> (the molecular surface), pocket_<rank>.<fmt>,
//                 void_<rank>.<fmt> (the casts: PocketRun::meshes), an OBJ's
//                 .mtl files, and meshlab.mlp, a MeshLab project opening
//                 them all
//   tunnels.csv, tunnel_profiles.csv (tunnels_csv, tunnel_profiles_csv;
//                 like pockets.csv and sites.csv from outputs/tables.hpp),
//   tunnels.pdb   the tunnels and pores (tunnel_pdb)
//   report.html   the run in a browser, scene.mvsj its 3D scene as
//                 MolViewSpec (report_page), viewer/ the viewer files the
//                 page loads (report_assets)
//
// Which of them are written (OutputSelection: all by default, batch
// writes only the report).
//
// The directory describes one run, whole: the files are made in memory,
// written into a hidden sibling and swapped in with one rename
// (StagedDirectory), which replaces the earlier run's directory. So an
// existing directory must hold nothing but such files (or nothing): any
// other entry, e.g. the input structure or another tool's files, is
// refused, as are an empty name, the root of a file system, a mount point,
// the current directory (or one holding it) and a symbolic link to nothing.
// A symbolic link to a directory is followed; the directory replaced is a
// new one (its own permissions and owner are not kept). Nothing is created
// before write().
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "molecule/output_selection.hpp"
#include "outputs/pocket_report.hpp"
#include "util/temporary_paths.hpp"

namespace molecule {

class PocketOutputDir {
public:
  // Checks that `path` may become the output directory (above); throws
  // alpha::Error with one line naming it otherwise. Creates nothing. With
  // `temporaries`, write()'s hidden sibling is registered there.
  explicit PocketOutputDir(const std::string& path, const OutputSelection& selection = {},
                           TemporaryPaths* temporaries = nullptr);

  const std::filesystem::path& path() const { return path_; }
  // What the last write() could not put in the files, one line each (e.g.
  // pockets.pdb's pseudo-atoms beyond the PDB columns' range).
  const std::vector<std::string>& warnings() const { return warnings_; }
  // report.html loads its viewer files from directory `relative` (to the
  // output directory, e.g. "../viewer": a batch run's one copy) instead of
  // a copy in viewer/ beside it.
  void share_viewer(const std::string& relative) { viewer_ = relative; }

  // Writes the selected files, replacing the directory. Returns the names
  // written, relative to the directory.
  std::vector<std::string> write(const PocketRun& run);
  // The same with report.json from `report` (pocket_report(run), built
  // once by a caller that also prints it).
  std::vector<std::string> write(const PocketRun& run, const nlohmann::ordered_json& report);

private:
  std::filesystem::path path_;    // as given
  OutputSelection selection_;
  std::filesystem::path target_;  // absolute, through a symbolic link
  TemporaryPaths* temporaries_;
  std::string viewer_;  // share_viewer; empty: a copy in viewer/
  std::vector<std::string> warnings_;

  void check_ours() const;
};

// The output directory `name` names: absolute, without a trailing '/',
// through a symbolic link. Throws alpha::Error with one line naming it for an
// empty name, a file system root, a symbolic link to nothing.
std::filesystem::path output_directory_path(const std::string& name);

// Removes the files of an earlier run from directory `path` (only names of
// the forms above), and the directory itself if that leaves it empty:
// what a structure that now fails leaves of its outputs.
void remove_pocket_outputs(const std::string& path);

}  // namespace molecule
