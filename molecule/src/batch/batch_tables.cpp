// SPDX-License-Identifier: Apache-2.0
#include "batch/batch_tables.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include <sqlite3.h>

#include "alpha/error.hpp"
#include "util/atomic_file.hpp"
#include "outputs/tables.hpp"
#include "batch/batch_page.hpp"
#include "outputs/report_assets.hpp"
#include "alphapocket/version.hpp"

namespace molecule {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const char* sql_type(ColumnType t) {
  return t == ColumnType::Text ? "TEXT" : t == ColumnType::Integer ? "INTEGER" : "REAL";
}

[[noreturn]] void sqlite_fail(sqlite3* db, const std::string& what, alpha::ErrorKind kind) {
  alpha::fail(what + ": " + (db ? sqlite3_errmsg(db) : "out of memory"), kind);
}

// One table's output: its text file and its prepared INSERT.
class TableWriter {
public:
  TableWriter(const Table& table, const fs::path& dir, sqlite3* db, TemporaryPaths* temporaries)
      : table_(table), tsv_(&table == &kFailuresTable),
        target_((dir / (std::string(table.name) + (tsv_ ? ".tsv" : ".csv"))).string()), tmp_(target_, temporaries),
        db_(db) {
    out_.open(tmp_.path(), std::ios::binary | std::ios::trunc);
    if (!out_)
      alpha::fail(target_ + ": cannot write " + tmp_.path() + ": " + std::strerror(errno), alpha::ErrorKind::BadInput);
    std::string create = "CREATE TABLE " + std::string(table.name) + " (";
    std::string insert = "INSERT INTO " + std::string(table.name) + " VALUES (";
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
      const Column& c = table.columns[i];
      out_ << (i ? (tsv_ ? "\t" : ",") : "") << c.name;
      create += std::string(i ? ", " : "") + c.name + " " + sql_type(c.type);
      insert += i ? ", ?" : "?";
    }
    out_ << '\n';
    create += ", PRIMARY KEY (" + std::string(table.primary_key) + "))";
    if (sqlite3_exec(db_, create.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK)
      sqlite_fail(db_, target_, alpha::ErrorKind::BadInput);
    if (sqlite3_prepare_v2(db_, (insert + ")").c_str(), -1, &insert_, nullptr) != SQLITE_OK)
      sqlite_fail(db_, target_, alpha::ErrorKind::BadInput);
  }
  ~TableWriter() { sqlite3_finalize(insert_); }

  void add(const json& row) {
    if (row.size() != table_.columns.size())
      alpha::fail(std::string(table_.name) + ": a record's row has " + std::to_string(row.size()) +
                      " values, the table " + std::to_string(table_.columns.size()) + " columns",
                  alpha::ErrorKind::BadInput);
    sqlite3_reset(insert_);
    for (std::size_t i = 0; i < row.size(); ++i) {
      const json& v = row[i];
      out_ << (i ? (tsv_ ? "\t" : ",") : "") << table_value(v, tsv_);
      const int k = int(i) + 1;
      if (v.is_null())
        sqlite3_bind_null(insert_, k);
      else if (v.is_string())
        sqlite3_bind_text(insert_, k, v.get_ref<const std::string&>().c_str(), -1, SQLITE_TRANSIENT);
      else if (v.is_number_float())
        sqlite3_bind_double(insert_, k, v.get<double>());
      else
        sqlite3_bind_int64(insert_, k, v.get<std::int64_t>());
    }
    out_ << '\n';
    if (sqlite3_step(insert_) != SQLITE_DONE) sqlite_fail(db_, target_, alpha::ErrorKind::BadInput);
  }

  // The last row was added: the statement is released (the database can
  // commit) and the file is complete.
  void finish() {
    sqlite3_finalize(insert_);
    insert_ = nullptr;
    out_.close();
    if (!out_) alpha::fail(target_ + ": cannot write " + tmp_.path(), alpha::ErrorKind::BadInput);
  }
  void commit() { tmp_.commit(); }

private:
  const Table& table_;
  bool tsv_;
  std::string target_;
  TemporaryFile tmp_;
  std::ofstream out_;
  sqlite3* db_;
  sqlite3_stmt* insert_ = nullptr;
};

std::string read_line_at(std::ifstream& in, std::uint64_t offset, const std::string& file) {
  in.clear();
  in.seekg(std::streamoff(offset));
  std::string line;
  if (!std::getline(in, line))
    alpha::fail(file + ": cannot read the record at byte " + std::to_string(offset), alpha::ErrorKind::BadInput);
  return line;
}

}  // namespace

RecordAppender::RecordAppender(const std::string& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "a+b");
  if (!file_) alpha::fail(path + ": cannot open for appending: " + std::strerror(errno), alpha::ErrorKind::BadInput);
  if (std::fseek(file_, -1, SEEK_END) == 0 && std::fgetc(file_) != '\n') {  // a partial last line
    std::fseek(file_, 0, SEEK_END);
    std::fputc('\n', file_);
    std::fflush(file_);
  }
}

RecordAppender::~RecordAppender() { std::fclose(file_); }

void RecordAppender::append(const BatchRecord& record) {
  const std::string line = record_line(record) + '\n';
  const std::lock_guard<std::mutex> lock(mutex_);
  std::fseek(file_, 0, SEEK_END);
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0)
    alpha::fail(path_ + ": cannot append a record: " + std::strerror(errno), alpha::ErrorKind::BadInput);
}

std::map<std::string, RecordLocation> index_records(const std::vector<std::string>& files, std::size_t* malformed) {
  std::map<std::string, RecordLocation> out;
  std::map<std::string, std::size_t> owner;  // id -> file it was found in
  for (std::size_t f = 0; f < files.size(); ++f) {
    std::ifstream in(files[f], std::ios::binary);
    if (!in) continue;
    std::string line;
    std::uint64_t offset = 0;
    while (std::getline(in, line)) {
      const std::uint64_t at = offset;
      offset += line.size() + 1;
      if (line.empty()) continue;
      BatchRecord r;
      try {
        r = parse_record(line);
      } catch (const alpha::Error&) {
        if (malformed) ++*malformed;
        continue;
      }
      const auto [it, fresh] = owner.emplace(r.id, f);
      if (!fresh && it->second != f)
        alpha::fail("structure id '" + r.id + "' is in both " + files[it->second] + " and " + files[f],
                    alpha::ErrorKind::BadInput);
      out[r.id] = {f, at, r.path, r.checksum, r.key, r.status, r.category};
    }
  }
  return out;
}

void write_batch_tables(const std::string& outdir, const std::vector<std::string>& files,
                        const std::vector<std::pair<std::string, RecordLocation>>& locations,
                        TemporaryPaths* temporaries) {
  const fs::path dir(outdir);
  const std::string db_target = (dir / "alphapocket.sqlite").string();
  TemporaryFile db_tmp(db_target, temporaries);
  sqlite3* db = nullptr;
  if (sqlite3_open(db_tmp.path().c_str(), &db) != SQLITE_OK) {
    sqlite3_close(db);
    alpha::fail(db_target + ": cannot create the database", alpha::ErrorKind::BadInput);
  }
  std::unique_ptr<sqlite3, int (*)(sqlite3*)> db_guard(db, sqlite3_close);
  if (sqlite3_exec(db, "PRAGMA journal_mode = OFF; PRAGMA synchronous = OFF; BEGIN", nullptr, nullptr, nullptr) !=
      SQLITE_OK)
    sqlite_fail(db, db_target, alpha::ErrorKind::BadInput);
  std::vector<std::unique_ptr<TableWriter>> tables;
  for (const Table* t : {&kStructuresTable, &kSitesTable, &kTunnelsTable, &kFailuresTable})
    tables.push_back(std::make_unique<TableWriter>(*t, dir, db, temporaries));
  TableWriter& structures = *tables[0];
  TableWriter& sites = *tables[1];
  TableWriter& tunnels = *tables[2];
  TableWriter& failures = *tables[3];

  const std::string records_target = (dir / kRecordsFile).string();
  TemporaryFile records_tmp(records_target, temporaries);
  std::ofstream records(records_tmp.path(), std::ios::binary | std::ios::trunc);
  std::vector<std::ifstream> in;
  for (const std::string& f : files) in.emplace_back(f, std::ios::binary);

  // index.html always (it needs no file beside it); viewer/ for the
  // structures' report.html when any has one, and the index links to them
  // only when viewer/ is there for them (report_assets.hpp).
  std::error_code ec;
  const bool have_molstar = missing_viewer_assets().empty();
  const bool viewer_usable = have_molstar || fs::is_regular_file(dir / kViewerDir / "molstar.js", ec);
  bool any_page = false;
  const auto names = [](const Table& t) {
    std::vector<std::string> out;
    for (const Column& c : t.columns) out.push_back(c.name);
    return out;
  };
  std::vector<std::string> numeric;
  for (const Table* t : {&kStructuresTable, &kSitesTable})
    for (const Column& c : t->columns)
      if (c.type != ColumnType::Text) numeric.push_back(c.name);
  BatchPage page(names(kStructuresTable), names(kSitesTable), names(kFailuresTable), numeric);

  for (const auto& [id, where] : locations) {
    const std::string line = read_line_at(in.at(where.file), where.offset, files[where.file]);
    const BatchRecord r = parse_record(line);
    records << line << '\n';
    json row = json::array({r.id, r.path, r.status});
    std::vector<json> site_rows;
    if (r.status == "ok") {
      for (const json& v : r.rows.at("structure")) row.push_back(v);
      for (const char* key : {"sites", "tunnels"})
        for (const json& values : r.rows.at(key)) {
          json full = json::array({r.id});
          for (const json& v : values) full.push_back(v);
          (key == std::string("sites") ? sites : tunnels).add(full);
          if (key == std::string("sites")) site_rows.push_back(std::move(full));
        }
    } else {
      while (row.size() < kStructuresTable.columns.size()) row.push_back(nullptr);
      const json failure = json::array({r.id, r.path, r.category, r.message});
      failures.add(failure);
      page.add_failure(failure);
    }
    structures.add(row);
    const bool has_page = viewer_usable && fs::is_regular_file(dir / r.id / "report.html", ec);
    any_page = any_page || has_page;
    page.add_structure(row, site_rows, has_page);
  }

  for (auto& t : tables) t->finish();
  if (sqlite3_exec(db, "COMMIT", nullptr, nullptr, nullptr) != SQLITE_OK)
    sqlite_fail(db, db_target, alpha::ErrorKind::BadInput);
  if (sqlite3_close(db_guard.release()) != SQLITE_OK)
    alpha::fail(db_target + ": cannot close the database", alpha::ErrorKind::BadInput);
  records.close();
  if (!records) alpha::fail(records_target + ": cannot write " + records_tmp.path(), alpha::ErrorKind::BadInput);
  std::vector<std::unique_ptr<TemporaryFile>> pages;
  const auto page_file = [&](const fs::path& target, const std::string& content) {
    pages.push_back(std::make_unique<TemporaryFile>(target.string(), temporaries));
    std::ofstream out(pages.back()->path(), std::ios::binary | std::ios::trunc);
    out << content;
    out.close();
    if (!out) alpha::fail(target.string() + ": cannot write " + pages.back()->path(), alpha::ErrorKind::BadInput);
  };
  if (any_page && have_molstar) {
    fs::create_directories(dir / kViewerDir, ec);
    if (ec) alpha::fail((dir / kViewerDir).string() + ": cannot create it: " + ec.message(), alpha::ErrorKind::BadInput);
    for (const auto& [name, bytes] : viewer_files()) page_file(dir / kViewerDir / name, bytes);
  }
  page_file(dir / "index.html", page.html(alphapocket::kVersion));
  // Everything is complete: into place, the records last (they are what a
  // re-run trusts).
  db_tmp.commit();
  for (auto& t : tables) t->commit();
  for (auto& p : pages) p->commit();
  records_tmp.commit();
}

}  // namespace molecule
