// SPDX-License-Identifier: Apache-2.0
#include "outputs/pocket_outputs.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <regex>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include "alpha/error.hpp"
#include "util/staged_directory.hpp"
#include "molecule/mesh_export.hpp"
#include "outputs/meshlab_project.hpp"
#include "outputs/pocket_pdb.hpp"
#include "outputs/pymol_script.hpp"
#include "outputs/report_assets.hpp"
#include "outputs/report_page.hpp"
#include "outputs/chimerax_script.hpp"
#include "outputs/structure_copy.hpp"
#include "outputs/tables.hpp"
#include "outputs/viewer_scene.hpp"
#include "structure/structure_id.hpp"

namespace molecule {

namespace fs = std::filesystem;

namespace {

constexpr const char* kOurFiles[] = {"report.json", "pockets.csv", "sites.csv", "pockets.pml", "pockets.cxc", "structure.cif",
                                     "pockets.pdb", "tunnels.csv", "tunnel_profiles.csv", "tunnels.pdb",
                                     "report.html", "scene.mvsj"};

bool is_our_viewer_file(const std::string& name) {
  static const std::regex kOurs(R"((molstar|report)\.(js|css))");
  return std::regex_match(name, kOurs);
}

bool is_our_mesh(const std::string& name) {
  static const std::regex kOurs(R"(((pocket|void)_[0-9]+|surface|molecule)\.(ply|obj|mtl|off|stl)|meshlab\.mlp)");
  return std::regex_match(name, kOurs);
}

// The entries of dir that no run of ours writes (at most `max`, sorted):
// a regular file of one of our names, meshes/ and our meshes in it are ours.
std::vector<std::string> foreign_entries(const fs::path& dir, std::size_t max) {
  std::vector<std::string> foreign;
  const auto check = [&](const fs::path& d, const std::string& prefix, const auto& ours) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(d, ec)) {
      const std::string name = e.path().filename().string();
      std::error_code type_ec;
      if (e.is_symlink(type_ec) || !ours(e, name)) foreign.push_back(prefix + name);
    }
  };
  check(dir, "", [&](const fs::directory_entry& e, const std::string& name) {
    std::error_code ec;
    if (name == "meshes" && e.is_directory(ec)) {
      check(e.path(), "meshes/", [](const fs::directory_entry& m, const std::string& mesh) {
        std::error_code mec;
        return m.is_regular_file(mec) && is_our_mesh(mesh);
      });
      return true;
    }
    if (name == kViewerDir && e.is_directory(ec)) {
      check(e.path(), name + "/", [](const fs::directory_entry& m, const std::string& file) {
        std::error_code mec;
        return m.is_regular_file(mec) && is_our_viewer_file(file);
      });
      return true;
    }
    return e.is_regular_file(ec) && std::find(std::begin(kOurFiles), std::end(kOurFiles), name) != std::end(kOurFiles);
  });
  std::sort(foreign.begin(), foreign.end());
  if (foreign.size() > max) foreign.resize(max);
  return foreign;
}

// Every refusal is of the output directory the user named: bad input.
[[noreturn]] void bad_input(const std::string& name, const std::string& why) {
  alpha::fail(name + ": " + why, alpha::ErrorKind::BadInput);
}

// The output directory `name` as a path (output_directory_path), checked
// further: what must not be replaced by a run's directory is refused.
fs::path output_target(const std::string& name) {
  const fs::path target = output_directory_path(name);
  std::error_code ec;
  if (fs::exists(target, ec) && !fs::is_directory(target, ec))
    bad_input(name, "cannot create the output directory: a file of that name exists");
  if (fs::exists(target, ec) && ::access(target.c_str(), W_OK | X_OK) != 0)
    bad_input(name, "cannot write into the output directory: " + std::string(std::strerror(errno)));
  const fs::path parent = target.parent_path();
  struct stat parent_st {};
  if (::stat(parent.c_str(), &parent_st) != 0)
    bad_input(name, "cannot create the output directory: " + std::string(std::strerror(errno)));
  if (!S_ISDIR(parent_st.st_mode))
    bad_input(name, "cannot create the output directory: " + std::string(std::strerror(ENOTDIR)));
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    bad_input(name, "cannot create the output directory: " + std::string(std::strerror(errno)));
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0 && st.st_dev != parent_st.st_dev)
    bad_input(name, "is a mount point: write into a directory inside it");
  const fs::path cwd = fs::current_path(ec);
  if (!ec && fs::exists(target, ec)) {
    const fs::path here = fs::canonical(cwd, ec);
    const auto [end, _] = std::mismatch(target.begin(), target.end(), here.begin(), here.end());
    if (end == target.end()) bad_input(name, "is the current directory or holds it; name a directory for the results");
  }
  return target;
}

}  // namespace

fs::path output_directory_path(const std::string& name) {
  if (name.empty()) bad_input("''", "not an output directory name (empty)");
  std::error_code ec;
  fs::path target = fs::absolute(name, ec).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();
  if (fs::is_symlink(target, ec)) {
    const fs::path to = fs::read_symlink(target, ec);
    if (!fs::exists(target, ec))
      bad_input(name, "is a symbolic link to " + to.string() + ", which does not exist; remove the link or create " +
                          to.string());
    target = fs::canonical(target, ec);
  }
  if (target == target.root_path()) bad_input(name, "is the root of the file system, not an output directory");
  return target;
}

PocketOutputDir::PocketOutputDir(const std::string& path, const OutputSelection& selection,
                                 TemporaryPaths* temporaries)
    : path_(path), selection_(selection), target_(output_target(path)), temporaries_(temporaries) {
  check_ours();
}

void PocketOutputDir::check_ours() const {
  const std::vector<std::string> foreign = foreign_entries(target_, 4);
  if (!foreign.empty()) {
    std::string list;
    for (const std::string& f : foreign) list += (list.empty() ? "'" : ", '") + f + "'";
    bad_input(path_.string(), "holds files that are not alphapocket outputs (" + list +
                                  "); they would be removed: choose a new or empty directory");
  }
}

std::vector<std::string> PocketOutputDir::write(const PocketRun& run) { return write(run, pocket_report(run)); }

std::vector<std::string> PocketOutputDir::write(const PocketRun& run, const nlohmann::ordered_json& report) {
  // Every file is made in memory first, so that a failure (a mesh OpenMesh
  // refuses, a full disk) leaves the directory as it was.
  std::vector<std::pair<std::string, std::string>> files;  // (name, content)
  std::vector<std::pair<std::string, fs::path>> copies;    // (name, the file whose content it has)
  warnings_.clear();
  // Invalid UTF-8 in the input's names is replaced, not an error.
  if (selection_.report)
    files.emplace_back("report.json",
                      report_file_text(report));
  if (selection_.csv) {
    files.emplace_back("pockets.csv", pockets_csv(run));
    files.emplace_back("sites.csv", sites_csv(structure_id(run.file), run));
  }
  std::optional<StructureCopy> copy;
  std::optional<ViewerScene> scene;
  if (selection_.pml || selection_.html) {
    copy = structure_copy(run.structure, "alphapocket " + run.options.version + ": the atoms searched in " + run.file +
                                              ", and its ligands");
    scene = viewer_scene(run, copy->ligand_ids);
    files.emplace_back("structure.cif", copy->cif);
  }
  if (selection_.pml) {
    files.emplace_back("pockets.pml", pymol_script(run, *scene));
    files.emplace_back("pockets.cxc", chimerax_script(run, *scene));
  }
  const alpha::AlphaComplex& ac = run.search.shape->complex();
  const Cavities& cavities = run.search.cavities;
  if (selection_.pdb) {
    PocketPdb pdb = pocket_pdb(ac, cavities, "alphapocket " + run.options.version + " pockets of " + run.file);
    if (pdb.left_out > 0)
      warnings_.push_back("pockets.pdb: " + std::to_string(pdb.left_out) +
                          " pseudo-atoms left out, beyond the PDB columns' range (report.json has every cavity)");
    files.emplace_back("pockets.pdb", std::move(pdb.text));
  }
  if (selection_.tunnels) {
    files.emplace_back("tunnels.csv", tunnels_csv(run));
    files.emplace_back("tunnel_profiles.csv", tunnel_profiles_csv(run));
    PocketPdb tunnels = tunnel_pdb(run.cycle_paths, run.paths,
                                   "alphapocket " + run.options.version + " tunnels of " + run.file);
    if (tunnels.left_out > 0)
      warnings_.push_back("tunnels.pdb: " + std::to_string(tunnels.left_out) +
                          " pseudo-atoms left out, beyond the PDB columns' range");
    files.emplace_back("tunnels.pdb", std::move(tunnels.text));
  }
  const PocketMeshes* meshes = nullptr;  // those written
  if (selection_.meshes && run.meshes) {
    meshes = &*run.meshes;
    std::vector<std::string> names;
    const auto mesh_file = [&](const std::string& name, const TriangleMesh& mesh) {
      MeshFileContent file = mesh_file_content((path_ / name).string(), mesh);
      files.emplace_back(name, std::move(file.bytes));
      if (!file.companion_path.empty())
        files.emplace_back(fs::relative(file.companion_path, path_).string(), std::move(file.companion));
      names.push_back(fs::path(name).filename().string());
    };
    mesh_file(molecule_mesh_path(run.mesh_format()), meshes->surface);
    for (std::size_t i = 0; i < meshes->pockets.size(); ++i)
      mesh_file(cavity_mesh_path("pocket", i + 1, run.mesh_format()), meshes->pockets[i]);
    for (std::size_t i = 0; i < meshes->voids.size(); ++i)
      mesh_file(cavity_mesh_path("void", i + 1, run.mesh_format()), meshes->voids[i]);
    files.emplace_back(kMeshlabProject, meshlab_project(names));
  }
  if (selection_.html) {
    const nlohmann::ordered_json mvs = molviewspec_scene(run, *scene, "structure.cif", meshes);
    files.emplace_back("scene.mvsj", mvs.dump(1, '\t', false, nlohmann::ordered_json::error_handler_t::replace));
    std::vector<std::string> names{"report.html"};
    for (const auto& f : files) names.push_back(f.first);
    if (viewer_.empty()) {
      for (const auto& [name, path] : molstar_files()) copies.emplace_back(std::string(kViewerDir) + "/" + name, path);
      for (const char* name : {"report.js", "report.css"})
        files.emplace_back(std::string(kViewerDir) + "/" + name, page_asset(name));
    }
    files.emplace_back("report.html", report_page(run, mvs, copy->cif, names,
                                                  viewer_.empty() ? std::string(kViewerDir) : viewer_));
  }

  check_ours();  // again: files may have appeared while the run worked
  StagedDirectory staged(target_, path_.string(), temporaries_);
  std::vector<std::string> written;
  for (const auto& [name, content] : files) {
    staged.write(name, content);
    written.push_back(name);
  }
  for (const auto& [name, source] : copies) {
    staged.copy(name, source);
    written.push_back(name);
  }
  staged.commit();
  return written;
}

void remove_pocket_outputs(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return;
  for (const char* name : kOurFiles) fs::remove(fs::path(path) / name, ec);
  for (const auto& entry : fs::directory_iterator(fs::path(path) / kViewerDir, ec))
    if (is_our_viewer_file(entry.path().filename().string())) fs::remove(entry.path(), ec);
  fs::remove(fs::path(path) / kViewerDir, ec);  // only when empty
  for (const auto& entry : fs::directory_iterator(fs::path(path) / "meshes", ec))
    if (is_our_mesh(entry.path().filename().string())) fs::remove(entry.path(), ec);
  fs::remove(fs::path(path) / "meshes", ec);  // only when empty
  fs::remove(path, ec);
}

}  // namespace molecule
