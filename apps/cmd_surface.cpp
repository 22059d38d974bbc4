// alphapocket surface FILE [--probe R] [--json] [--per-atom] [--sa-only]
//
// Solvent-accessible surface (SAS) area and volume of a molecule: the union
// of its atom balls, radius = ProtOr radius + probe, measured analytically
// over the weighted alpha complex at alpha_sq = 0 (alpha::UnionOfBalls), so
// there is no resolution to choose (unlike Lee-Richards slices or
// Shrake-Rupley points). With --per-atom, the SAS area of every atom. A
// point file with --weighted gives the union of its balls.
//
// For a structure, also the solvent-excluded (molecular, Connolly) surface:
// the SAS union eroded by the probe (alpha::ErodedUnion); null for a point
// file, whose balls carry no probe, and with --sa-only (it takes several
// times as long as the SAS).
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "alpha/eroded_union.hpp"
#include "alpha/input_file.hpp"
#include "alpha/union_of_balls.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "molecule/radii.hpp"
#include "molecule/structure.hpp"

namespace alphapocket {
namespace {

struct SurfaceOptions {
  InputOptions input;
  bool json = false;
  bool per_atom = false;
  bool sa_only = false;
};

// The balls of FILE, and for a structure file its atoms (names for
// --per-atom).
struct Balls {
  PointSet set;
  std::optional<std::vector<molecule::Atom>> atoms;
};

Balls read_balls(const InputOptions& opt) {
  const bool structure = molecule::is_structure_file(opt.file);
  if (!structure && !opt.weighted) {
    alpha::read_input_file(opt.file);  // a missing file or a directory is the first thing to say
    throw std::runtime_error(opt.file +
                             ": a point file has no balls without --weighted (x y z r per line): its surface is empty");
  }
  InputOptions any_size = opt;
  any_size.structure.min_atoms = 1;  // one atom has a surface (see run_surface)
  Balls b;
  std::vector<molecule::Atom> atoms;
  b.set = read_input(any_size, &atoms);
  if (structure) b.atoms = std::move(atoms);
  return b;
}

nlohmann::ordered_json atom_json(const molecule::Atom& a, double area) {
  nlohmann::ordered_json j;
  j["serial"] = a.serial;
  j["name"] = a.name;
  j["residue"] = a.residue_name;
  j["seq_num"] = a.seq_num;
  j["icode"] = molecule::icode_text(a.icode);
  j["chain"] = a.chain;
  j["area"] = area;
  return j;
}

int run_surface(const SurfaceOptions& opt) {
  Balls balls = read_balls(opt.input);
  const std::size_t n = balls.set.points.size();
  Stopwatch build_time;
  // Any set of balls has a union, but a triangulation needs four points
  // not in one plane: far points make a small or flat molecule one.
  if (alpha::affine_dimension(balls.set.points) < 3) alpha::add_far_points(balls.set.points, balls.set.weights);
  const std::unique_ptr<alpha::Triangulation> t = triangulate(balls.set, opt.input.file);
  const alpha::AlphaComplex complex(*t);
  const double build_seconds = build_time.seconds();
  Stopwatch measure_time;
  const alpha::UnionOfBalls u(complex);
  spdlog::info("regular triangulation and alpha complex: {:.3f} s; union of balls: {:.3f} s ({} hidden balls)",
               build_seconds, measure_time.seconds(), t->num_hidden());
  const auto areas = u.ball_areas();
  const bool structure = balls.atoms.has_value();
  std::optional<alpha::LayerShare> excluded;  // the eroded union's volume and area
  if (structure && !opt.sa_only) {
    Stopwatch ses_time;
    const alpha::LayerShare layer = alpha::ErodedUnion(u, opt.input.probe).layer();
    excluded = alpha::LayerShare{u.volume() - layer.volume, layer.area};
    spdlog::info("solvent-excluded surface: {:.3f} s", ses_time.seconds());
  }
  const auto excluded_json = [&](double alpha::LayerShare::*measure) {
    return excluded ? nlohmann::ordered_json((*excluded).*measure) : nlohmann::ordered_json(nullptr);
  };

  if (opt.json) {
    nlohmann::ordered_json j;
    j["atoms"] = n;
    j["probe"] = structure ? nlohmann::ordered_json(opt.input.probe) : nlohmann::ordered_json(nullptr);
    j["sa_area"] = u.area();
    j["sa_volume"] = u.volume();
    j["ms_volume"] = excluded_json(&alpha::LayerShare::volume);
    j["ms_area"] = excluded_json(&alpha::LayerShare::area);
    j["radii"] = structure ? std::string(molecule::kRadiusTable) : std::string("file");
    if (opt.per_atom) {
      j["per_atom"] = nlohmann::ordered_json::array();
      for (std::size_t i = 0; i < n; ++i) {
        if (structure) {
          j["per_atom"].push_back(atom_json((*balls.atoms)[i], areas[i]));
        } else {
          nlohmann::ordered_json p;
          p["index"] = i;
          p["area"] = areas[i];
          j["per_atom"].push_back(p);
        }
      }
    }
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s", fmt::format("{}: {} {}, {}\n", opt.input.file, n, structure ? "atoms" : "balls",
                                  structure ? fmt::format("{} radii + probe {} A", molecule::kRadiusTable,
                                                          opt.input.probe)
                                            : std::string("radii from the file"))
                          .c_str());
    std::printf("%s", fmt::format("solvent-accessible area    {:.3f} A^2\nsolvent-accessible volume  {:.3f} A^3\n",
                                  u.area(), u.volume())
                          .c_str());
    if (excluded)
      std::printf("%s", fmt::format("solvent-excluded area      {:.3f} A^2\nsolvent-excluded volume    {:.3f} A^3\n",
                                    excluded->area, excluded->volume)
                            .c_str());
    if (opt.per_atom) {
      std::printf("%s", structure ? "serial name residue seq_num chain area\n" : "index area\n");
      for (std::size_t i = 0; i < n; ++i) {
        if (structure) {
          const molecule::Atom& a = (*balls.atoms)[i];
          std::printf("%s", fmt::format("{} {} {} {}{} {} {:.3f}\n", a.serial, a.name, a.residue_name, a.seq_num,
                                        molecule::icode_text(a.icode), a.chain, areas[i])
                                .c_str());
        } else {
          std::printf("%s", fmt::format("{} {:.3f}\n", i, areas[i]).c_str());
        }
      }
    }
  }
  flush_stdout();
  return 0;
}

}  // namespace

Subcommand add_surface_command(CLI::App& app) {
  auto opt = std::make_shared<SurfaceOptions>();
  CLI::App* sub = app.add_subcommand(
      "surface",
      "Solvent-accessible (SAS) and solvent-excluded (molecular) surface area and volume of a structure: the union "
      "of its atom balls (ProtOr radius + probe) and that union eroded by the probe, from the weighted alpha "
      "complex; SAS area per atom with --per-atom");
  add_input_options(*sub, opt->input);
  sub->add_flag("--json", opt->json, "Print one JSON object on stdout instead of a summary");
  sub->add_flag("--per-atom", opt->per_atom, "Also print the SAS area of every atom (ball)");
  sub->add_flag("--sa-only", opt->sa_only,
                "Skip the solvent-excluded (molecular) surface, which takes several times as long as the SAS: "
                "ms_volume and ms_area are null");
  return {sub, [opt] { return run_surface(*opt); }};
}

}  // namespace alphapocket
