// SPDX-License-Identifier: Apache-2.0
// alphapocket batch INPUT... -o OUTDIR [-j N] [--list FILE] [--outputs LIST]
//                  [--max-atoms N] [the options of pockets]
// alphapocket batch INPUT... [--list FILE] --print-inputs
//
// Many structures, one per worker thread: each goes through the same
// pipeline as `pockets` (molecule::analyse), writes the chosen outputs to
// OUTDIR/<id>/ and one record to OUTDIR/records.jsonl; the run's tables
// (batch/batch_tables.hpp) are written from the records at the end.
// A re-run skips the structures whose record matches (same path, content
// checksum, parameters and version). SIGINT/SIGTERM: no new structure is
// started, the ones in flight finish, the tables are written; a second
// signal abandons the run at once, leaving no temporary file or directory
// (apps/interrupt.hpp).
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "alpha/input_file.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "interrupt.hpp"
#include "molecule/analysis.hpp"
#include "batch/batch_inputs.hpp"
#include "batch/batch_record.hpp"
#include "batch/batch_tables.hpp"
#include "util/checksum.hpp"
#include "outputs/pocket_outputs.hpp"
#include "outputs/pocket_report.hpp"
#include "outputs/tables.hpp"
#include "outputs/report_assets.hpp"
#include "progress.hpp"

namespace alphapocket {
namespace {

namespace fs = std::filesystem;

// Exit codes (docs/cli.md, `alphapocket batch`).
constexpr int kSomeFailed = 3;
constexpr int kNoneSucceeded = 4;

struct BatchOptions {
  std::vector<std::string> inputs;  // files, directories, "-"
  std::vector<std::string> lists;   // --list
  std::string output_dir;
  unsigned jobs = 0;  // 0: all cores
  std::string outputs = "report";
  std::size_t max_atoms = 2'000'000;
  molecule::AnalysisOptions analysis;
  bool print_inputs = false;
};


// The structures named by the command line, sorted by id.
std::vector<molecule::BatchInput> collect_inputs(const BatchOptions& opt) {
  std::vector<std::string> paths;
  for (const std::string& input : opt.inputs) {
    if (input != "-") {
      paths.push_back(input);
      continue;
    }
    const std::vector<std::string> listed = molecule::read_path_list(std::cin, "standard input", false, "");
    paths.insert(paths.end(), listed.begin(), listed.end());
  }
  for (const std::string& list : opt.lists) {
    const std::vector<std::string> listed = molecule::read_path_list_file(list);
    paths.insert(paths.end(), listed.begin(), listed.end());
  }
  std::vector<molecule::BatchInput> inputs = molecule::batch_inputs(paths);
  if (inputs.empty()) throw alpha::Error("no structure files in the inputs", alpha::ErrorKind::BadInput);
  return inputs;
}

// --print-inputs: the structures as the run would see them, "id<TAB>path"
// per line, sorted by id (what workflow/Snakefile chunks). A path with a
// tab or line break cannot be a line of a list: an error.
int print_inputs(const BatchOptions& opt) {
  for (const molecule::BatchInput& in : collect_inputs(opt)) {
    if (in.path.find_first_of("\t\r\n") != std::string::npos)
      throw alpha::Error(in.path + ": a path with a tab or line break cannot be listed", alpha::ErrorKind::BadInput);
    std::printf("%s\t%s\n", in.id.c_str(), in.path.c_str());
  }
  flush_stdout();
  return 0;
}

// Everything that changes a structure's results or outputs.
nlohmann::ordered_json parameters(const BatchOptions& opt) {
  const molecule::AnalysisOptions& a = opt.analysis;
  return {{"probe", a.cavities.probe},
          {"min_volume", a.cavities.min_volume},
          {"model", a.structure.model},
          {"chains", a.structure.chains},
          {"keep_hydrogens", a.structure.keep_hydrogens},
          {"keep_waters", a.structure.keep_waters},
          {"keep_hetero", a.structure.keep_hetero},
          {"keep_hetero_codes", a.structure.keep_hetero_codes},
          {"keep_cofactors", a.structure.keep_cofactors},
          {"max_atoms", a.max_atoms},
          {"outputs", molecule::output_list(a.outputs)},
          {"mesh", a.mesh_format},
          {"mesh_resolution", a.mesh_resolution}};
}

class Batch {
public:
  Batch(const BatchOptions& opt, std::vector<molecule::BatchInput> inputs)
      : opt_(opt), inputs_(std::move(inputs)), outdir_(opt.output_dir),
        records_((outdir_ / molecule::kRecordsFile).string()),
        key_(molecule::batch_key(parameters(opt), opt.analysis.version)),
        previous_(molecule::index_records({records_})),
        progress_(inputs_.size(), spdlog::get_level() <= spdlog::level::info) {}

  // Runs the workers until every input is done or an interrupt; returns
  // the exit code.
  int run(unsigned jobs) {
    Stopwatch time;
    {
      molecule::RecordAppender appender(records_);
      appender_ = &appender;
      std::vector<std::thread> workers;
      for (unsigned k = 0; k < std::max(1u, jobs); ++k) workers.emplace_back([this] { work(); });
      for (std::thread& t : workers) t.join();
      appender_ = nullptr;
    }
    progress_.finish();
    if (error_) std::rethrow_exception(error_);
    return finish(time.seconds());
  }

private:
  const BatchOptions& opt_;
  const std::vector<molecule::BatchInput> inputs_;
  const fs::path outdir_;
  const std::string records_;
  const std::string key_;
  const std::map<std::string, molecule::RecordLocation> previous_;
  Progress progress_;
  molecule::RecordAppender* appender_ = nullptr;
  std::atomic<std::size_t> next_{0};
  std::atomic<std::size_t> resumed_{0};
  std::mutex error_mutex_;
  std::exception_ptr error_;  // a record that could not be written: the run stops

  void work() {
    while (!interrupted()) {
      const std::size_t i = next_++;
      if (i >= inputs_.size()) return;
      try {
        process(inputs_[i]);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex_);
        if (!error_) error_ = std::current_exception();
        next_ = inputs_.size();  // no more work
        return;
      }
    }
  }

  // The previous run's record of this input if it stands, else null.
  const molecule::RecordLocation* done_before(const molecule::BatchInput& in, const std::string& checksum) const {
    const auto it = previous_.find(in.id);
    if (it == previous_.end()) return nullptr;
    const molecule::RecordLocation& r = it->second;
    if (r.path != in.path || r.checksum != checksum || r.key != key_) return nullptr;
    if (r.category == molecule::failure_name(molecule::FailureKind::Internal)) return nullptr;  // worth a retry
    std::error_code ec;
    const bool outputs = r.status != "ok" || !opt_.analysis.outputs.report ||
                         fs::exists(outdir_ / in.id / "report.json", ec);
    return outputs ? &r : nullptr;
  }

  void process(const molecule::BatchInput& in) {
    Stopwatch time;
    molecule::BatchRecord r;
    r.id = in.id;
    r.path = in.path;
    r.key = key_;
    const auto failed = [&](const std::string& status, molecule::FailureKind kind, const std::string& message) {
      r.status = status;
      r.category = molecule::failure_name(kind);
      molecule::remove_pocket_outputs((outdir_ / in.id).string());  // an earlier run's
      r.message = message;
      progress_.warn(in.id + ": " + r.category + ": " + message);
    };
    try {
      std::string content;
      std::string unreadable;  // why, if the file cannot be read
      try {
        content = alpha::read_input_file(in.path);
        r.checksum = molecule::sha256_hex(content);
      } catch (const alpha::Error& e) {
        unreadable = e.what();
      }
      if (const molecule::RecordLocation* done = done_before(in, r.checksum)) {  // unreadable: if it was before
        ++resumed_;
        progress_.add(done->status != "ok");
        return;
      }
      if (!unreadable.empty()) throw molecule::AnalysisError(molecule::FailureKind::BadInput, unreadable);
      const molecule::Analysis analysis = molecule::analyse_content(in.path, content, opt_.analysis);
      log_analysis(analysis, spdlog::level::debug);
      molecule::PocketOutputDir out((outdir_ / in.id).string(), opt_.analysis.outputs, &temporaries());
      out.share_viewer(std::string("../") + molecule::kViewerDir);  // the run's one copy, beside index.html
      molecule::write_outputs(analysis, out);
      for (const std::string& warning : out.warnings()) progress_.warn(in.id + ": " + warning);
      r.status = "ok";
      r.rows = molecule::table_rows(analysis);
    } catch (const molecule::AnalysisError& e) {
      failed(e.skipped() ? "skipped" : "failed", e.kind(), e.what());
    } catch (const std::bad_alloc&) {
      failed("failed", molecule::FailureKind::LimitExceeded, in.path + ": out of memory");
    } catch (const std::exception& e) {  // e.g. the outputs could not be written
      failed("failed", molecule::FailureKind::Internal, e.what());
    }
    r.seconds = time.seconds();
    appender_->append(r);
    progress_.add(r.status != "ok");
  }

  // Tables from the records of this run's inputs; the exit code.
  int finish(double seconds) {
    const std::map<std::string, molecule::RecordLocation> index = molecule::index_records({records_});
    std::vector<std::pair<std::string, molecule::RecordLocation>> locations;
    std::size_t ok = 0, failed = 0, skipped = 0;
    for (const molecule::BatchInput& in : inputs_) {
      const auto it = index.find(in.id);
      if (it == index.end() || it->second.path != in.path || it->second.key != key_) continue;  // not done
      locations.emplace_back(in.id, it->second);
      const std::string& status = it->second.status;
      (status == "ok" ? ok : status == "skipped" ? skipped : failed) += 1;
    }
    molecule::write_batch_tables(outdir_.string(), {records_}, locations, &temporaries());
    const std::size_t missing = inputs_.size() - locations.size();
    spdlog::info("{} structures: {} ok, {} failed, {} skipped ({} done before){} in {:.1f} s; tables in {}/",
                 inputs_.size(), ok, failed, skipped, resumed_.load(),
                 missing ? ", " + std::to_string(missing) + " not done (interrupted)" : std::string(), seconds,
                 outdir_.string());
    if (interrupted()) return 128 + interrupt_signal();
    if (ok == inputs_.size()) return 0;
    return ok == 0 ? kNoneSucceeded : kSomeFailed;
  }
};

int run_batch(BatchOptions& opt) {
  opt.analysis.max_atoms = opt.max_atoms;
  std::vector<molecule::BatchInput> inputs = collect_inputs(opt);  // errors (duplicate ids) before any work
  molecule::output_directory_path(opt.output_dir);  // refuses a root or a link to nothing
  std::error_code ec;
  if (fs::exists(opt.output_dir, ec) && !fs::is_directory(opt.output_dir, ec))
    throw alpha::Error(opt.output_dir + ": cannot create the output directory: a file of that name exists",
                       alpha::ErrorKind::BadInput);
  if (!fs::is_directory(opt.output_dir, ec) && !fs::create_directory(opt.output_dir, ec))
    throw alpha::Error(opt.output_dir + ": cannot create the output directory: " + ec.message(),
                       alpha::ErrorKind::BadInput);
  const unsigned jobs = opt.jobs ? opt.jobs : std::max(1u, std::thread::hardware_concurrency());
  spdlog::info("{} structures, {} worker{}, outputs {} in {}/", inputs.size(), jobs, jobs == 1 ? "" : "s",
               molecule::output_list(opt.analysis.outputs), opt.output_dir);
  install_interrupt_handlers(2);
  Batch batch(opt, std::move(inputs));
  return batch.run(std::min<std::size_t>(jobs, std::numeric_limits<unsigned>::max()));
}

}  // namespace

Subcommand add_batch_command(CLI::App& app) {
  auto opt = std::make_shared<BatchOptions>();
  CLI::App* sub = app.add_subcommand(
      "batch", "Find the pockets of many structures, in parallel, into one set of tables (CSV, TSV, SQLite)");
  sub->footer(
      "INPUT: structure files, directories (searched recursively for .pdb .ent .cif .mmcif, optionally .gz), or - "
      "(paths on standard input). OUTDIR gets structures.csv, sites.csv, tunnels.csv, failures.tsv, "
      "alphapocket.sqlite, records.jsonl and <id>/ per structure. Exit code 0: all succeeded, 3: some failed or "
      "were skipped, 4: none succeeded, 128+N: stopped by signal N. See docs/cli.md, \"alphapocket batch\".");
  sub->add_option("INPUT", opt->inputs, "Structure files, directories, or - for paths on standard input");
  sub->add_option("--list", opt->lists,
                  "File listing one path per line (# comments; a P2Rank .ds dataset: first column, relative to "
                  "its directory); may be repeated");
  sub->add_option("-o,--output-dir", opt->output_dir,
                  "Directory for the tables and the structures' outputs (required unless --print-inputs)")
      ->check(output_directory_name());
  sub->add_flag("--print-inputs", opt->print_inputs,
                "Only print the structures the run would analyse, one 'id<TAB>path' line each, sorted by id (or "
                "the error an input would stop the run with), and exit");
  sub->add_option("-j,--jobs", opt->jobs, "Worker threads, one structure each (default: all cores)")
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u).description(""));
  add_outputs_option(*sub, opt->outputs, "OUTDIR/<id>/ for each structure");
  sub->add_option("--max-atoms", opt->max_atoms, "Structures with more atoms (after the selection) are skipped")
      ->capture_default_str()
      ->type_name("N")
      ->check(CLI::PositiveNumber.description(""));
  // Some input, and -o unless --print-inputs: a wrong command line (exit 2) otherwise.
  sub->parse_complete_callback([opt] {
    if (opt->inputs.empty() && opt->lists.empty()) throw CLI::ValidationError("batch", "no INPUT and no --list");
    if (!opt->print_inputs && opt->output_dir.empty()) throw CLI::RequiredError("-o,--output-dir");
  });
  add_structure_options(*sub, opt->analysis.structure, opt->analysis.cavities.probe);
  add_cavity_options(*sub, opt->analysis);
  return {sub, [opt, sub] {
            opt->analysis.outputs = selected_outputs(*sub, opt->outputs);
            if (opt->print_inputs) return print_inputs(*opt);
            return run_batch(*opt);
          }};
}

}  // namespace alphapocket
