#include "common.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "structure_file.hpp"

namespace alphapocket {
namespace {

// Library errors (too few distinct points, all coplanar, too many
// simplices, ...) are about this input: name the file.
template <class F>
auto naming_file(const std::string& file, F&& build) {
  try {
    return build();
  } catch (const alpha::Error& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
}

}  // namespace

void add_input_options(CLI::App& sub, InputOptions& opt) {
  sub.add_option("FILE", opt.file,
                 "Point file (x y z per line; x y z r with --weighted) or structure file "
                 "(.pdb .ent .cif .mmcif, optionally .gz: all atoms of the first model)")
      ->required();
  sub.add_flag("--weighted", opt.weighted,
               "Weighted points: read a radius r per point (weight r^2); for structure files every atom "
               "gets r = 1.8 A");
}

CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        const char* begin = text.data();
        const char* end = begin + text.size();
        if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') ++begin;  // "+2" is fine
        const auto [ptr, ec] = std::from_chars(begin, end, value);
        if (ec != std::errc() || ptr != end || !std::isfinite(value)) return "'" + text + "' is not a finite number";
        return {};
      },
      "NUMBER");
}

PointSet read_input(const InputOptions& opt) {
  Stopwatch read_time;
  PointSet set;
  if (!is_structure_file(opt.file)) {
    set = read_point_file(opt.file, opt.weighted);
  } else {
    set.points = read_structure_atoms(opt.file);
    if (opt.weighted) set.weights.assign(set.points.size(), kDefaultAtomRadius * kDefaultAtomRadius);
  }
  spdlog::info("read {} {}points from {} in {:.3f} s", set.points.size(), opt.weighted ? "weighted " : "",
               opt.file, read_time.seconds());
  return set;
}

std::unique_ptr<alpha::Triangulation> triangulate(PointSet input, const std::string& file) {
  return naming_file(file, [&] {
    return std::make_unique<alpha::Triangulation>(std::move(input.points), std::move(input.weights));
  });
}

AlphaInput load_alpha_complex(const InputOptions& opt) {
  AlphaInput in;
  PointSet points = read_input(opt);
  in.points = points.points.size();
  Stopwatch build_time;
  in.triangulation = triangulate(std::move(points), opt.file);
  spdlog::info("{} triangulation: {:.3f} s, {} vertices, {} finite cells",
               opt.weighted ? "regular" : "Delaunay", build_time.seconds(), in.triangulation->num_vertices(),
               in.triangulation->num_finite_cells());
  Stopwatch complex_time;
  in.complex = naming_file(opt.file, [&] { return std::make_unique<alpha::AlphaComplex>(*in.triangulation); });
  spdlog::info("alpha complex: {:.3f} s, {} critical values, {} persistence pairs", complex_time.seconds(),
               in.complex->spectrum_size(), in.complex->persistence().size());
  return in;
}

void flush_stdout() {
  if (std::fflush(stdout) != 0) throw std::runtime_error("cannot write to standard output");
}

}  // namespace alphapocket
