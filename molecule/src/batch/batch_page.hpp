// SPDX-License-Identifier: Apache-2.0
// index.html of a batch run (`batch`, `merge`): the structures and sites
// tables of the run (the rows of structures.csv, sites.csv, failures.tsv,
// only the columns the page shows,
// with each structure's top site probability), which of the structures
// have a report.html, drawn by index.js (report_assets.hpp, inside the page) as
// sortable, filterable tables that show a screen of rows at a time, with
// histograms of the top site's probability and of the sites' volumes.
// Text from the inputs is inside the page's JSON block only, '<', '>' and
// '&' escaped (script_json), and index.js puts it in as text.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace molecule {

// Collects the rows, then writes the page.
class BatchPage {
public:
  // The tables' column names and which of them are numbers.
  BatchPage(const std::vector<std::string>& structure_columns, const std::vector<std::string>& site_columns,
            const std::vector<std::string>& failure_columns, const std::vector<std::string>& numeric);

  // A structure's row, its sites' rows (in site order, the first column its id)
  // and whether it has a page (OUTDIR/<id>/report.html).
  void add_structure(const nlohmann::ordered_json& row, const std::vector<nlohmann::ordered_json>& sites, bool page);
  void add_failure(const nlohmann::ordered_json& row);

  // The page; its scripts and style at viewer/ beside it.
  std::string html(const std::string& version) const;

private:
  std::vector<std::size_t> structure_columns_, site_columns_;  // the columns kept, in the tables' rows
  std::size_t probability_;  // the sites' probability column in the tables' rows
  nlohmann::ordered_json data_;
};

}  // namespace molecule
