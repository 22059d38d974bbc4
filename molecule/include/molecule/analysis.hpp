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
#include "alphapocket/version.hpp"
#include "molecule/cavities.hpp"
#include "molecule/ligand_sites.hpp"
#include "molecule/output_selection.hpp"
#include "molecule/pocket_meshes.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/structure.hpp"
#include "molecule/tunnel_paths.hpp"

namespace molecule {

struct PocketRun;       // outputs/pocket_run.hpp
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

struct AnalysisOptions {
  StructureOptions structure;
  CavityOptions cavities;
  std::string version = alphapocket::kVersion;  // written into the report
  // More atoms after the selection: LimitExceeded before the search. 0: no limit.
  std::size_t max_atoms = 0;
  OutputSelection outputs;
  std::string mesh_format = "ply";  // "ply", "obj", "off", "stl"
  std::string radii_file;           // --radii (molecule/radius_file.hpp); empty: ProtOr
  std::string tunnels_from = "auto";  // --tunnels-from (molecule/tunnel_start.hpp)
  TunnelOptions tunnels;            // --tunnel-probe, --pores
  SiteRanking ranking = SiteRanking::probability;
  double mesh_resolution = kDefaultMeshResolution;  // triangle size of the surface mesh, A (Analysis::meshes)
  bool report = true;  // Analysis::report made, and ligands (read by it and the writers only)
};

// Everything one structure produced; owns all of it.
struct Analysis {
  std::string file;  // as given
  AnalysisOptions options;
  Structure structure;
  PocketSearch search;
  std::vector<LigandSite> ligands;  // where each hetero group lies (ligand_sites), by Structure::hetero_groups
  std::vector<std::string> tunnel_starts;  // labels of the starts
  std::vector<TunnelPath> paths;           // tunnels and pores (find_tunnels)
  std::vector<TunnelPath> cycle_paths;     // the way through each of search.cavities.tunnels (find_tunnels)
  // The surface and casts (pocket_meshes) when options.outputs.meshes, made
  // of the search's solvent-excluded body, which is then freed
  // (search.bodies is empty); none otherwise.
  std::optional<PocketMeshes> meshes;
  double tunnels_seconds = 0;
  std::size_t radius_fallbacks = 0;  // atoms no rule of the radius file matched
  std::shared_ptr<const Report> report;  // pocket_report(run()) if options.report; report_text() is its file

  // The writers' view of it (outputs/pocket_run.hpp; borrows from *this: keep
  // *this alive and in place).
  PocketRun run() const;
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
