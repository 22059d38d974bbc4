// SPDX-License-Identifier: Apache-2.0
#include "outputs/viewer_scene.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string_view>

#include "alpha/sizes.hpp"
#include "molecule/residues.hpp"
#include "outputs/pocket_colors.hpp"

namespace molecule {
namespace {

// Names PyMOL or ChimeraX read as something else, and our own objects'.
bool reserved(std::string_view name) {
  static constexpr std::array<std::string_view, 14> kWords{"all",     "none",    "sele",   "enabled", "visible",
                                                          "center",  "origin",  "ligands", "spaces",  "centers",
                                                          "tunnels", "cavities", "same",   "structure"};
  std::string lower(name);
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  return std::find(kWords.begin(), kWords.end(), lower) != kWords.end() || lower.rfind("pocket_", 0) == 0 ||
         lower.rfind("void_", 0) == 0 || lower.rfind("tunnel_", 0) == 0 || lower.rfind("ap_", 0) == 0;
}

std::vector<std::size_t> ids_of(const std::vector<alpha::Index>& atoms) {
  std::vector<std::size_t> ids;
  for (const alpha::Index i : atoms) ids.push_back(std::size_t(i) + 1);  // structure_copy's ids
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace

std::string viewer_object_name(const std::string& file) {
  std::string stem = std::filesystem::path(file).filename().string();
  stem = stem.substr(0, stem.find('.'));
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  if (stem.empty()) return "structure";
  return reserved(stem) ? stem + "_molecule" : stem;
}

ViewerScene viewer_scene(const PocketRun& run, const std::vector<std::size_t>& ligand_ids) {
  const Cavities& cavities = run.search.cavities;
  const alpha::AlphaComplex& ac = run.search.shape->complex();
  const CavityColors colors = cavity_colors(cavities);
  ViewerScene scene;
  scene.object = viewer_object_name(run.file);
  scene.ligand_ids = ligand_ids;
  const auto add = [&](bool is_void, std::size_t index, std::size_t site_rank) {
    const Cavity& c = is_void ? cavities.voids.at(index) : cavities.pockets.at(index);
    SceneCavity s;
    s.name = std::string(is_void ? "void_" : "pocket_") + std::to_string(index + 1);
    s.site_rank = site_rank;
    s.color = (is_void ? colors.voids : colors.pockets).at(index);
    s.shown = site_rank >= 1 && site_rank <= kShownSites;
    s.lining_ids = ids_of(c.lining_atoms);
    s.center = c.center;
    s.space = sink_spheres(ac, c);
    if (!run.mesh_format().empty())
      s.cast = cavity_mesh_path(is_void ? "void" : "pocket", index + 1, run.mesh_format());
    scene.cavities.push_back(std::move(s));
  };
  // In colour-rank order: the sites, then the pockets and voids that are no site.
  const CavityRanks ranks = cavity_ranks(cavities);
  std::vector<std::pair<bool, std::size_t>> order(ranks.pockets.size() + ranks.voids.size());
  for (const bool is_void : {false, true}) {
    const std::vector<std::size_t>& list = is_void ? ranks.voids : ranks.pockets;
    for (std::size_t i = 0; i < list.size(); ++i) order.at(list[i] - 1) = {is_void, i};
  }
  for (std::size_t k = 0; k < order.size(); ++k)
    add(order[k].first, order[k].second, k < cavities.sites.size() ? k + 1 : 0);
  for (std::size_t i = 0; i < cavities.tunnels.size(); ++i) {
    const Tunnel& t = cavities.tunnels[i];
    scene.tunnels.push_back({"tunnel_" + std::to_string(i + 1), ids_of(t.lining_atoms),
                             {t.bottleneck_center, t.bottleneck_radius}});
  }
  const std::vector<Atom>& atoms = run.structure.atoms;
  // Each atom's residue once, not once a path.
  std::vector<std::string> residue_of(atoms.size());
  if (!run.paths.empty())
    for (std::size_t i = 0; i < atoms.size(); ++i) residue_of[i] = residue_id(atoms[i]);
  for (std::size_t k = 0; k < run.paths.size(); ++k) {
    const TunnelPath& p = run.paths[k];
    ScenePath path{"tunnel_" + std::to_string(cavities.tunnels.size() + k + 1), tunnel_color(k), {}, {}};
    std::set<std::string> residues;
    for (const alpha::Index i : p.lining_atoms) residues.insert(residue_of.at(i));
    for (std::size_t i = 0; i < atoms.size(); ++i)
      if (residues.count(residue_of[i])) path.lining_ids.push_back(i + 1);  // structure_copy's ids
    for (const ProfilePoint& q : p.profile) path.spheres.push_back({q.x, q.radius});
    scene.paths.push_back(std::move(path));
  }
  return scene;
}

std::vector<std::pair<std::size_t, std::size_t>> id_runs(const std::vector<std::size_t>& ids) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (const std::size_t id : ids) {
    if (!runs.empty() && id == runs.back().second + 1)
      runs.back().second = id;
    else
      runs.emplace_back(id, id);
  }
  return runs;
}

std::string script_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", x);
  return buf;
}

}  // namespace molecule
