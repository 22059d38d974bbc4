// SPDX-License-Identifier: Apache-2.0
#include "outputs/chimerax_script.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "outputs/pocket_colors.hpp"
#include "util/safe_text.hpp"

namespace molecule {
namespace {

// rgb(r,g,b): a colour no atom spec can be read into (unlike #rrggbb).
std::string rgb(Rgb c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "rgb(%d,%d,%d)", c.r, c.g, c.b);
  return buf;
}

// Atoms of model #1 by serial number (ids not empty): "(#1 &
// @@serial_number>=12 & @@serial_number<=15) | (#1 & @@serial_number=20)".
std::string atoms_spec(const std::vector<std::size_t>& ids) {
  std::string s;
  for (const auto& [first, last] : id_runs(ids)) {
    if (!s.empty()) s += " | ";
    s += first == last ? "(#1 & @@serial_number=" + std::to_string(first) + ")"
                       : "(#1 & @@serial_number>=" + std::to_string(first) + " & @@serial_number<=" +
                             std::to_string(last) + ")";
  }
  return s;
}

std::string marker(const std::string& model, const SinkSphere& sphere, Rgb color) {
  const alpha::Vec3& p = sphere.center;
  return "marker " + model + " position " + script_number(p.x) + "," + script_number(p.y) + "," + script_number(p.z) + " color " +
         rgb(color) + " radius " + script_number(std::max(sphere.radius, 0.05)) + "\n";
}

std::string header(const PocketRun& run, const ViewerScene& scene) {
  // No ';' in a comment: ChimeraX separates commands there.
  std::string s = "# alphapocket " + printable_ascii(run.options.version, ";") + ": pockets of " +
                  printable_ascii(run.file, ";") + "\n";
  s += "# Open with `chimerax pockets.cxc` or `open pockets.cxc` in ChimeraX. Model #1 is structure.cif\n";
  s += "# (" + scene.object + ": the atoms searched and the ligands). Coloured by site rank (report.json sites).\n";
  s += "# pocket_N names the atoms lining pocket N (void_N likewise). #2 holds the cavities' spaces (spheres\n";
  s += "# at their sinks), #3 their centres, #4 the tunnels' bottlenecks (cyan), #5 the tunnels and pores\n";
  s += "# with a path as spheres of their radius profile (tunnel_N_path, shades of cyan, tunnel_N names the\n";
  s += "# lining residues). Sites after the " + std::to_string(kShownSites) + "th are hidden.\n";
  s += "# pocket_N_cast is the cast of its space as the molecular surface bounds it (meshes/, when written\n";
  s += "# as OBJ or STL: --mesh obj), transparent, in its colour.\n";
  return s;
}

std::string structure(const ViewerScene& scene) {
  std::string s = "open structure.cif\n";
  s += "rename #1 " + scene.object + "\n";
  s += "hide #1 atoms\n";
  s += "show #1 cartoons\n";
  s += "color #1 " + rgb(kMoleculeColor) + "\n";
  if (!scene.ligand_ids.empty()) {
    s += "name ligands " + atoms_spec(scene.ligand_ids) + "\n";
    s += "show ligands atoms\n";
    s += "style ligands stick\n";
    s += "color ligands byhetero\n";
    s += "color ligands & C " + rgb(kLigandColor) + "\n";
  }
  s += "surface #1\n";
  s += "color #1 rgb(179,179,179) target s\n";
  s += "transparency #1 75 target s\n";
  return s;
}

std::string cavities(const ViewerScene& scene) {
  std::string s;
  for (std::size_t k = 0; k < scene.cavities.size(); ++k) {
    const SceneCavity& c = scene.cavities[k];
    const std::string space = "#2." + std::to_string(k + 1), center = "#3." + std::to_string(k + 1);
    s += "name " + c.name + " " + atoms_spec(c.lining_ids) + "\n";
    for (const SinkSphere& sphere : c.space) s += marker(space, sphere, c.color);
    s += marker(center, {c.center, 0.4}, c.color);
    if (!c.space.empty()) s += "rename " + space + " " + c.name + "_space\n";
    s += "rename " + center + " " + c.name + "_center\n";
  }
  // Worst site first: the best one's colour is the one left on shared atoms.
  for (std::size_t k = scene.cavities.size(); k-- > 0;) {
    const SceneCavity& c = scene.cavities[k];
    if (c.shown) {
      s += "show " + c.name + " atoms\n";
      s += "style " + c.name + " stick\n";
      s += "color " + c.name + " & C " + rgb(c.color) + "\n";
    } else {
      if (!c.space.empty()) s += "hide #2." + std::to_string(k + 1) + " models\n";
      s += "hide #3." + std::to_string(k + 1) + " models\n";
    }
  }
  if (!scene.cavities.empty()) {
    s += "transparency #2 15 target a\n";
  }
  return s;
}

std::string tunnels(const ViewerScene& scene) {
  std::string s;
  for (std::size_t k = 0; k < scene.tunnels.size(); ++k) {
    const SceneTunnel& t = scene.tunnels[k];
    const std::string model = "#4." + std::to_string(k + 1);
    s += "name " + t.name + " " + atoms_spec(t.lining_ids) + "\n";
    s += marker(model, t.bottleneck, kTunnelColor);
    s += "rename " + model + " " + t.name + "_bottleneck\n";
  }
  if (!scene.tunnels.empty()) s += "transparency #4 50 target a\n";
  for (std::size_t k = 0; k < scene.paths.size(); ++k) {
    const ScenePath& p = scene.paths[k];
    const std::string model = "#5." + std::to_string(k + 1);
    if (!p.lining_ids.empty()) s += "name " + p.name + " " + atoms_spec(p.lining_ids) + "\n";
    for (const SinkSphere& sphere : p.spheres) s += marker(model, sphere, p.color);
    if (!p.spheres.empty()) s += "rename " + model + " " + p.name + "_path\n";
  }
  if (!scene.paths.empty()) s += "transparency #5 30 target a\n";
  return s;
}

// Each cavity's cast, where the meshes are in a format ChimeraX opens (OBJ
// or STL; not PLY or OFF): opened last, each as the lowest free model id
// after those made above (#1, #2 and #3 with cavities, #4 with tunnels, #5
// with tunnel paths),
// renamed after its cavity, transparent, in its colour.
std::string casts(const ViewerScene& scene) {
  std::vector<bool> taken{true, true, false, !scene.cavities.empty(), !scene.tunnels.empty(),
                          !scene.paths.empty()};  // [0]: no id
  for (const SceneCavity& c : scene.cavities) taken[2] = taken[2] || !c.space.empty();
  std::string s;
  std::size_t id = 1;
  for (const SceneCavity& c : scene.cavities) {
    const std::string ext = std::filesystem::path(c.cast).extension().string();
    if (ext != ".obj" && ext != ".stl") continue;
    while (id < taken.size() && taken[id]) ++id;
    const std::string model = "#" + std::to_string(id++);
    s += "open " + c.cast + "\n";
    s += "rename " + model + " " + c.name + "_cast\n";
    s += "color " + model + " " + rgb(c.color) + "\n";
    s += "transparency " + model + " 40 target s\n";
    if (!c.shown) s += "hide " + model + " models\n";
  }
  return s;
}

std::string view(const ViewerScene& scene) {
  if (scene.cavities.empty() || scene.cavities.front().site_rank != 1) return "view #1\n";
  return "view " + scene.cavities.front().name + " | #3.1\n";
}

}  // namespace

std::string chimerax_script(const PocketRun& run, const ViewerScene& scene) {
  return header(run, scene) + structure(scene) + cavities(scene) + tunnels(scene) + casts(scene) + view(scene);
}

}  // namespace molecule
