// SPDX-License-Identifier: Apache-2.0
#include "batch/batch_page.hpp"

#include <algorithm>

#include "outputs/report_page.hpp"

namespace molecule {

using json = nlohmann::ordered_json;

BatchPage::BatchPage(const std::vector<std::string>& structure_columns, const std::vector<std::string>& site_columns,
                     const std::vector<std::string>& failure_columns, const std::vector<std::string>& numeric) {
  json structures = structure_columns;
  structures.push_back("top_probability");
  json numbers = numeric;
  numbers.push_back("top_probability");
  data_ = {{"structures", {{"columns", structures}, {"numeric", numbers}, {"rows", json::array()}}},
           {"sites", {{"columns", site_columns}, {"numeric", numbers}, {"rows", json::array()}}},
           {"failures", {{"columns", failure_columns}, {"rows", json::array()}}},
           {"pages", json::array()}};
  probability_ = std::size_t(std::find(site_columns.begin(), site_columns.end(), "probability") - site_columns.begin());
}

void BatchPage::add_structure(const json& row, const std::vector<json>& sites, bool page) {
  json full = row;
  full.push_back(sites.empty() || probability_ >= sites.front().size() ? json(nullptr) : sites.front()[probability_]);
  data_["structures"]["rows"].push_back(std::move(full));
  for (const json& s : sites) data_["sites"]["rows"].push_back(s);
  if (page) data_["pages"].push_back(row.at(0));
}

void BatchPage::add_failure(const json& row) { data_["failures"]["rows"].push_back(row); }

std::string BatchPage::html(const std::string& version) const {
  json data = data_;
  data["alphapocket"] = version;
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<title>alphapocket screening run</title>\n<link rel=\"stylesheet\" href=\"viewer/index.css\">\n";
  page += "</head>\n<body>\n<noscript>This page needs JavaScript; structures.csv and sites.csv hold the same tables.</noscript>\n";
  page += "<script type=\"application/json\" id=\"alphapocket-index\">" + script_json(data) + "</script>\n";
  page += "<script src=\"viewer/index.js\"></script>\n</body>\n</html>\n";
  return page;
}

}  // namespace molecule
