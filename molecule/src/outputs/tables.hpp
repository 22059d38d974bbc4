// SPDX-License-Identifier: Apache-2.0
// The tables of the results, one schema each, and the rows a report gives
// them: `pockets` writes its structure's sites.csv from them, `batch` the
// whole run's structures.csv, sites.csv, tunnels.csv, failures.tsv and
// alphapocket.sqlite (batch/batch_tables.hpp). So a batch run's sites.csv
// is its structures' sites.csv files joined. Schemas: docs/outputs.md.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace molecule {

enum class ColumnType { Text, Integer, Real };
struct Column {
  const char* name;
  ColumnType type;
};
struct Table {
  const char* name;  // SQLite table; the file is <name>.csv (failures: .tsv)
  std::vector<Column> columns;
  std::size_t leading;      // columns that come from the record itself, not its rows
  const char* primary_key;  // SQLite's, e.g. "structure_id, site_rank"
};

extern const Table kStructuresTable, kSitesTable, kTunnelsTable, kFailuresTable;

// The rows of the tables a report gives, without the structure's id:
// {"structure": [...], "sites": [[...], ...], "tunnels": [[...], ...]}, in
// the column order of each table after its leading columns.
nlohmann::ordered_json report_rows(const nlohmann::ordered_json& report);

// A CSV field: quoted (quotes doubled) when it holds a separator, a quote
// or a line break.
std::string csv_field(const std::string& s);

// One value as a CSV field (csv_field), or as a TSV field (tabs and line
// breaks made spaces); null is empty.
std::string table_value(const nlohmann::ordered_json& value, bool tsv);

// sites.csv of one structure: the header and the rows the sites table has
// for it (from its report.json).
std::string sites_csv(const std::string& structure_id, const nlohmann::ordered_json& report);

}  // namespace molecule
