// SPDX-License-Identifier: Apache-2.0
// One structure from file to results: read, cavity search, report and the
// chosen output files. `alphapocket pockets` and `alphapocket batch` both
// run a structure through this, so the two cannot drift apart.
//
// Failures come back as AnalysisError, an alpha::Error whose kind() is the
// category (what batch's failures.tsv records): bad input (the file cannot
// be read, or its atoms make no 3D complex), limit exceeded (more atoms than
// allowed, out of memory), misuse (options out of range) or internal
// (anything else: a bug, a full disk).
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "alpha/error.hpp"
#include "molecule/pocket_run.hpp"

namespace molecule {

struct Report;          // pocket_report.hpp: report.json as JSON
class PocketOutputDir;  // pocket_outputs.hpp

using FailureKind = alpha::ErrorKind;

// "bad_input", "limit_exceeded", "misuse", "internal".
inline std::string_view failure_name(FailureKind kind) { return alpha::error_kind_name(kind); }

class AnalysisError : public alpha::Error {
public:
  AnalysisError(FailureKind kind, const std::string& message, bool skipped = false)
      : alpha::Error(message, kind), skipped_(skipped) {}
  // Not attempted: over AnalysisOptions::max_atoms.
  bool skipped() const { return skipped_; }

private:
  bool skipped_;
};

// Everything one structure produced, owned: the run (the options, the
// structure, the search, the ligands' sites, the tunnels, the meshes:
// molecule/pocket_run.hpp), which the writers take as it is, and how it went.
struct Analysis : PocketRun {
  double tunnels_seconds = 0;
  std::size_t radius_fallbacks = 0;  // atoms no rule of the radius file matched
  std::shared_ptr<const Report> report;  // pocket_report(*this) if options.report; report_text() is its file
};

// Reads `file` and searches its cavities; throws AnalysisError naming the file.
Analysis analyse(const std::string& file, const AnalysisOptions& options);
// The same from the file's bytes (read by the caller, e.g. to checksum them).
Analysis analyse_content(const std::string& file, std::string_view content, const AnalysisOptions& options);
// The same from atoms already read (e.g. given as arrays); `name` stands for
// the file in messages and the report (options.structure is not applied).
Analysis analyse_structure(const std::string& name, Structure structure, const AnalysisOptions& options);

// report.json's text: the report, indented, as written into OUTDIR.
std::string report_text(const Analysis& analysis);

// Writes the selected outputs (options.outputs) into `out`. Returns the
// names written; warnings in out.warnings().
std::vector<std::string> write_outputs(const Analysis& analysis, PocketOutputDir& out);
// The same into directory `dir` (created if missing; molecule::PocketOutputDir);
// its warnings into *warnings when given.
std::vector<std::string> write_outputs(const Analysis& analysis, const std::string& dir,
                                       std::vector<std::string>* warnings = nullptr);

}  // namespace molecule
