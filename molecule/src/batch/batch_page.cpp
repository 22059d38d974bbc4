// SPDX-License-Identifier: Apache-2.0
#include "batch/batch_page.hpp"

#include <algorithm>

#include "alpha/error.hpp"

#include "outputs/report_assets.hpp"
#include "outputs/report_page.hpp"

namespace molecule {

using json = nlohmann::ordered_json;

namespace {

// The columns index.js shows or filters on: the page holds only these.
const std::vector<std::string> kStructureColumns{"id", "status", "atoms", "sites", "sa_volume", "mean_plddt", "tunnels"};
const std::vector<std::string> kSiteColumns{"structure_id", "site_rank", "kind", "probability", "sa_volume",
                                            "ms_volume", "depth", "mean_plddt", "residues", "ligands"};

// Where each of `kept` is in `all`.
std::vector<std::size_t> positions(const std::vector<std::string>& all, const std::vector<std::string>& kept) {
  std::vector<std::size_t> out;
  for (const std::string& name : kept) {
    const auto it = std::find(all.begin(), all.end(), name);
    if (it == all.end()) alpha::fail("index.html: no column " + name + " in the tables", alpha::ErrorKind::Internal);
    out.push_back(std::size_t(it - all.begin()));
  }
  return out;
}

json project(const json& row, const std::vector<std::size_t>& columns) {
  json out = json::array();
  for (const std::size_t k : columns) out.push_back(k < row.size() ? row[k] : json(nullptr));
  return out;
}

}  // namespace

BatchPage::BatchPage(const std::vector<std::string>& structure_columns, const std::vector<std::string>& site_columns,
                     const std::vector<std::string>& failure_columns, const std::vector<std::string>& numeric)
    : structure_columns_(positions(structure_columns, kStructureColumns)),
      site_columns_(positions(site_columns, kSiteColumns)),
      probability_(positions(site_columns, {"probability"}).front()) {
  json structures = kStructureColumns;
  structures.push_back("top_probability");
  json numbers = numeric;
  numbers.push_back("top_probability");
  data_ = {{"structures", {{"columns", structures}, {"numeric", numbers}, {"rows", json::array()}}},
           {"sites", {{"columns", kSiteColumns}, {"numeric", numbers}, {"rows", json::array()}}},
           {"failures", {{"columns", failure_columns}, {"rows", json::array()}}},
           {"pages", json::array()}};
}

void BatchPage::add_structure(const json& row, const std::vector<json>& sites, bool page) {
  json full = project(row, structure_columns_);
  full.push_back(sites.empty() || probability_ >= sites.front().size() ? json(nullptr) : sites.front()[probability_]);
  data_["structures"]["rows"].push_back(std::move(full));
  for (const json& s : sites) data_["sites"]["rows"].push_back(project(s, site_columns_));
  if (page) data_["pages"].push_back(row.at(0));
}

void BatchPage::add_failure(const json& row) { data_["failures"]["rows"].push_back(row); }

std::string BatchPage::html(const std::string& version) const {
  json data = data_;
  data["alphapocket"] = version;
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<title>alphapocket screening run</title>\n<style>\n" + page_asset("index.css") + "</style>\n";
  page += "</head>\n<body>\n<noscript>This page needs JavaScript; structures.csv and sites.csv hold the same tables.</noscript>\n";
  page += "<script type=\"application/json\" id=\"alphapocket-index\">" + script_json(data) + "</script>\n";
  page += "<script>\n" + page_asset("index.js") + "</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace molecule
