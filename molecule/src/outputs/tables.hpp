// SPDX-License-Identifier: Apache-2.0
// The tables of the results, one schema each, and their rows, made from a
// run's typed results (numbers rounded as in report.json,
// outputs/report_numbers.hpp): `pockets` writes its structure's sites.csv,
// pockets.csv, tunnels.csv and tunnel_profiles.csv from them, `batch` the
// whole run's structures.csv, sites.csv, tunnels.csv, failures.tsv and
// alphapocket.sqlite (batch/batch_tables.hpp). So a batch run's sites.csv
// is its structures' sites.csv files joined. Schemas: docs/outputs.md.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "molecule/pocket_run.hpp"

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

// The rows of the tables a run gives, without the structure's id:
// {"structure": [...], "sites": [[...], ...], "tunnels": [[...], ...]}, in
// the column order of each table after its leading columns. JSON, as
// batch keeps them (batch/batch_record.hpp).
nlohmann::ordered_json table_rows(const PocketRun& run);

// A CSV field: quoted (quotes doubled) when it holds a separator, a quote
// or a line break.
std::string csv_field(const std::string& s);

// One value as a CSV field (csv_field), or as a TSV field (tabs and line
// breaks made spaces); null is empty.
std::string table_value(const nlohmann::ordered_json& value, bool tsv);

// sites.csv of one structure: the header and the rows the sites table has
// for it.
std::string sites_csv(const std::string& structure_id, const PocketRun& run);

// pockets.csv: one row per pocket, for spreadsheets and scripts.
std::string pockets_csv(const PocketRun& run);
// tunnels.csv (one row per entry of report.json's tunnels) and
// tunnel_profiles.csv (tunnel, distance, x, y, z, radius: CAVER's columns,
// one row per profile point of each cycle's way through, tunnel and pore).
std::string tunnels_csv(const PocketRun& run);
std::string tunnel_profiles_csv(const PocketRun& run);

}  // namespace molecule
