// SPDX-License-Identifier: Apache-2.0
// alphapocket delaunay FILE [--weighted] [--check] [--json]
//
// Builds the Delaunay (or, with --weighted, the regular) triangulation of a
// point file or of the atoms of a structure file and reports its size.
#include <cstdio>
#include <memory>
#include <string>
#include <utility>

#include <sys/resource.h>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "alpha/simplices.hpp"
#include "alpha/triangulation.hpp"
#include "alpha/validation.hpp"
#include "commands.hpp"
#include "common.hpp"

namespace alphapocket {
namespace {

struct DelaunayOptions {
  InputOptions input;
  bool check = false;
  bool json = false;
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

int run_delaunay(const DelaunayOptions& opt) {
  PointSet input = read_input(opt.input);
  const std::size_t n = input.points.size();

  Stopwatch build_time;
  const auto tri = triangulate(std::move(input), opt.input.file, opt.input.threads);
  const alpha::Triangulation& t = *tri;
  const double build_s = build_time.seconds();

  const alpha::SimplexCounts s = alpha::count_simplices(t);  // no edge and triangle tables

  spdlog::info("triangulation: {:.3f} s ({:.2f} us/point), {} vertices, {} finite cells", build_s,
               1e6 * build_s / double(n), t.num_vertices(), t.num_finite_cells());
  spdlog::info("simplices: {} edges, {} triangles", s.edges, s.triangles);
  spdlog::info("memory: triangulation {} ({:.0f} bytes/point), peak RSS {}", mib(t.memory_bytes()),
               double(t.memory_bytes()) / double(n), mib(peak_rss_bytes()));
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
    j["edges"] = s.edges;
    j["triangles"] = s.triangles;
    j["tetrahedra"] = t.num_finite_cells();
    j["hull_triangles"] = s.hull_triangles;
    if (opt.check) j["valid"] = valid;
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s: %zu points, %zu vertices (%zu duplicates, %zu hidden)\n", opt.input.file.c_str(), n,
                t.num_vertices(), t.num_duplicates(), t.num_hidden());
    std::printf("%s triangulation: %zu edges, %zu triangles (%zu on the hull), %zu tetrahedra\n",
                t.weighted() ? "regular" : "Delaunay", s.edges, s.triangles,
                s.hull_triangles, t.num_finite_cells());
    if (opt.check) std::printf("valid: %s\n", valid ? "yes" : "NO");
  }
  flush_stdout();
  return valid ? 0 : 1;
}

}  // namespace

Subcommand add_delaunay_command(CLI::App& app) {
  auto opt = std::make_shared<DelaunayOptions>();
  CLI::App* sub = app.add_subcommand("delaunay", "Build the Delaunay (or regular) triangulation of a point or structure file");
  add_input_options(*sub, opt->input);
  add_threads_option(*sub, opt->input.threads);
  sub->add_flag("--check", opt->check, "Verify the triangulation exactly; exit code 1 if it is invalid");
  sub->add_flag("--json", opt->json, "Print one JSON object on stdout instead of a summary");
  return {sub, [opt] { return run_delaunay(*opt); }};
}

}  // namespace alphapocket
