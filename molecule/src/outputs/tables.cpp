// SPDX-License-Identifier: Apache-2.0
#include "outputs/tables.hpp"

#include "molecule/residues.hpp"
#include "outputs/report_numbers.hpp"
#include "outputs/result_entries.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;
constexpr ColumnType T = ColumnType::Text, I = ColumnType::Integer, R = ColumnType::Real;

using report_number::length;
using report_number::score;

// The ids (residue_id) of the residues given by their first atoms
// (residues_of), one space between them.
std::string residue_words(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& residues) {
  std::string out;
  for (const alpha::Index i : residues) {
    if (!out.empty()) out += ' ';
    out += residue_id(atoms[i]);
  }
  return out;
}

// The lining_residues and residues columns: how many residues, and their ids.
std::string residue_columns(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& residues) {
  return ',' + std::to_string(residues.size()) + ',' + csv_field(residue_words(atoms, residues));
}

// A number as report.json has it (the shortest text that reads back the
// same); null is empty.
std::string csv_number(const json& x) { return x.is_null() ? std::string() : x.dump(); }

}  // namespace

// The documented schemas (docs/outputs.md); the rows of table_rows() follow the leading columns.
const Table kStructuresTable{"structures",
                             {{"id", T}, {"path", T}, {"status", T}, {"format", T}, {"predicted", I}, {"atoms", I},
                              {"pockets", I}, {"voids", I}, {"sites", I}, {"tunnels", I}, {"sa_area", R},
                              {"sa_volume", R}, {"mean_plddt", R}},
                             3,
                             "id"};
const Table kSitesTable{"sites",
                        {{"structure_id", T}, {"site_rank", I}, {"kind", T}, {"cavity_rank", I}, {"score", R},
                         {"probability", R}, {"sa_volume", R}, {"ms_volume", R}, {"sa_area", R}, {"ms_area", R},
                         {"depth", R}, {"mouths", I}, {"mouth_area", R}, {"buriedness", R}, {"burial_atoms", I},
                         {"max_probe_radius", R}, {"center_x", R}, {"center_y", R}, {"center_z", R},
                         {"mean_plddt", R}, {"lining_residues", I}, {"residues", T}, {"ligands", T}},
                        1,
                        "structure_id, site_rank"};
const Table kTunnelsTable{"tunnels",
                          {{"structure_id", T}, {"tunnel_rank", I}, {"kind", T}, {"bottleneck_radius", R},
                           {"center_x", R}, {"center_y", R}, {"center_z", R}, {"length", R}, {"birth_alpha_sq", R},
                           {"death_alpha_sq", R}, {"residues", T}},
                          1,
                          "structure_id, tunnel_rank"};
const Table kFailuresTable{"failures", {{"id", T}, {"path", T}, {"category", T}, {"message", T}}, 4, "id"};

json table_rows(const PocketRun& run) {
  const Structure& st = run.structure;
  const Cavities& cavities = run.search.cavities;
  json structure = json::array({st.report.format, int(st.report.predicted), st.atoms.size(), cavities.pockets.size(),
                                cavities.voids.size(), cavities.sites.size(), cavities.tunnels.size(),
                                length(cavities.sa_area), length(cavities.sa_volume), mean_plddt(st)});
  json sites = json::array();
  for (const SiteEntry& s : site_entries(run)) {
    const Cavity& c = *s.cavity;
    std::string ligands;
    for (const std::string& id : s.ligands) ligands += (ligands.empty() ? "" : " ") + id;
    sites.push_back(json::array(
        {s.rank, s.kind, s.cavity_rank, score(c.score), report_probability(c.probability), length(c.sa_volume),
         length(c.ms_volume), length(c.sa_area), length(c.ms_area), length(c.depth), c.mouths.size(),
         length(c.mouth_area), score(c.buriedness), c.burial_atoms, length(c.max_probe_radius), length(s.center.x),
         length(s.center.y), length(s.center.z), s.mean_plddt, s.residues.size(), residue_words(st.atoms, s.residues),
         ligands.empty() ? json(nullptr) : json(ligands)}));
  }
  json tunnels = json::array();
  for (const TunnelEntry& t : tunnel_entries(run))
    tunnels.push_back(json::array({t.rank, t.kind, length(t.bottleneck_radius), length(t.bottleneck.x),
                                   length(t.bottleneck.y), length(t.bottleneck.z), t.length, t.birth_alpha_sq,
                                   t.death_alpha_sq, residue_words(st.atoms, t.residues)}));
  return {{"structure", std::move(structure)}, {"sites", std::move(sites)}, {"tunnels", std::move(tunnels)}};
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + '"';
}

std::string table_value(const json& v, bool tsv) {
  if (v.is_null()) return "";
  if (!v.is_string()) return v.dump();
  std::string s = v.get<std::string>();
  if (!tsv) return csv_field(s);
  for (char& ch : s)
    if (ch == '\t' || ch == '\n' || ch == '\r') ch = ' ';
  return s;
}

std::string sites_csv(const std::string& structure_id, const PocketRun& run) {
  std::string out;
  for (const Column& c : kSitesTable.columns) {
    if (!out.empty()) out += ',';
    out += c.name;
  }
  out += '\n';
  const json rows = table_rows(run);
  for (const json& row : rows.at("sites")) {
    out += csv_field(structure_id);
    for (const json& v : row) out += ',' + table_value(v, false);
    out += '\n';
  }
  return out;
}

std::string pockets_csv(const PocketRun& run) {
  std::string out =
      "rank,score,probability,sa_volume,ms_volume,sa_area,ms_area,mouths,mouth_area,depth,center_x,center_y,center_z,"
      "lining_residues,residues,mean_plddt\n";
  const std::vector<Atom>& atoms = run.structure.atoms;
  std::size_t rank = 0;
  for (const Cavity& c : run.search.cavities.pockets) {
    out += std::to_string(++rank) + ',' + csv_number(score(c.score)) + ',' + csv_number(report_probability(c.probability));
    for (const double x : {length(c.sa_volume), length(c.ms_volume), length(c.sa_area), length(c.ms_area)})
      out += ',' + csv_number(x);
    out += ',' + std::to_string(c.mouths.size());
    for (const double x : {length(c.mouth_area), length(c.depth), length(c.center.x), length(c.center.y),
                           length(c.center.z)})
      out += ',' + csv_number(x);
    out += residue_columns(atoms, residues_of(atoms, c.lining_atoms)) + ',' + csv_number(mean_plddt(run.structure, c.lining_atoms)) +
           '\n';
  }
  return out;
}

std::string tunnels_csv(const PocketRun& run) {
  std::string out =
      "tunnel,kind,start,bottleneck_radius,bottleneck_x,bottleneck_y,bottleneck_z,length,curvature,cost,"
      "lining_residues,residues\n";
  const std::vector<Atom>& atoms = run.structure.atoms;
  for (const TunnelEntry& t : tunnel_entries(run)) {
    out += std::to_string(t.rank) + ',' + t.kind + ',' + table_value(t.start, false);
    for (const double x : {t.bottleneck_radius, t.bottleneck.x, t.bottleneck.y, t.bottleneck.z})
      out += ',' + csv_number(length(x));
    out += ',' + csv_number(t.length) + ',' + csv_number(t.curvature) + ',' + csv_number(t.cost) +
           residue_columns(atoms, t.residues) + '\n';
  }
  return out;
}

std::string tunnel_profiles_csv(const PocketRun& run) {
  std::string out = "tunnel,distance,x,y,z,radius\n";
  const auto rows = [&](std::size_t rank, const TunnelPath& p) {
    for (const ProfilePoint& q : p.profile) {
      out += std::to_string(rank);
      for (const double x : {q.distance, q.x.x, q.x.y, q.x.z, q.radius}) out += ',' + csv_number(length(x));
      out += '\n';
    }
  };
  for (const TunnelEntry& t : tunnel_entries(run))
    if (t.way) rows(t.rank, *t.way);
  return out;
}

}  // namespace molecule
