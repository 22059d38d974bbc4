// alphapocket delaunay FILE [--weighted] [--check] [--json]
//
// Builds the Delaunay (or, with --weighted, the regular) triangulation of a
// point file or of the atoms of a structure file and reports its size.
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <sys/resource.h>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"
#include "alpha/validation.hpp"
#include "commands.hpp"
#include "point_file.hpp"
#include "structure_file.hpp"

namespace alphapocket {
namespace {

// Radius given to every atom of a structure file with --weighted, until a
// molecule layer assigns radii per element.
constexpr double kDefaultAtomRadius = 1.8;

struct DelaunayOptions {
  std::string file;
  bool weighted = false;
  bool check = false;
  bool json = false;
};

class Stopwatch {
public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string mib(std::size_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
  return buf;
}

void log_stage_counts(const char* name, const alpha::StageCounts& s) {
  spdlog::info("{} predicates: {} calls, {} filtered, {} exact, {} perturbed", name, s.calls(),
               s.filtered, s.exact, s.perturbed);
}

// Peak resident set size of this process, in bytes (0 if unknown).
std::size_t peak_rss_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return std::size_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

PointSet read_input(const DelaunayOptions& opt) {
  if (!is_structure_file(opt.file)) return read_point_file(opt.file, opt.weighted);
  PointSet set;
  set.points = read_structure_atoms(opt.file);
  if (opt.weighted) set.weights.assign(set.points.size(), kDefaultAtomRadius * kDefaultAtomRadius);
  return set;
}

int run_delaunay(const DelaunayOptions& opt) {
  Stopwatch read_time;
  PointSet input = read_input(opt);
  const std::size_t n = input.points.size();
  spdlog::info("read {} {}points from {} in {:.3f} s", n, opt.weighted ? "weighted " : "", opt.file,
               read_time.seconds());

  Stopwatch build_time;
  // Library errors (too few distinct points, all coplanar, ...) are about
  // this input: name the file.
  auto tri = [&] {
    try {
      return std::make_unique<alpha::Triangulation>(std::move(input.points), std::move(input.weights));
    } catch (const alpha::Error& e) {
      throw std::runtime_error(opt.file + ": " + e.what());
    }
  }();
  const alpha::Triangulation& t = *tri;
  const double build_s = build_time.seconds();

  Stopwatch simplices_time;
  const alpha::Simplices s(t);
  const double simplices_s = simplices_time.seconds();

  spdlog::info("triangulation: {:.3f} s ({:.2f} us/point), {} vertices, {} finite cells", build_s,
               1e6 * build_s / double(n), t.num_vertices(), t.num_finite_cells());
  spdlog::info("simplices: {:.3f} s, {} edges, {} triangles", simplices_s, s.num_edges(),
               s.num_triangles());
  spdlog::info("memory: triangulation {} ({:.0f} bytes/point), simplices {} ({:.0f} bytes/point), peak RSS {}",
               mib(t.memory_bytes()), double(t.memory_bytes()) / double(n), mib(s.memory_bytes()),
               double(s.memory_bytes()) / double(n), mib(peak_rss_bytes()));
  log_stage_counts("orient3d", t.predicate_stats().orient);
  log_stage_counts("power test", t.predicate_stats().power);

  bool valid = true;
  if (opt.check) {
    Stopwatch check_time;
    const alpha::ValidationReport report = alpha::validate(t);
    valid = report.valid;
    spdlog::info("validation: {:.3f} s, {}", check_time.seconds(), valid ? "valid" : "INVALID");
    for (const std::string& problem : report.problems) spdlog::error("invalid triangulation: {}", problem);
  }

  if (opt.json) {
    nlohmann::ordered_json j;
    j["points"] = n;
    j["vertices"] = t.num_vertices();
    j["duplicates"] = t.num_duplicates();
    j["hidden"] = t.num_hidden();
    j["edges"] = s.num_edges();
    j["triangles"] = s.num_triangles();
    j["tetrahedra"] = t.num_finite_cells();
    j["hull_triangles"] = s.num_hull_triangles();
    if (opt.check) j["valid"] = valid;
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s: %zu points, %zu vertices (%zu duplicates, %zu hidden)\n", opt.file.c_str(), n,
                t.num_vertices(), t.num_duplicates(), t.num_hidden());
    std::printf("%s triangulation: %zu edges, %zu triangles (%zu on the hull), %zu tetrahedra\n",
                t.weighted() ? "regular" : "Delaunay", s.num_edges(), s.num_triangles(),
                s.num_hull_triangles(), t.num_finite_cells());
    if (opt.check) std::printf("valid: %s\n", valid ? "yes" : "NO");
  }
  if (std::fflush(stdout) != 0) throw std::runtime_error("cannot write to standard output");
  return valid ? 0 : 1;
}

}  // namespace

Subcommand add_delaunay_command(CLI::App& app) {
  auto opt = std::make_shared<DelaunayOptions>();
  CLI::App* sub = app.add_subcommand("delaunay", "Build the Delaunay (or regular) triangulation of a point or structure file");
  sub->add_option("FILE", opt->file,
                  "Point file (x y z per line; x y z r with --weighted) or structure file "
                  "(.pdb .ent .cif .mmcif, optionally .gz: all atoms of the first model)")
      ->required();
  sub->add_flag("--weighted", opt->weighted,
                "Weighted points: read a radius r per point (weight r^2); for structure files every atom "
                "gets r = 1.8 A");
  sub->add_flag("--check", opt->check, "Verify the triangulation exactly; exit code 1 if it is invalid");
  sub->add_flag("--json", opt->json, "Print one JSON object on stdout instead of a summary");
  return {sub, [opt] { return run_delaunay(*opt); }};
}

}  // namespace alphapocket
