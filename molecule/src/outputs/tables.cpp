// SPDX-License-Identifier: Apache-2.0
#include "outputs/tables.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;
constexpr ColumnType T = ColumnType::Text, I = ColumnType::Integer, R = ColumnType::Real;

json value_or_null(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? json(nullptr) : *it;
}

// Strings, or objects' "id"s, as one space-separated list.
std::string words(const json& items) {
  std::string out;
  for (const json& r : items) {
    if (!out.empty()) out += ' ';
    out += (r.is_string() ? r : r.at("id")).get<std::string>();
  }
  return out;
}

}  // namespace

// The documented schemas (docs/outputs.md); the rows of report_rows() follow the leading columns.
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

json report_rows(const json& report) {
  const json& input = report.at("input");
  const json& m = report.at("molecule");
  json structure = json::array({input.at("format"), int(value_or_null(input, "predicted") == true),
                                m.at("atoms"), m.at("pockets"), m.at("voids"), m.at("sites"), m.at("tunnels"),
                                m.at("sa_area"), m.at("sa_volume"), value_or_null(m, "mean_plddt")});
  json sites = json::array();
  for (const json& s : report.at("sites")) {
    const std::string kind = s.at("kind");
    const json& c = report.at(kind == "void" ? "voids" : "pockets").at(s.at("cavity_rank").get<std::size_t>() - 1);
    const json& center = s.at("center");  // the site's (its cluster's), not always its cavity's
    sites.push_back({s.at("rank"), kind, s.at("cavity_rank"), c.at("score"), c.at("probability"), c.at("sa_volume"), c.at("ms_volume"),
                     c.at("sa_area"), c.at("ms_area"), c.at("depth"), c.at("mouths"), c.at("mouth_area"),
                     c.at("buriedness"), c.at("burial_atoms"), c.at("max_probe_radius"), center[0], center[1],
                     center[2], value_or_null(s, "mean_plddt"), c.at("lining_residues").size(),
                     words(c.at("lining_residues")),
                     s.at("ligands").empty() ? json(nullptr) : json(words(s.at("ligands")))});
  }
  json tunnels = json::array();
  for (const json& t : report.at("tunnels")) {
    const json& center = t.at("bottleneck_center");
    tunnels.push_back({t.at("rank"), t.at("kind"), t.at("bottleneck_radius"), center[0], center[1], center[2],
                       t.at("length"), value_or_null(t, "birth_alpha_sq"), value_or_null(t, "death_alpha_sq"),
                       words(t.at("lining_residues"))});
  }
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

std::string sites_csv(const std::string& structure_id, const json& report) {
  std::string out;
  for (const Column& c : kSitesTable.columns) {
    if (!out.empty()) out += ',';
    out += c.name;
  }
  out += '\n';
  const json rows = report_rows(report);
  for (const json& row : rows.at("sites")) {
    out += csv_field(structure_id);
    for (const json& v : row) out += ',' + table_value(v, false);
    out += '\n';
  }
  return out;
}

}  // namespace molecule
