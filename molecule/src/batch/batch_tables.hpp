// SPDX-License-Identifier: Apache-2.0
// The tables of a batch run, for the whole run, rows sorted by structure
// id (so they depend neither on -j nor on the order of the inputs):
//
//   structures.csv   one row per input: id, path, status, counts, areas
//   sites.csv        one row per candidate binding site of every structure
//   tunnels.csv      one row per tunnel of every structure
//   failures.tsv     one row per input that failed or was skipped
//   alphapocket.sqlite  the same four tables (schemas: outputs/tables.hpp)
//   index.html       the run in a browser (batch/batch_page.hpp), one file
//   viewer/          Mol* and the script the structures' report.html load,
//                    when any structure has one and Mol* is installed
//                    (outputs/report_assets.hpp)
//
// They are written from records (batch_record.hpp) kept in a records file
// (OUTDIR/records.jsonl, one line per finished structure, appended as the
// run goes; the latest line of an id counts), one record at a time: memory
// does not grow with the run. `batch` and `merge` both write through
// write_batch_tables. Every file appears whole or not at all.
#pragma once
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "batch/batch_record.hpp"
#include "util/temporary_paths.hpp"

namespace molecule {

inline constexpr const char* kRecordsFile = "records.jsonl";

// Appends records to a records file, one flushed line each; safe to call
// from several threads. A partial last line (a run killed mid-write) is
// closed first, so that it stays one malformed line that readers skip.
class RecordAppender {
public:
  explicit RecordAppender(const std::string& path);
  ~RecordAppender();
  RecordAppender(const RecordAppender&) = delete;
  RecordAppender& operator=(const RecordAppender&) = delete;
  void append(const BatchRecord& record);

private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::mutex mutex_;
};

// Where a record is, and what a re-run needs to know of it.
struct RecordLocation {
  std::size_t file = 0;  // index into the records files given
  std::uint64_t offset = 0;
  std::string path, checksum, key, status, category;
};

// The latest record of each id in each file; an id in two files is an
// error naming both (`merge`). Malformed lines are skipped and counted
// into *malformed. A missing file has no records.
std::map<std::string, RecordLocation> index_records(const std::vector<std::string>& files,
                                                    std::size_t* malformed = nullptr);

// Writes the tables into outdir from the records at `locations` (read from
// `files`), in the order given (sorted by id), and the records file itself
// again, compacted to those records. With `temporaries`, the temporary
// files are registered there.
void write_batch_tables(const std::string& outdir, const std::vector<std::string>& files,
                        const std::vector<std::pair<std::string, RecordLocation>>& locations,
                        TemporaryPaths* temporaries = nullptr);

}  // namespace molecule
