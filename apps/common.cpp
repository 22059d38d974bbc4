// SPDX-License-Identifier: Apache-2.0
#include "common.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <limits>
#include <system_error>
#include <utility>

#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/output_selection.hpp"
#include "outputs/report_assets.hpp"
#include "molecule/radii.hpp"

namespace alphapocket {
namespace {

// A PDB chemical component code (1-5 letters and digits), upper-cased; or
// "all" (the flag without a value).
CLI::Validator hetero_code() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text == "all") return {};
        const bool ok = !text.empty() && text.size() <= 5 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)); });
        if (!ok) return "'" + text + "' is not a residue code (1-5 letters and digits, e.g. ZN,HEM)";
        for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
        return {};
      },
      "");
}

// A ranking's name, as the enum's number CLI11 stores; a plain message
// otherwise (CLI11's own names its internal map).
CLI::Validator ranking_name() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          text = std::to_string(int(molecule::parse_site_ranking(text)));
        } catch (const alpha::Error& e) {
          return e.what();
        }
        return {};
      },
      "");
}

// "report,meshes": each item a known output; the error names the unknown one.
CLI::Validator output_list() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          molecule::parse_output_selection(text);
        } catch (const alpha::Error& e) {
          return e.what();
        }
        return {};
      },
      "");
}

}  // namespace

void add_outputs_option(CLI::App& sub, std::string& list, const std::string& where) {
  sub.add_option("--outputs", list, "What to write to " + where + ": any of report,csv,pml,pdb,meshes,tunnels,html, or all")
      ->type_name("LIST")
      ->capture_default_str()
      ->check(output_list());
}

molecule::OutputSelection selected_outputs(const CLI::App& sub, const std::string& list) {
  molecule::OutputSelection selection = molecule::parse_output_selection(list);
  if (sub.count("--mesh") > 0 || sub.count("--mesh-resolution") > 0) selection.meshes = true;
  // html needs Mol* (report_assets.hpp): asked by name, an error without it; by
  // default or `all`, left out with a warning.
  const std::string missing = selection.html ? molecule::missing_viewer_assets() : "";
  if (!missing.empty()) {
    if (sub.count("--outputs") > 0 && ("," + list + ",").find(",html,") != std::string::npos)
      alpha::fail(missing, alpha::ErrorKind::BadInput);
    spdlog::warn("{}", missing);
    selection.html = false;
  }
  return selection;
}

void add_input_options(CLI::App& sub, InputOptions& opt) {
  sub.add_option("FILE", opt.file,
                 "Point file (x y z per line; x y z r with --weighted) or structure file (.pdb .ent .cif "
                 ".mmcif, optionally .gz), whose atoms are always weighted points: ball radius = ProtOr radius "
                 "+ probe")
      ->required();
  sub.add_flag("--weighted", opt.weighted,
               "Point files: read a radius r per point (weight r^2). Structure files are always weighted, so "
               "this changes nothing for them");
  opt.structure_only = add_structure_options(sub, opt.structure, opt.probe);
}

void add_threads_option(CLI::App& sub, unsigned& threads) {
  sub.add_option("-j,--jobs", threads,
                 "Threads for the triangulation and what follows, from 2^15 points on (the output is the same for "
                 "any number)")
      ->capture_default_str()
      ->type_name("N")
      ->check(CLI::Range(1u, 254u).description(""));
}

std::vector<const CLI::Option*> add_structure_options(CLI::App& sub, molecule::StructureOptions& selection,
                                                      double& probe) {
  const std::string group = "Structure files";
  return {
      sub.add_option("--probe", probe, "Solvent probe radius added to every atom radius, A (0: van der Waals balls)")
          ->capture_default_str()
          ->type_name("R")
          ->check(finite_number(0, kMaxProbe))
          ->group(group),
      sub.add_option("--model", selection.model, "Model number to read (MODEL n; default: the first model)")
          ->type_name("N")
          ->check(CLI::PositiveNumber.description(""))
          ->group(group),
      // One value per --chains (repeat it, or give A,B): FILE after it is FILE.
      sub.add_option("--chains", selection.chains, "Chains to keep, e.g. A,B (default: all)")
          ->type_name("A,B")
          ->delimiter(',')
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
          ->group(group),
      sub.add_flag("--keep-hydrogens", selection.keep_hydrogens, "Keep hydrogen atoms (dropped by default)")
          ->group(group),
      sub.add_flag("--keep-waters", selection.keep_waters, "Keep waters (dropped by default)")->group(group),
      // A flag that takes its optional value after '=' only: FILE after it stays FILE.
      sub.add_flag("--keep-hetero{all}", selection.keep_hetero_codes,
                   "Keep hetero groups as part of the protein: all, or with =CODES those named, e.g. "
                   "--keep-hetero=ZN,HEM (dropped by default and reported as ligands with their site; modified "
                   "residues of a polymer are always kept)")
          ->type_name("[=CODES]")
          ->delimiter(',')
          ->transform(hetero_code())
          ->each([&selection](const std::string& code) { selection.keep_hetero |= code == "all"; })
          ->group(group),
      sub.add_flag("--keep-cofactors", selection.keep_cofactors,
                   "Keep common metal ions and cofactors (ZN, MG, CA, FE, HEM, FAD, NAD, SF4, ...: docs/cli.md) as part "
                   "of the protein; other hetero groups are still dropped")
          ->group(group),
      sub.add_option("--min-plddt", selection.min_plddt,
                     "Predicted models (AlphaFold): leave out residues with a lower pLDDT, 0-100 (default: keep all)")
          ->type_name("P")
          ->check(finite_number(0, 100))
          ->group(group),
      sub.add_option("--max-input-mb", selection.max_input_mib,
                     "Largest structure file read, MiB, after gzip decompression (a bound on memory)")
          ->capture_default_str()
          ->type_name("MB")
          ->check(CLI::Range(std::size_t(1), std::size_t(1) << 20).description(""))
          ->group(group),
  };
}

void add_cavity_options(CLI::App& sub, molecule::AnalysisOptions& options) {
  sub.add_option("--min-volume", options.cavities.min_volume,
                 "Drop pockets and voids whose SA volume (space the probe centre reaches) is below this, A^3")
      ->capture_default_str()
      ->type_name("V")
      ->check(finite_number(0));
  sub.add_option("--mesh", options.mesh_format, "Write the meshes (molecular surface, pocket and void casts) in this format: ply, obj, off or stl")
      ->type_name("FMT")
      ->capture_default_str()
      ->check(CLI::IsMember({"ply", "obj", "off", "stl"}).description(""));
  sub.add_option("--radii", options.radii_file,
                 "Radius file: RESIDUE ATOM RADIUS lines with ? and * wildcards, element SYMBOL RADIUS, or HOLE's "
                 ".rad format (VDWR records)");
  sub.add_option("--tunnels-from", options.tunnels_from,
                 "Where tunnels start: auto (the top 3 sites), none, a site rank, residues A:45,A:67, or x,y,z")
      ->capture_default_str();
  sub.add_option("--tunnel-probe", options.tunnels.probe, "Narrowest probe a tunnel or pore lets through, A")
      ->capture_default_str()
      ->type_name("R")
      ->check(finite_number())
      ->check(CLI::PositiveNumber.description(""));
  sub.add_flag("--pores", options.tunnels.pores, "Also find pores: paths across the molecule from solvent to solvent");
  sub.add_option("--ranking", options.ranking,
                 "Order of the sites: probability (the ligandability model's) or geometric (the score)")
      ->default_str("probability")
      ->type_name("ORDER")
      ->transform(ranking_name());
  sub.add_option("--mesh-resolution", options.mesh_resolution,
                 "Triangle size of the meshes (lattice spacing), A; finer is closer to the analytic surface and slower")
      ->capture_default_str()
      ->check(finite_number())
      ->check(CLI::PositiveNumber.description(""));
}

CLI::Validator finite_number(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double value = 0;
        const char* begin = text.data();
        const char* end = begin + text.size();
        if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') ++begin;  // "+2" is fine
        const auto [ptr, ec] = std::from_chars(begin, end, value);
        if (ec != std::errc() || ptr != end || !std::isfinite(value)) return "'" + text + "' is not a finite number";
        // Plain bounds: CLI::Range would print the largest double in full.
        const auto bound = [](double b) { return fmt::format("{:g}", b); };
        if (value < lo && hi == kNoBound) return "'" + text + "' is below " + bound(lo);
        if (value < lo || value > hi) return "'" + text + "' is not between " + bound(lo) + " and " + bound(hi);
        return {};
      },
      "");
}

CLI::Validator output_directory_name() {
  return CLI::Validator([](std::string& text) { return text.empty() ? "an empty name is not an output directory" : ""; },
                        "");
}

molecule::Structure read_structure_file(const std::string& file, const molecule::StructureOptions& options) {
  molecule::Structure structure = molecule::read_structure(file, options);
  spdlog::info("{}: {}", file, molecule::summary(structure.report));
  for (const std::string& warning : structure.report.warnings) spdlog::warn("{}: {}", file, warning);
  return structure;
}

void log_analysis(const molecule::Analysis& a, spdlog::level::level_enum level) {
  const molecule::Cavities& c = a.search.cavities;
  spdlog::log(level, "{}: {}", a.file, molecule::summary(a.structure.report));
  for (const std::string& warning : a.structure.report.warnings) spdlog::warn("{}: {}", a.file, warning);
  spdlog::log(level, "regular triangulation and alpha complex: {:.3f} s, {} atoms, {} finite cells",
              a.search.complex_seconds, a.structure.atoms.size(), a.search.shape->triangulation().num_finite_cells());
  spdlog::log(level, "cavities: {:.3f} s, {} pockets, {} voids, {} tunnels", a.search.cavities_seconds,
              c.pockets.size(), c.voids.size(), c.tunnels.size());
  if (a.radius_fallbacks > 0)
    spdlog::warn("{}: {} atoms matched no rule: built-in element radii", a.options.radii_file, a.radius_fallbacks);
  spdlog::log(level, "tunnels and pores: {:.3f} s, {} paths from {} starts", a.tunnels_seconds, a.paths.size(),
              a.tunnel_starts.size());
  spdlog::log(level, "site features and ligandability: {:.3f} s", a.search.ranking_seconds);
}

PointSet read_input(const InputOptions& opt, std::vector<molecule::Atom>* atoms) {
  Stopwatch read_time;
  if (!molecule::is_structure_file(opt.file)) {
    std::string given;
    int count = 0;
    for (const CLI::Option* o : opt.structure_only)
      if (o->count() > 0) given += (count++ ? ", " : "") + o->get_name();
    if (count)
      throw alpha::Error(opt.file + ": a point file, but " + given + (count > 1 ? " are" : " is") +
                             " for structure files (.pdb .ent .cif .mmcif, optionally .gz)",
                         alpha::ErrorKind::BadInput);
    PointSet set = read_point_file(opt.file, opt.weighted);
    spdlog::info("read {} {}points from {} in {:.3f} s", set.points.size(), opt.weighted ? "weighted " : "", opt.file,
                 read_time.seconds());
    return set;
  }
  molecule::Structure structure = read_structure_file(opt.file, opt.structure);
  molecule::AtomBalls balls = molecule::atom_balls(structure.atoms, opt.probe);
  spdlog::info("read {} atoms from {} in {:.3f} s: weighted points, radius = {} radius + probe {} A",
               balls.points.size(), opt.file, read_time.seconds(), molecule::kRadiusTable, opt.probe);
  if (atoms) *atoms = std::move(structure.atoms);
  return {std::move(balls.points), std::move(balls.weights)};
}

std::unique_ptr<alpha::Triangulation> triangulate(PointSet input, const std::string& file, unsigned threads) {
  return naming_file(file, [&] {
    return std::make_unique<alpha::Triangulation>(std::move(input.points), std::move(input.weights), threads);
  });
}

AlphaInput load_alpha_complex(const InputOptions& opt) {
  PointSet points = read_input(opt);
  const std::size_t count = points.points.size();
  Stopwatch build_time;
  std::unique_ptr<alpha::Triangulation> t = triangulate(std::move(points), opt.file, opt.threads);
  spdlog::info("{} triangulation: {:.3f} s, {} vertices, {} finite cells", t->weighted() ? "regular" : "Delaunay",
               build_time.seconds(), t->num_vertices(), t->num_finite_cells());
  Stopwatch complex_time;
  AlphaInput in{count, naming_file(opt.file, [&] { return alpha::PointSetComplex(std::move(t), opt.threads); })};
  // Not the persistence pairs: they are computed when a command needs them.
  spdlog::info("alpha complex: {:.3f} s, {} critical values", complex_time.seconds(),
               in.shape.complex().spectrum_size());
  return in;
}

void flush_stdout() {
  // ferror too: a failed write can leave nothing buffered for fflush to fail on.
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    throw alpha::Error("cannot write to standard output", alpha::ErrorKind::BadInput);
}

}  // namespace alphapocket
