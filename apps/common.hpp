// SPDX-License-Identifier: Apache-2.0
// What the subcommands share: FILE (a point file or a structure file) and
// its options, the points of FILE, their triangulation and alpha complex,
// and a few helpers for options and output.
#pragma once
#include <chrono>
#include <limits>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "alpha/point_set_complex.hpp"
#include "alpha/triangulation.hpp"
#include "molecule/analysis.hpp"
#include "molecule/structure.hpp"
#include "point_file.hpp"

namespace alphapocket {

// Larger probes are refused: they make nothing of interest, and the
// areas and volumes of balls that large lose their digits.
inline constexpr double kMaxProbe = 100;

struct InputOptions {
  std::string file;
  bool weighted = false;                 // point files: x y z r per line
  molecule::StructureOptions structure;  // structure files: which atoms
  double probe = molecule::CavityOptions{}.probe;  // structure files: atom i is (x_i, (r_i + probe)^2)
  unsigned threads = 1;                  // the triangulation's (add_threads_option)
  // The options that only apply to structure files, to reject them when
  // FILE is a point file.
  std::vector<const CLI::Option*> structure_only;
};

// Adds the positional FILE (required), --weighted, and the structure file
// options (add_structure_options).
void add_input_options(CLI::App& sub, InputOptions& opt);

// Adds -j/--jobs N, the triangulation's threads, to the commands whose
// printed results do not depend on how its cells are numbered.
void add_threads_option(CLI::App& sub, unsigned& threads);

// Adds --probe, --model, --chains, --keep-hydrogens, --keep-waters and
// --keep-hetero[=CODES], --keep-cofactors (help group "Structure files"); returns them.
std::vector<const CLI::Option*> add_structure_options(CLI::App& sub, molecule::StructureOptions& selection,
                                                      double& probe);

// Adds the options of the cavity search and its outputs that `pockets` and
// `batch` share: --min-volume, --mesh.
void add_cavity_options(CLI::App& sub, molecule::AnalysisOptions& options);

// Adds --outputs LIST (report,csv,pml,pdb,meshes,tunnels,html or all; checked, a
// wrong item is a usage error); `where` names the folder they go to in the help.
void add_outputs_option(CLI::App& sub, std::string& list, const std::string& where);

// The outputs that --outputs `list` selects, with the meshes added when
// --mesh or --mesh-resolution is on the command line: asking for a mesh
// format is asking for meshes. html, unless named in `list`, only when the
// viewer files are installed (molecule/report_assets.hpp).
molecule::OutputSelection selected_outputs(const CLI::App& sub, const std::string& list);

// A structure file read through the molecule layer; logs (info) what was
// kept and dropped, and its warnings.
molecule::Structure read_structure_file(const std::string& file, const molecule::StructureOptions& options);

// Logs what analyse() read, kept and dropped, its warnings and the stages'
// timings (at `level`; warnings always as warnings).
void log_analysis(const molecule::Analysis& analysis, spdlog::level::level_enum level = spdlog::level::info);

// Alpha values on the command line: squared radii, finite (the validator
// rejects inf and nan), and the convention of which simplices are present.
inline constexpr const char* kAlphaSqHelp =
    "alpha is a SQUARED radius (alpha_sq); for weighted points (--weighted, or a structure file) it may be "
    "negative (a ball of radius r enters at -r^2). A simplex whose value equals alpha_sq counts as present "
    "(CGAL's convention).";
inline constexpr double kNoBound = std::numeric_limits<double>::infinity();
// A finite number within [lo, hi], with a plain message otherwise.
CLI::Validator finite_number(double lo = -kNoBound, double hi = kNoBound);
// An output directory name: -o '' is a usage error, not "no -o".
CLI::Validator output_directory_name();

// The points of a point file, or the atoms of a structure file as
// weighted points (always: ProtOr radius + probe, molecule::atom_balls),
// the atoms themselves into *atoms when asked. Logs what was read.
PointSet read_input(const InputOptions& opt, std::vector<molecule::Atom>* atoms = nullptr);

// Library errors (too few distinct points, all coplanar, too many
// simplices, ...) are about this input: rethrown naming the file, same kind.
template <class F>
auto naming_file(const std::string& file, F&& build) {
  try {
    return build();
  } catch (const alpha::Error& e) {
    throw alpha::in_file(file, e);
  }
}

// The triangulation of the points; library errors about the input (too few
// distinct points, all coplanar, ...) are rethrown naming the file.
std::unique_ptr<alpha::Triangulation> triangulate(PointSet input, const std::string& file, unsigned threads = 1);

// FILE read, triangulated and turned into its alpha complex, with timings
// logged.
struct AlphaInput {
  std::size_t points = 0;  // points read
  alpha::PointSetComplex shape;
};
AlphaInput load_alpha_complex(const InputOptions& opt);

class Stopwatch {
public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Flushes stdout; throws when the results could not be written.
void flush_stdout();

// A value to print: -0 becomes 0 (a critical value of 0 may come out as -0).
inline double printable(double v) { return v == 0 ? 0.0 : v; }

}  // namespace alphapocket
