// SPDX-License-Identifier: Apache-2.0
#include "molecule/pymol_script.hpp"

#include <algorithm>
#include <cstdio>

#include "molecule/pocket_colors.hpp"
#include "molecule/safe_text.hpp"

namespace molecule {
namespace {

// Atom-id runs per "select" line: keeps lines short for PyMOL's parser.
constexpr std::size_t kRunsPerLine = 40;

std::string rgb(Rgb c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "[%d, %d, %d]", c.r, c.g, c.b);
  return buf;
}

std::string position(const alpha::Vec3& p) {
  return "pos=[" + script_number(p.x) + ", " + script_number(p.y) + ", " + script_number(p.z) + "]";
}

// "select NAME, OBJ and id 12-15+20 ..." lines, kRunsPerLine runs a line.
std::string select_lines(const std::string& name, const std::string& obj, const std::vector<std::size_t>& ids) {
  const auto runs = id_runs(ids);
  if (runs.empty()) return "select " + name + ", none\n";
  std::string s;
  for (std::size_t k = 0; k < runs.size(); k += kRunsPerLine) {
    std::string part;
    for (std::size_t j = k; j < std::min(runs.size(), k + kRunsPerLine); ++j) {
      if (!part.empty()) part += '+';
      part += std::to_string(runs[j].first);
      if (runs[j].second > runs[j].first) part += '-' + std::to_string(runs[j].second);
    }
    s += "select " + name + ", " + (k == 0 ? "" : name + " or ") + "(" + obj + " and id " + part + ")\n";
  }
  return s;
}

// Each section writes one part of the scene.

std::string header(const PocketRun& run, const ViewerScene& scene) {
  // No ';' in a comment: PyMOL's parser splits a line there first.
  std::string s = "# alphapocket " + printable_ascii(run.version, ";") + ": pockets of " +
                  printable_ascii(run.file, ";") + "\n";
  s += "# Open with `pymol pockets.pml` (from any directory) or `@pockets.pml` inside PyMOL: it loads\n";
  s += "# structure.cif beside it as " + scene.object + " (the atoms searched and the ligands).\n";
  s += "# Coloured by site rank (report.json sites). pocket_N selects the atoms lining pocket N,\n";
  s += "# pocket_N_space is its space (spheres at its sinks), pocket_N_center its centre (void_N likewise).\n";
  s += "# Sites after the " + std::to_string(kShownSites) + "th are loaded but disabled. tunnel_N selects the atoms of\n";
  s += "# tunnel N's bottleneck, tunnel_N_bottleneck is the largest probe passing it (cyan). For tunnels\n";
  s += "# and pores with a path (report.json tunnels of kind tunnel or pore), tunnel_N selects the lining\n";
  s += "# residues and tunnel_N_path is the centreline as spheres of the radius profile (shades of cyan).\n";
  return s;
}

std::string structure(const ViewerScene& scene) {
  const std::string& obj = scene.object;
  std::string s;
  s += "/import os\n";
  s += "/cmd.load(os.path.join(os.path.dirname(os.path.abspath(globals().get(\"__script__\", \"pockets.pml\"))), "
       "\"structure.cif\"), \"" + obj + "\")\n";
  s += "hide everything\n";
  s += "bg_color white\n";
  s += select_lines("ligands", obj, scene.ligand_ids);
  s += "show cartoon, " + obj + "\n";
  s += "set cartoon_color, grey80, " + obj + "\n";
  s += "color grey80, " + obj + "\n";
  s += "show sticks, ligands\n";
  s += "color atomic, ligands\n";
  s += "color yellow, ligands and elem C\n";
  // A grey surface of its own colour (not the pockets' atoms'), light
  // enough to see the buried sites through it.
  s += "show surface, " + obj + " and not ligands\n";
  s += "set surface_color, grey70, " + obj + "\n";
  s += "set transparency, 0.75, " + obj + "\n";
  return s;
}

std::string cavities(const ViewerScene& scene) {
  std::string s;
  for (const SceneCavity& c : scene.cavities) {
    s += "set_color ap_" + c.name + ", " + rgb(c.color) + "\n";
    s += select_lines(c.name, scene.object, c.lining_ids);
    s += "pseudoatom " + c.name + "_center, " + position(c.center) + ", vdw=0.4\n";
    for (const SinkSphere& sphere : c.space)
      s += "pseudoatom " + c.name + "_space, " + position(sphere.center) + ", vdw=" + script_number(sphere.radius) + "\n";
    s += "color ap_" + c.name + ", " + c.name + "_*\n";
  }
  // Worst site first: the best one's colour is the one left on shared residues.
  for (auto c = scene.cavities.rbegin(); c != scene.cavities.rend(); ++c) {
    if (c->shown) {
      s += "show sticks, byres " + c->name + "\n";
      s += "color ap_" + c->name + ", byres " + c->name + " and elem C\n";
    }
  }
  if (!scene.cavities.empty()) {
    s += "show spheres, *_space or *_center\n";
    // The other sites' spheres see-through, so none hides the best one.
    for (const SceneCavity& c : scene.cavities) {
      if (c.site_rank != 1) s += "set sphere_transparency, 0.6, " + c.name + "_space\n";
      if (!c.shown) s += "disable " + c.name + "_space\ndisable " + c.name + "_center\n";
    }
    s += "group spaces, *_space\n";
    s += "group centers, *_center\n";
  }
  return s;
}

std::string tunnels(const ViewerScene& scene) {
  std::string s;
  for (const SceneTunnel& t : scene.tunnels) {
    s += select_lines(t.name, scene.object, t.lining_ids);
    s += "pseudoatom " + t.name + "_bottleneck, " + position(t.bottleneck.center) +
         ", vdw=" + script_number(t.bottleneck.radius) + "\n";
  }
  if (!scene.tunnels.empty()) {
    s += "set_color ap_tunnel, " + rgb(kTunnelColor) + "\n";
    s += "color ap_tunnel, tunnel_*_bottleneck\n";
    s += "show spheres, tunnel_*_bottleneck\n";
    s += "set sphere_transparency, 0.5, tunnel_*_bottleneck\n";
  }
  for (const ScenePath& p : scene.paths) {
    s += "set_color ap_" + p.name + ", " + rgb(p.color) + "\n";
    s += select_lines(p.name, scene.object, p.lining_ids);
    for (const SinkSphere& sphere : p.spheres)
      s += "pseudoatom " + p.name + "_path, " + position(sphere.center) + ", vdw=" + script_number(sphere.radius) + "\n";
    s += "color ap_" + p.name + ", " + p.name + "_path\n";
  }
  if (!scene.paths.empty()) {
    s += "show spheres, tunnel_*_path\n";
    s += "set sphere_transparency, 0.3, tunnel_*_path\n";
  }
  if (!scene.tunnels.empty() || !scene.paths.empty()) s += "group tunnels, tunnel_*_bottleneck tunnel_*_path\n";
  return s;
}

// The best site in the middle of the view.
std::string view(const ViewerScene& scene) {
  std::string s = "deselect\n";
  if (scene.cavities.empty() || scene.cavities.front().site_rank != 1) return s + "orient " + scene.object + "\n";
  const std::string& top = scene.cavities.front().name;
  // orient fills the view with it: zoom out to show its surroundings.
  return s + "orient " + top + "_space or byres " + top + "\nzoom " + top + "_space or byres " + top + ", 8\n";
}

}  // namespace

std::string pymol_script(const PocketRun& run, const ViewerScene& scene) {
  return header(run, scene) + structure(scene) + cavities(scene) + tunnels(scene) + view(scene);
}

}  // namespace molecule
