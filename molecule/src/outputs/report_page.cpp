// SPDX-License-Identifier: Apache-2.0
#include "outputs/report_page.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <map>
#include <set>

#include "molecule/residues.hpp"
#include "outputs/pocket_colors.hpp"
#include "outputs/report_numbers.hpp"
#include "outputs/result_entries.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;
// Coordinates and radii as report.json rounds lengths.
using report_number::length;

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02X%02X%02X", c.r, c.g, c.b);
  return buf;
}

json point(const alpha::Vec3& p) { return {length(p.x), length(p.y), length(p.z)}; }

json node(const std::string& kind, json params = json::object(), json children = json::array()) {
  json n = {{"kind", kind}};
  if (!params.empty()) n["params"] = std::move(params);
  if (!children.empty()) n["children"] = std::move(children);
  return n;
}

json atom_selector(const std::vector<std::size_t>& ids) {
  json s = json::array();
  for (const std::size_t id : ids) s.push_back({{"atom_id", id}});
  return s;
}

// A component drawn as `type` in one colour.
json drawn(const json& selector, const std::string& type, const std::string& color, double opacity = 1,
           const std::string& tooltip = "") {
  json rep = node("representation", {{"type", type}}, json::array({node("color", {{"color", color}})}));
  if (opacity < 1) rep["children"].push_back(node("opacity", {{"opacity", opacity}}));
  json component = node("component", {{"selector", selector}}, json::array({std::move(rep)}));
  if (!tooltip.empty()) component["children"].push_back(node("tooltip", {{"text", tooltip}}));
  return component;
}

// AlphaFold DB's confidence bands: very high, confident, low, very low.
std::string plddt_color(double plddt) {
  if (plddt >= 90) return "#0053D6";
  if (plddt >= 70) return "#65CBF3";
  if (plddt >= 50) return "#FFDB13";
  return "#FF7D45";
}

// The cartoon: grey, or by pLDDT band for a predicted model (atom ids of
// structure.cif: atom i is id i + 1).
json cartoon(const Structure& structure) {
  json rep = node("representation", {{"type", "cartoon"}}, json::array({node("color", {{"color", hex(kMoleculeColor)}})}));
  if (structure.report.predicted) {
    std::map<std::string, std::vector<std::size_t>> bands;
    for (std::size_t i = 0; i < structure.atoms.size(); ++i)
      bands[plddt_color(structure.atoms[i].b_factor)].push_back(i + 1);
    for (const auto& [color, ids] : bands)
      rep["children"].push_back(node("color", {{"color", color}, {"selector", atom_selector(ids)}}));
  }
  return node("component", {{"selector", "polymer"}}, json::array({std::move(rep)}));
}

json sphere(const SinkSphere& s, const std::string& color) {
  return node("primitive", {{"kind", "ellipsoid"}, {"center", point(s.center)}, {"radius", length(s.radius)}, {"color", color}});
}

json cast(const TriangleMesh& mesh, const std::string& color) {
  json vertices = json::array(), indices = json::array();
  for (const alpha::Vec3& p : mesh.points)
    for (const double x : {p.x, p.y, p.z}) vertices.push_back(length(x));
  for (const auto& t : mesh.triangles)
    for (const alpha::Index i : t) indices.push_back(i);
  return node("primitive", {{"kind", "mesh"}, {"vertices", std::move(vertices)}, {"indices", std::move(indices)},
                            {"color", color}});
}

// The ids (residue_id) of the residues given by their first atoms (residues_of).
json residue_ids(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& residues) {
  json out = json::array();
  for (const alpha::Index i : residues) out.push_back(residue_id(atoms[i]));
  return out;
}

// The tables' data, numbers as report.json has them: the sites with their
// cavity's MS volume, depth and mouths, the tunnels (tunnel_entries), the
// ligands, and report.json's input, parameters and molecule.
json page_data(const PocketRun& run) {
  const Structure& st = run.structure;
  json sites = json::array();
  for (const SiteEntry& s : site_entries(run)) {
    const Cavity& c = *s.cavity;
    sites.push_back({{"rank", s.rank},
                     {"kind", s.kind},
                     {"cavity_rank", s.cavity_rank},
                     {"probability", report_probability(c.probability)},
                     {"score", report_number::score(c.score)},
                     {"sa_volume", length(c.sa_volume)},
                     {"ms_volume", length(c.ms_volume)},
                     {"depth", length(c.depth)},
                     {"mouths", c.mouths.size()},
                     {"mean_plddt", s.mean_plddt},
                     {"center", point(s.center)},
                     {"residues", residue_ids(st.atoms, s.residues)},
                     {"ligands", s.ligands}});
  }
  json tunnels = json::array();
  for (const TunnelEntry& t : tunnel_entries(run))
    tunnels.push_back({{"rank", t.rank},
                       {"kind", t.kind},
                       {"bottleneck_radius", length(t.bottleneck_radius)},
                       {"bottleneck_center", point(t.bottleneck)},
                       {"length", t.length},
                       {"profile", t.way ? report_profile(*t.way) : json::array()},
                       {"residues", residue_ids(st.atoms, t.residues)}});
  json ligands = json::array();
  for (const LigandSite& l : run.ligands) {
    const HeteroGroup& g = st.hetero_groups.at(l.group);
    LigandPlace place = ligand_place(g, l);
    ligands.push_back({{"id", ligand_id(g)},
                       {"kept", g.kept},
                       {"site", std::move(place.site)},
                       {"nearest_site", std::move(place.nearest_site)},
                       {"distance", std::move(place.distance)}});
  }
  return {{"file", run.file},
          {"alphapocket", run.options.version},
          {"input", report_input(run)},
          {"parameters", report_parameters(run)},
          {"molecule", report_molecule(run)},
          {"sites", std::move(sites)},
          {"tunnels", std::move(tunnels)},
          {"ligands", std::move(ligands)}};
}

}  // namespace

json molviewspec_scene(const PocketRun& run, const ViewerScene& scene, const std::string& structure_url,
                       const PocketMeshes* meshes) {
  const Structure& structure = run.structure;
  // Each lining atom's whole residue, as the scripts show it.
  std::map<std::string, std::vector<std::size_t>> residue_atoms;
  std::vector<std::string> residue_of(structure.atoms.size());
  for (std::size_t i = 0; i < structure.atoms.size(); ++i) {
    residue_of[i] = residue_id(structure.atoms[i]);
    residue_atoms[residue_of[i]].push_back(i + 1);
  }
  const auto whole_residues = [&](const std::vector<std::size_t>& ids) {
    std::set<std::string> seen;
    std::vector<std::size_t> out;
    for (const std::size_t id : ids)
      if (id <= structure.atoms.size() && seen.insert(residue_of[id - 1]).second) {
        const auto& atoms = residue_atoms[residue_of[id - 1]];
        out.insert(out.end(), atoms.begin(), atoms.end());
      }
    std::sort(out.begin(), out.end());
    return out;
  };

  json model = node("structure", {{"type", "model"}});
  json& parts = model["children"] = json::array();
  parts.push_back(cartoon(structure));
  parts.push_back(drawn("polymer", "surface", hex(kMoleculeColor), 0.25));
  if (!scene.ligand_ids.empty()) {
    json ligands = drawn(atom_selector(scene.ligand_ids), "ball_and_stick", hex(kLigandColor));
    parts.push_back(std::move(ligands));
  }
  json spaces = json::array();
  for (const SceneCavity& c : scene.cavities) {
    if (c.site_rank == 0) continue;
    const std::string color = hex(c.color), name = "site " + std::to_string(c.site_rank) + " (" + c.name + ")";
    // refs name the site's nodes for report.js, which fades the other sites while one is focused.
    const std::string ref = "site-" + std::to_string(c.site_rank);
    if (c.shown) {
      json lining = drawn(atom_selector(whole_residues(c.lining_ids)), "ball_and_stick", color, 1, name);
      lining["ref"] = ref + "-lining";
      parts.push_back(std::move(lining));
    }
    json group = node("primitives", {{"color", color}, {"opacity", c.site_rank == 1 ? 0.9 : 0.6}, {"tooltip", name}});
    group["ref"] = ref;
    json& shapes = group["children"] = json::array();
    const bool is_void = c.name.rfind("void_", 0) == 0;
    const std::size_t index = std::stoul(c.name.substr(c.name.find('_') + 1)) - 1;
    const std::vector<TriangleMesh>* casts = meshes ? (is_void ? &meshes->voids : &meshes->pockets) : nullptr;
    if (casts && index < casts->size() && !(*casts)[index].triangles.empty())
      shapes.push_back(cast((*casts)[index], color));
    else
      for (const SinkSphere& s : c.space) shapes.push_back(sphere(s, color));
    if (!shapes.empty() && c.shown) spaces.push_back(std::move(group));
  }
  json root = node("root");
  json& top = root["children"] = json::array();
  top.push_back(node("canvas", {{"background_color", "white"}}));
  top.push_back(node("download", {{"url", structure_url}},
                     json::array({node("parse", {{"format", "mmcif"}}, json::array({std::move(model)}))})));
  for (json& s : spaces) top.push_back(std::move(s));
  for (const ScenePath& p : scene.paths) {
    json group = node("primitives", {{"color", hex(p.color)}, {"opacity", 0.7}, {"tooltip", p.name}});
    group["ref"] = "path-" + p.name.substr(p.name.find('_') + 1);  // hidden while a site is focused
    json& shapes = group["children"] = json::array();
    for (const SinkSphere& s : p.spheres) shapes.push_back(sphere(s, hex(p.color)));
    if (!shapes.empty()) top.push_back(std::move(group));
  }
  // Named where the ligand is: its heavy atoms' mean.
  json labels = node("primitives", {{"label_color", "black"}});
  json& texts = labels["children"] = json::array();
  for (const HeteroGroup& g : structure.hetero_groups) {
    alpha::Vec3 sum{0, 0, 0};
    for (const Atom& a : g.atoms) sum = sum + a.position;
    const double n = double(g.atoms.size());
    const std::string id = g.chain + ':' + g.residue_name + ':' + std::to_string(g.seq_num);
    texts.push_back(node("primitive", {{"kind", "label"}, {"position", point({sum.x / n, sum.y / n, sum.z / n})},
                                       {"text", id}, {"label_size", 1.5}}));
  }
  if (!texts.empty()) top.push_back(std::move(labels));
  return {{"metadata", {{"version", "1"}, {"title", "alphapocket " + run.options.version + ": sites of " + run.file}}},
          {"root", std::move(root)}};
}

std::string script_json(const json& value) {
  const std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (c == '<') out += "\\u003c";
    else if (c == '>') out += "\\u003e";
    else if (c == '&') out += "\\u0026";
    else out += c;
  }
  return out;
}

std::string html_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string report_page(const PocketRun& run, const json& mvs, const std::string& structure_cif,
                        const std::vector<std::string>& files, const std::string& viewer) {
  const std::string at = html_text(viewer) + "/";
  json data = page_data(run);
  data["files"] = files;
  data["mvs"] = mvs;
  data["structure"] = structure_cif;
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<title>alphapocket: " + html_text(run.file) + "</title>\n";
  page += "<link rel=\"stylesheet\" href=\"" + at + "molstar.css\">\n<link rel=\"stylesheet\" href=\"" + at + "report.css\">\n";
  page += "</head>\n<body>\n<noscript>This page needs JavaScript; report.json holds the same results.</noscript>\n";
  page += "<script type=\"application/json\" id=\"alphapocket-data\">" + script_json(data) + "</script>\n";
  page += "<script src=\"" + at + "molstar.js\"></script>\n<script src=\"" + at + "report.js\"></script>\n";
  page += "</body>\n</html>\n";
  return page;
}

}  // namespace molecule
