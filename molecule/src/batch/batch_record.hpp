// SPDX-License-Identifier: Apache-2.0
// What a batch run keeps of one structure: one record, one line of JSON in
// OUTDIR/records.jsonl. It holds the structure's rows of the run's tables
// (batch_tables.hpp), so the tables of any set of records can be written
// again without the reports (a resumed run, `alphapocket merge`), and what
// tells a re-run whether the structure is done: its path, the checksum of
// its content and the key of the parameters and version it ran with.
#pragma once
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace molecule {

struct BatchRecord {
  std::string id, path;
  std::string checksum;  // SHA-256 of the file's bytes; empty if they could not be read
  std::string key;       // parameters and version (batch_key)
  std::string status;    // "ok", "failed" or "skipped" (over --max-atoms)
  std::string category;  // failures: failure_name(); "" when ok
  std::string message;   // failures: the one-line error
  double seconds = 0;    // wall-clock time of the structure (not in the tables: it varies)
  // The structure's rows (table_rows, outputs/tables.hpp), without its id; null for failures.
  nlohmann::ordered_json rows;
};

// One line (no line break); and back (throws alpha::Error on a malformed line).
std::string record_line(const BatchRecord& record);
BatchRecord parse_record(std::string_view line);

// A short, stable digest of everything that changes a structure's results
// (`parameters`: a JSON object of the options; the version).
std::string batch_key(const nlohmann::ordered_json& parameters, const std::string& version);

}  // namespace molecule
