#include "molecule/analysis.hpp"

#include <new>
#include <utility>

namespace molecule {

std::string_view failure_name(FailureKind kind) {
  switch (kind) {
    case FailureKind::BadInput: return "bad_input";
    case FailureKind::LimitExceeded: return "limit_exceeded";
    case FailureKind::Internal: break;
  }
  return "internal";
}

PocketRun Analysis::run() const {
  PocketRun r;
  r.file = file;
  r.structure = &structure;
  r.options = options.cavities;
  r.version = options.version;
  r.search = &search;
  r.mesh_format = options.outputs.meshes ? options.mesh_format : "";
  r.min_plddt = options.structure.min_plddt;
  return r;
}

namespace {

template <class Read>
Analysis analysed(const std::string& file, const AnalysisOptions& options, Read&& read) {
  Analysis a;
  a.file = file;
  a.options = options;
  try {
    a.structure = read();
    const std::size_t atoms = a.structure.atoms.size();
    if (options.max_atoms > 0 && atoms > options.max_atoms)
      throw AnalysisError(FailureKind::LimitExceeded, file + ": " + std::to_string(atoms) +
                                                          " atoms, more than --max-atoms " +
                                                          std::to_string(options.max_atoms),
                          /*skipped=*/true);
    try {
      a.search = search_pockets(a.structure, options.cavities);
    } catch (const alpha::Error& e) {
      throw AnalysisError(FailureKind::BadInput, file + ": " + e.what());  // e.g. all atoms in one plane
    }
    a.report = pocket_report(a.run());
  } catch (const AnalysisError&) {
    throw;
  } catch (const StructureError& e) {
    throw AnalysisError(FailureKind::BadInput, e.what());
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

std::vector<std::string> write_outputs(const Analysis& analysis, PocketOutputDir& out) {
  return out.write(analysis.run(), analysis.report);
}

}  // namespace molecule
