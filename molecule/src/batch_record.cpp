// SPDX-License-Identifier: Apache-2.0
#include "molecule/batch_record.hpp"

#include <exception>

#include "alpha/error.hpp"
#include "molecule/checksum.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;

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

std::string record_line(const BatchRecord& r) {
  const json line = {{"id", r.id},         {"path", r.path},         {"checksum", r.checksum},
                     {"key", r.key},       {"status", r.status},     {"category", r.category},
                     {"message", r.message}, {"seconds", r.seconds}, {"rows", r.rows}};
  return line.dump(-1, ' ', false, json::error_handler_t::replace);
}

BatchRecord parse_record(std::string_view line) {
  try {
    const json j = json::parse(line);
    BatchRecord r;
    r.id = j.at("id");
    r.path = j.at("path");
    r.checksum = j.at("checksum");
    r.key = j.at("key");
    r.status = j.at("status");
    r.category = j.at("category");
    r.message = j.at("message");
    r.seconds = j.at("seconds");
    r.rows = j.at("rows");
    if (r.id.empty() || (r.status == "ok") == r.rows.is_null()) alpha::fail("inconsistent record");
    return r;
  } catch (const std::exception& e) {
    alpha::fail(std::string("malformed record: ") + e.what());
  }
}

std::string batch_key(const json& parameters, const std::string& version) {
  return sha256_hex(json{{"version", version}, {"parameters", parameters}}.dump()).substr(0, 16);
}

}  // namespace molecule
