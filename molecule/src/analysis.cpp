// SPDX-License-Identifier: Apache-2.0
#include "molecule/analysis.hpp"

#include "outputs/pocket_outputs.hpp"
#include "outputs/pocket_report.hpp"
#include "molecule/radius_file.hpp"
#include "molecule/tunnel_start.hpp"

#include <chrono>
#include <new>
#include <utility>

namespace molecule {

namespace {

template <class Read>
Analysis analysed(const std::string& file, const AnalysisOptions& options, Read&& read) {
  Analysis a;
  a.file = file;
  a.options = options;
  try {
    a.structure = read();
    if (!options.radii_file.empty()) {
      try {
        a.radius_fallbacks = apply_radius_file(read_radius_file(options.radii_file), a.structure.atoms);
      } catch (const alpha::Error& e) {
        throw AnalysisError(e.kind(), e.what());  // names the radius file
      }
    }
    const std::size_t atoms = a.structure.atoms.size();
    if (options.max_atoms > 0 && atoms > options.max_atoms)
      throw AnalysisError(FailureKind::LimitExceeded, file + ": " + std::to_string(atoms) +
                                                          " atoms, more than --max-atoms " +
                                                          std::to_string(options.max_atoms),
                          /*skipped=*/true);
    try {
      a.search = search_pockets(a.structure, options.cavities, options.ranking, options.outputs.meshes);
    } catch (const alpha::Error& e) {
      throw AnalysisError(e.kind(), alpha::in_file(file, e).what());  // e.g. all atoms in one plane
    }
    if (options.outputs.meshes) {
      a.meshes = pocket_meshes(a.search, options.mesh_resolution);
      a.search.bodies = {};  // what they were kept for is done
    }
    // The ligands' sites are read by the report and the output files only.
    if (options.report) a.ligands = ligand_sites(a.structure, a.search);
    const auto start = std::chrono::steady_clock::now();
    std::vector<TunnelStart> starts;
    try {
      starts = tunnel_starts(options.tunnels_from, a.structure, a.search.cavities);
    } catch (const alpha::Error& e) {
      throw AnalysisError(e.kind(), alpha::in_file(file, e).what());
    }
    for (const TunnelStart& s : starts) a.tunnel_starts.push_back(s.label);
    std::vector<double> radii;
    for (const Atom& atom : a.structure.atoms) radii.push_back(atom.radius);
    TunnelNetwork network =
        find_tunnels(a.search.shape->complex(), radii, starts, a.search.cavities.tunnels, options.tunnels);
    a.paths = std::move(network.paths);
    a.cycle_paths = std::move(network.cycles);
    a.tunnels_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.report) a.report = std::make_shared<const Report>(Report{pocket_report(a)});
  } catch (const AnalysisError&) {
    throw;
  } catch (const StructureError& e) {
    throw AnalysisError(e.kind(), e.what());  // names the file
  } catch (const alpha::Error& e) {
    throw AnalysisError(e.kind(), alpha::in_file(file, e).what());
  } catch (const std::bad_alloc&) {
    throw AnalysisError(FailureKind::LimitExceeded, file + ": out of memory");
  } catch (const std::exception& e) {
    throw AnalysisError(FailureKind::Internal, file + ": " + e.what());
  }
  return a;
}

}  // namespace

Analysis analyse(const std::string& file, const AnalysisOptions& options) {
  return analysed(file, options, [&] { return read_structure(file, options.structure); });
}

Analysis analyse_content(const std::string& file, std::string_view content, const AnalysisOptions& options) {
  return analysed(file, options, [&] { return parse_structure(content, file, options.structure); });
}

Analysis analyse_structure(const std::string& name, Structure structure, const AnalysisOptions& options) {
  return analysed(name, options, [&] { return std::move(structure); });
}

std::string report_text(const Analysis& analysis) { return report_file_text(analysis.report->json); }

std::vector<std::string> write_outputs(const Analysis& analysis, PocketOutputDir& out) {
  return out.write(analysis, analysis.report->json);
}

std::vector<std::string> write_outputs(const Analysis& analysis, const std::string& dir,
                                       std::vector<std::string>* warnings) {
  PocketOutputDir out(dir, analysis.options.outputs);
  std::vector<std::string> written = write_outputs(analysis, out);
  if (warnings) *warnings = out.warnings();
  return written;
}

}  // namespace molecule
