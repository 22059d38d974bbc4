// The output directory of `alphapocket pockets`:
//
//   report.json   every result (pocket_report), indented
//   pockets.csv   one row per pocket (pockets_csv)
//   structure.cif the atoms searched and the ligands (structure_copy),
//                 which the viewer scripts load by a relative path
//   pockets.pml   PyMOL script (pymol_script)
//   pockets.cxc   ChimeraX script (chimerax_script)
//   pockets.pdb   cavity centres and sinks as pseudo-atoms (pocket_pdb)
//   meshes/       pocket_<rank>.<fmt>, void_<rank>.<fmt> (cavity_mesh) and
//                 molecule.<fmt> (molecule_mesh)
//   tunnels.csv, tunnel_profiles.csv (tunnels_csv, tunnel_profiles_csv),
//   tunnels.pdb   the tunnels and pores (tunnel_pdb)
//
// Which of them are written (OutputSelection: all by default, batch
// writes only the report); files of these names that this run does not
// write are removed.
//
// The files appear all together or not at all: all are made in memory,
// then written through write_files_atomically. Mesh files of an earlier
// run in meshes/ that this run does not write again (it found fewer
// cavities, or wrote another format) are removed, so the directory always
// describes one run; only names of the form above are touched.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "molecule/pocket_report.hpp"

namespace molecule {

struct OutputSelection {
  bool report = true, csv = true, pdb = true, meshes = true;
  bool pml = true;  // the viewer scripts: pockets.pml, pockets.cxc and structure.cif
  bool tunnels = true;  // tunnels.csv, tunnel_profiles.csv, tunnels.pdb
};

// "report,csv,pml,pdb,meshes,tunnels" (any subset, any order) -> a selection;
// throws alpha::Error naming an unknown item.
OutputSelection parse_output_selection(const std::string& list);

class PocketOutputDir {
public:
  // Creates the directory and its meshes/ subdirectory where missing and
  // checks that files can be created there; throws alpha::Error with one
  // line naming the directory otherwise.
  explicit PocketOutputDir(const std::string& path, const OutputSelection& selection = {});
  // Removes the directories the constructor created if no file was written
  // into them (the run failed before writing).
  ~PocketOutputDir();
  PocketOutputDir(const PocketOutputDir&) = delete;
  PocketOutputDir& operator=(const PocketOutputDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // What the last write() could not put in the files, one line each (e.g.
  // pockets.pdb's pseudo-atoms beyond the PDB columns' range).
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Writes the selected files. Returns the names written, relative to the
  // directory.
  std::vector<std::string> write(const PocketRun& run);
  // The same with report.json from `report` (pocket_report(run), built
  // once by a caller that also prints it).
  std::vector<std::string> write(const PocketRun& run, const nlohmann::ordered_json& report);

private:
  std::filesystem::path path_;
  OutputSelection selection_;
  std::vector<std::filesystem::path> created_;
  bool written_ = false;
  std::vector<std::string> warnings_;

  void create(const std::filesystem::path& dir);
  void remove_stale(const std::vector<std::string>& written) const;
};

// Removes the files of an earlier run from directory `path` (only names of
// the forms above), and the directory itself if that leaves it empty:
// what a structure that now fails leaves of its outputs.
void remove_pocket_outputs(const std::string& path);

}  // namespace molecule
