// SPDX-License-Identifier: Apache-2.0
#include "outputs/pocket_report.hpp"

#include <cmath>

#include "molecule/residues.hpp"
#include "outputs/report_numbers.hpp"
#include "outputs/result_entries.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;  // keys in the documented order

using report_number::length;
using report_number::score;

json point(const alpha::Vec3& p) { return json::array({length(p.x), length(p.y), length(p.z)}); }

json lining_atoms(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& indices) {
  json out = json::array();
  for (const alpha::Index i : indices) {
    const Atom& a = atoms.at(i);
    out.push_back({{"serial", a.serial}, {"name", a.name}, {"element", a.element}, {"residue", residue_id(a)}});
  }
  return out;
}

// The residues given by their first atoms (residues_of).
json lining_residues(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& residues) {
  json out = json::array();
  for (const alpha::Index i : residues) {
    const Atom& a = atoms[i];
    out.push_back({{"id", residue_id(a)},
                   {"chain", a.chain},
                   {"name", a.residue_name},
                   {"number", a.seq_num},
                   {"insertion_code", icode_text(a.icode)}});
  }
  return out;
}

json cavity_entry(const PocketRun& run, const Cavity& c, std::size_t rank, const std::string& kind) {
  const std::vector<Atom>& atoms = run.structure.atoms;
  json mouth_areas = json::array();
  std::size_t mouths_to_outside = 0;
  for (const Mouth& m : c.mouths) {
    mouth_areas.push_back(length(m.area));
    mouths_to_outside += m.to_outside;
  }
  json e = {
      {"rank", rank},
      {"score", score(c.score)},
      {"probability", report_probability(c.probability)},
      {"sa_volume", length(c.sa_volume)},
      {"sa_area", length(c.sa_area)},
      {"ms_volume", length(c.ms_volume)},
      {"ms_area", length(c.ms_area)},
      {"mouths", c.mouths.size()},
      {"mouths_to_outside", mouths_to_outside},
      {"mouth_areas", std::move(mouth_areas)},
      {"mouth_area", length(c.mouth_area)},
      {"buriedness", score(c.buriedness)},
      {"burial_atoms", c.burial_atoms},
      {"depth", length(c.depth)},
      {"center", point(c.center)},
      {"tetrahedra", c.cells.size()},
      {"max_alpha_sq", c.max_alpha_sq},
      {"max_probe_radius", length(c.max_probe_radius)},
      {"close_alpha_sq", c.close_alpha_sq},
      {"fill_alpha_sq", c.fill_alpha_sq},
      {"mean_plddt", mean_plddt(run.structure, c.lining_atoms)},
      {"lining_atoms", lining_atoms(atoms, c.lining_atoms)},
      {"lining_residues", lining_residues(atoms, residues_of(atoms, c.lining_atoms))},
  };
  if (!run.mesh_format().empty()) e["mesh"] = cavity_mesh_path(kind, rank, run.mesh_format());
  return e;
}

json cavity_list(const PocketRun& run, const std::vector<Cavity>& list, const std::string& kind) {
  json out = json::array();
  for (std::size_t i = 0; i < list.size(); ++i) out.push_back(cavity_entry(run, list[i], i + 1, kind));
  return out;
}

json holding(const LigandSite& l) {
  json out = json::array();
  for (const auto& [rank, atoms] : l.holding) out.push_back({{"site", rank}, {"atoms", atoms}});
  return out;
}

// Every hetero group with the site that holds it (molecule/ligand_sites.hpp).
json ligand_list(const PocketRun& run) {
  json out = json::array();
  for (const LigandSite& l : ligands_of(run)) {
    const HeteroGroup& g = run.structure.hetero_groups.at(l.group);
    LigandPlace place = ligand_place(g, l);
    out.push_back({{"id", ligand_id(g)},
                   {"name", g.residue_name},
                   {"chain", g.chain},
                   {"number", g.seq_num},
                   {"insertion_code", icode_text(g.icode)},
                   {"heavy_atoms", g.atoms.size()},
                   {"kept", g.kept},
                   {"site", std::move(place.site)},
                   {"nearest_site", std::move(place.nearest_site)},
                   {"distance", std::move(place.distance)},
                   {"atoms_in_site", l.atoms_in_site},
                   {"in_sites", holding(l)}});
  }
  return out;
}

// The binding-site ranking: which pocket or void each site is (its rank in
// that list), with the score, centre and lining residues repeated for
// scripts, and the ids of the hetero groups it holds.
json site_list(const PocketRun& run) {
  json out = json::array();
  for (const SiteEntry& s : site_entries(run)) {
    const Cavity& c = *s.cavity;
    out.push_back({{"rank", s.rank},
                   {"kind", s.kind},
                   {"cavity_rank", s.cavity_rank},
                   {"score", score(c.score)},
                   {"probability", report_probability(c.probability)},
                   {"sa_volume", length(c.sa_volume)},
                   {"center", point(s.center)},
                   {"mean_plddt", s.mean_plddt},
                   {"lining_residues", lining_residues(run.structure.atoms, s.residues)},
                   {"ligands", s.ligands}});
  }
  return out;
}

// The keys of each kind in the documented order.
json tunnel_entry(const std::vector<Atom>& atoms, const TunnelEntry& t) {
  if (t.is_cycle())
    return {{"rank", t.rank},
            {"kind", t.kind},
            {"birth_alpha_sq", t.birth_alpha_sq},
            {"death_alpha_sq", t.death_alpha_sq},
            {"bottleneck_radius", length(t.bottleneck_radius)},
            {"bottleneck_center", point(t.bottleneck)},
            {"length", t.length},
            {"path", t.path},
            {"profile", t.way ? report_profile(*t.way) : json::array()},
            {"lining_atoms", lining_atoms(atoms, *t.lining_atoms)},
            {"lining_residues", lining_residues(atoms, t.residues)}};
  return {{"rank", t.rank},
          {"kind", t.kind},
          {"start", t.start},
          {"bottleneck_radius", length(t.bottleneck_radius)},
          {"bottleneck_center", point(t.bottleneck)},
          {"length", t.length},
          {"curvature", t.curvature},
          {"cost", t.cost},
          {"start_point", point(t.way->start_point)},
          {"mouth", point(t.way->mouth)},
          {"profile", report_profile(*t.way)},
          {"lining_residues", lining_residues(atoms, t.residues)}};
}

json tunnel_list(const PocketRun& run) {
  json out = json::array();
  for (const TunnelEntry& t : tunnel_entries(run)) out.push_back(tunnel_entry(run.structure.atoms, t));
  return out;
}

}  // namespace

std::string cavity_mesh_path(const std::string& kind, std::size_t rank, const std::string& format) {
  return "meshes/" + kind + "_" + std::to_string(rank) + "." + format;
}

std::string molecule_mesh_path(const std::string& format) { return "meshes/surface." + format; }

json report_input(const PocketRun& run) {
  const StructureReport& r = run.structure.report;
  return {
      {"file", run.file},
      {"format", r.format},
      {"gzipped", r.gzipped},
      {"predicted", r.predicted},
      {"model", r.model},
      {"atoms_in_model", r.atoms_in_model},
      {"atoms_kept", r.kept},
      {"atoms_dropped",
       {{"chain", r.dropped_chain},
        {"altloc", r.dropped_altloc},
        {"water", r.dropped_water},
        {"hetero", r.dropped_hetero},
        {"hydrogen", r.dropped_hydrogen},
        {"plddt", r.dropped_plddt}}},
      {"hetero_groups", r.hetero_groups},
      {"warnings", r.warnings},
  };
}

json report_parameters(const PocketRun& run) {
  return {
      {"probe", run.options.cavities.probe},
      {"min_volume", run.options.cavities.min_volume},
      {"split_persistence", run.options.cavities.split_persistence},
      {"split_volume", run.options.cavities.split_volume},
      {"split_min_volume", run.options.cavities.split_min_volume},
      {"min_plddt", run.options.structure.min_plddt},
      {"radii", run.radii()},
      {"tunnels_from", run.options.tunnels_from},
      {"tunnel_probe", run.options.tunnels.probe},
      {"pores", run.options.tunnels.pores},
      {"alpha_sq", 0.0},
  };
}

json report_molecule(const PocketRun& run) {
  json molecule = {{"atoms", run.structure.atoms.size()},
                   {"sa_area", length(run.search.cavities.sa_area)},
                   {"sa_volume", length(run.search.cavities.sa_volume)},
                   {"pockets", run.search.cavities.pockets.size()},
                   {"voids", run.search.cavities.voids.size()},
                   {"sites", run.search.cavities.sites.size()},
                   {"tunnels", run.search.cavities.tunnels.size()},
                   {"mean_plddt", mean_plddt(run.structure)},
                   {"tunnel_paths", run.paths.size()}};
  if (!run.mesh_format().empty()) molecule["mesh"] = molecule_mesh_path(run.mesh_format());
  return molecule;
}

LigandPlace ligand_place(const HeteroGroup& g, const LigandSite& l) {
  const auto rank = [](std::size_t r) { return r ? json(r) : json(nullptr); };
  return {rank(l.site), g.kept ? json(nullptr) : rank(l.nearest_site),
          g.kept || !l.nearest_site ? json(nullptr) : json(length(l.distance))};
}

json report_profile(const TunnelPath& p) {
  json out = json::array();
  for (const ProfilePoint& q : p.profile) out.push_back({length(q.x.x), length(q.x.y), length(q.x.z), length(q.radius)});
  return out;
}

json pocket_report(const PocketRun& run) {
  return {
      {"alphapocket", run.options.version},
      {"input", report_input(run)},
      {"parameters", report_parameters(run)},
      {"molecule", report_molecule(run)},
      {"pockets", cavity_list(run, run.search.cavities.pockets, "pocket")},
      {"voids", cavity_list(run, run.search.cavities.voids, "void")},
      {"sites", site_list(run)},
      {"ligands", ligand_list(run)},
      {"tunnels", tunnel_list(run)},
  };
}

std::string report_file_text(const nlohmann::ordered_json& report) {
  return report.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace molecule
