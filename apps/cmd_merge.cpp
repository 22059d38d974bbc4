// SPDX-License-Identifier: Apache-2.0
// alphapocket merge DIR... -o OUTDIR
//
// The tables of several batch runs' OUTDIRs (chunks of one screen) as one:
// the records of every DIR (DIR/records.jsonl) are written into OUTDIR's
// tables through the same code as `batch` (molecule::write_batch_tables),
// so the result is byte-identical to one batch run over all the chunks'
// inputs. A structure id in two DIRs is an error naming both. The
// structures' own outputs (DIR/<id>/) stay where they are.
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "commands.hpp"
#include "batch/batch_tables.hpp"

namespace alphapocket {
namespace {

namespace fs = std::filesystem;

struct MergeOptions {
  std::vector<std::string> dirs;
  std::string output_dir;
};

int run_merge(const MergeOptions& opt) {
  std::vector<std::string> files;
  for (const std::string& dir : opt.dirs) {
    const fs::path records = fs::path(dir) / molecule::kRecordsFile;
    std::error_code ec;
    if (!fs::is_regular_file(records, ec))
      throw alpha::Error(dir + ": not a batch output directory (no " + molecule::kRecordsFile + ")",
                         alpha::ErrorKind::BadInput);
    files.push_back(records.string());
  }
  std::size_t malformed = 0;
  const auto index = molecule::index_records(files, &malformed);
  if (malformed) spdlog::warn("{} malformed record line(s) skipped (a run killed mid-write)", malformed);
  std::error_code ec;
  if (!fs::is_directory(opt.output_dir, ec) && !fs::create_directory(opt.output_dir, ec))
    throw alpha::Error(opt.output_dir + ": cannot create the output directory" +
                           (ec ? ": " + ec.message() : std::string(": a file of that name exists")),
                       alpha::ErrorKind::BadInput);
  const std::vector<std::pair<std::string, molecule::RecordLocation>> locations(index.begin(), index.end());
  molecule::write_batch_tables(opt.output_dir, files, locations);
  spdlog::info("merged {} structures from {} directories into {}/", locations.size(), files.size(),
               opt.output_dir);
  return 0;
}

}  // namespace

Subcommand add_merge_command(CLI::App& app) {
  auto opt = std::make_shared<MergeOptions>();
  CLI::App* sub = app.add_subcommand("merge", "Merge the tables of several batch output directories into one");
  sub->add_option("DIR", opt->dirs, "Output directories of alphapocket batch")->required();
  sub->add_option("-o,--output-dir", opt->output_dir, "Directory for the merged tables")->required();
  return {sub, [opt] { return run_merge(*opt); }};
}

}  // namespace alphapocket
