#include "molecule/pocket_outputs.hpp"

#include <algorithm>
#include <regex>
#include <system_error>

#include "alpha/error.hpp"
#include "molecule/atomic_file.hpp"
#include "molecule/cavity_mesh.hpp"
#include "molecule/mesh_export.hpp"
#include "molecule/pocket_colors.hpp"
#include "molecule/pocket_pdb.hpp"
#include "molecule/pymol_script.hpp"
#include "molecule/chimerax_script.hpp"
#include "molecule/structure_copy.hpp"
#include "molecule/viewer_scene.hpp"

namespace molecule {

namespace fs = std::filesystem;

OutputSelection parse_output_selection(const std::string& list) {
  OutputSelection s{false, false, false, false, false, false};
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string item = list.substr(begin, end - begin);
    bool* flag = item == "report" ? &s.report
                 : item == "csv"  ? &s.csv
                 : item == "pml"  ? &s.pml
                 : item == "pdb"  ? &s.pdb
                 : item == "meshes" ? &s.meshes
                 : item == "tunnels" ? &s.tunnels
                                    : nullptr;
    if (!flag) alpha::fail("unknown output '" + item + "' (report, csv, pml, pdb, meshes, tunnels)");
    *flag = true;
    begin = end + 1;
  }
  return s;
}

PocketOutputDir::PocketOutputDir(const std::string& path, const OutputSelection& selection)
    : path_(path), selection_(selection) {
  std::error_code ec;
  if (fs::exists(path_, ec) && !fs::is_directory(path_, ec))
    alpha::fail(path + ": cannot create the output directory: a file of that name exists");
  create(path_);
  check_can_create((path_ / "report.json").string());
  if (selection_.meshes) {
    create(path_ / "meshes");
    check_can_create((path_ / "meshes" / "molecule.ply").string());
  }
}

PocketOutputDir::~PocketOutputDir() {
  if (written_) return;
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
    std::error_code ec;
    fs::remove(*it, ec);  // removes only an empty directory
  }
}

void PocketOutputDir::create(const fs::path& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  if (!fs::create_directory(dir, ec))
    alpha::fail(dir.string() + ": cannot create the output directory: " +
                (ec ? ec.message() : std::string("a file of that name exists")));
  created_.push_back(dir);
}

std::vector<std::string> PocketOutputDir::write(const PocketRun& run) { return write(run, pocket_report(run)); }

std::vector<std::string> PocketOutputDir::write(const PocketRun& run, const nlohmann::ordered_json& report) {
  // Every file is made in memory first, so that a failure (a mesh OpenMesh
  // refuses, a full disk) leaves the directory as it was.
  std::vector<std::pair<std::string, std::string>> files;  // (name, content)
  warnings_.clear();
  // Invalid UTF-8 in the input's names is replaced, not an error.
  if (selection_.report)
    files.emplace_back("report.json",
                       report.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
  if (selection_.csv) files.emplace_back("pockets.csv", pockets_csv(run));
  if (selection_.pml) {
    StructureCopy copy = structure_copy(*run.structure, "alphapocket " + run.version + ": the atoms searched in " +
                                                            run.file + ", and its ligands");
    const ViewerScene scene = viewer_scene(run, copy.ligand_ids);
    files.emplace_back("structure.cif", std::move(copy.cif));
    files.emplace_back("pockets.pml", pymol_script(run, scene));
    files.emplace_back("pockets.cxc", chimerax_script(run, scene));
  }
  const alpha::AlphaComplex& ac = *run.search->complex;
  const Cavities& cavities = run.search->cavities;
  if (selection_.pdb) {
    PocketPdb pdb = pocket_pdb(ac, cavities, "alphapocket " + run.version + " pockets of " + run.file);
    if (pdb.left_out > 0)
      warnings_.push_back("pockets.pdb: " + std::to_string(pdb.left_out) +
                          " pseudo-atoms left out, beyond the PDB columns' range (report.json has every cavity)");
    files.emplace_back("pockets.pdb", std::move(pdb.text));
  }
  if (selection_.tunnels && run.paths) {
    files.emplace_back("tunnels.csv", tunnels_csv(run));
    files.emplace_back("tunnel_profiles.csv", tunnel_profiles_csv(run));
    PocketPdb tunnels = tunnel_pdb(*run.paths, cavities.tunnels.size() + 1,
                                   "alphapocket " + run.version + " tunnels of " + run.file);
    if (tunnels.left_out > 0)
      warnings_.push_back("tunnels.pdb: " + std::to_string(tunnels.left_out) +
                          " pseudo-atoms left out, beyond the PDB columns' range");
    files.emplace_back("tunnels.pdb", std::move(tunnels.text));
  }
  if (selection_.meshes && !run.mesh_format.empty()) {
    const auto mesh_file = [&](const std::string& name, const TriangleMesh& mesh) {
      files.emplace_back(name, mesh_file_content((path_ / name).string(), mesh).bytes);
    };
    const CavityColors colors = cavity_colors(cavities);
    const auto meshes = [&](const std::vector<Cavity>& list, const std::vector<Rgb>& color, const std::string& kind) {
      for (std::size_t i = 0; i < list.size(); ++i)
        mesh_file(cavity_mesh_path(kind, i + 1, run.mesh_format), cavity_mesh(ac, list[i], color[i]));
    };
    meshes(cavities.pockets, colors.pockets, "pocket");
    meshes(cavities.voids, colors.voids, "void");
    mesh_file(molecule_mesh_path(run.mesh_format), molecule_mesh(ac));
  }

  std::vector<std::string> written;
  for (auto& [name, content] : files) {
    written.push_back(name);
    name = (path_ / name).string();
  }
  write_files_atomically(files);
  written_ = true;
  remove_stale(written);
  return written;
}

namespace {

// Removes the files of ours in dir that are not among `written`, and
// meshes/ if that leaves it empty and keep_meshes_dir is false.
void remove_ours(const fs::path& dir, const std::vector<std::string>& written, bool keep_meshes_dir) {
  const auto is_written = [&](const std::string& name) {
    return std::find(written.begin(), written.end(), name) != written.end();
  };
  for (const char* name : {"report.json", "pockets.csv", "pockets.pml", "pockets.cxc", "structure.cif", "pockets.pdb",
                           "tunnels.csv", "tunnel_profiles.csv", "tunnels.pdb"}) {
    std::error_code rm;
    if (!is_written(name)) fs::remove(dir / name, rm);
  }
  static const std::regex kOurs(R"(((pocket|void)_[0-9]+|molecule)\.(ply|obj|off|stl))");
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir / "meshes", ec)) {
    const std::string name = entry.path().filename().string();
    if (!std::regex_match(name, kOurs)) continue;
    if (is_written("meshes/" + name)) continue;
    std::error_code rm;
    fs::remove(entry.path(), rm);
  }
  if (!keep_meshes_dir) fs::remove(dir / "meshes", ec);  // only when empty
}

}  // namespace

void PocketOutputDir::remove_stale(const std::vector<std::string>& written) const {
  remove_ours(path_, written, selection_.meshes);
}

void remove_pocket_outputs(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return;
  remove_ours(path, {}, false);
  fs::remove(path, ec);  // only when empty
}

}  // namespace molecule
