// SPDX-License-Identifier: Apache-2.0
// alphapocket surface FILE [--probe R] [--json] [--per-atom] [--sa-only]
//
// Solvent-accessible surface (SAS) area and volume of a molecule: the union
// of its atom balls, radius = ProtOr radius + probe, measured analytically
// over the weighted alpha complex at alpha_sq = 0 (alpha::UnionOfBalls), so
// there is no resolution to choose (unlike Lee-Richards slices or
// Shrake-Rupley points). With --per-atom, the SAS area and volume of every
// atom (its power cell's share), and the solvent-excluded ones (the MS
// surface's area and the volume it encloses inside the atom's power cell).
// A point file with --weighted gives the union of its balls.
//
// For a structure, also the solvent-excluded (molecular, Connolly) surface:
// the SAS union eroded by the probe (alpha::ErodedUnion); null for a point
// file, whose balls carry no probe, and with --sa-only (it takes several
// times as long as the SAS). The measuring is molecule::measure_surface
// (molecule/surface.hpp); this file reads FILE and prints.
#include <cstdio>
#include <memory>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "alpha/input_file.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "molecule/radii.hpp"
#include "molecule/structure.hpp"
#include "molecule/surface.hpp"

namespace alphapocket {
namespace {

struct SurfaceOptions {
  InputOptions input;
  bool json = false;
  bool per_atom = false;
  bool sa_only = false;
};

// FILE measured (molecule/surface.hpp), and for a structure file its
// atoms (names for --per-atom).
struct Measured {
  molecule::Surface surface;
  std::optional<std::vector<molecule::Atom>> atoms;
};

Measured measure(const SurfaceOptions& opt) {
  const InputOptions& in = opt.input;
  Measured m;
  if (molecule::is_structure_file(in.file)) {
    molecule::StructureOptions selection = in.structure;
    selection.min_atoms = 1;  // one atom has a surface
    m.atoms = read_structure_file(in.file, selection).atoms;
    m.surface = naming_file(in.file, [&] {
      return molecule::measure_surface(*m.atoms, {in.probe, !opt.sa_only, opt.per_atom});
    });
  } else {
    if (!in.weighted) {
      alpha::read_input_file(in.file);  // a missing file or a directory is the first thing to say
      throw alpha::Error(
          in.file + ": a point file has no balls without --weighted (x y z r per line): its surface is empty",
          alpha::ErrorKind::BadInput);
    }
    PointSet set = read_input(in);
    m.surface = naming_file(in.file, [&] { return molecule::measure_balls(std::move(set.points), std::move(set.weights)); });
  }
  const molecule::Surface& s = m.surface;
  spdlog::info("regular triangulation and alpha complex: {:.3f} s; union of balls: {:.3f} s ({} hidden balls)",
               s.complex_seconds, s.union_seconds, s.hidden);
  if (s.ms_area) spdlog::info("solvent-excluded surface: {:.3f} s", s.excluded_seconds);
  return m;
}

nlohmann::ordered_json atom_json(const molecule::Atom& a) {
  nlohmann::ordered_json j;
  j["serial"] = a.serial;
  j["name"] = a.name;
  j["residue"] = a.residue_name;
  j["seq_num"] = a.seq_num;
  j["icode"] = molecule::icode_text(a.icode);
  j["chain"] = a.chain;
  return j;
}

int run_surface(const SurfaceOptions& opt) {
  const Measured m = measure(opt);
  const molecule::Surface& u = m.surface;
  const std::size_t n = u.balls;
  const std::vector<double>& areas = u.ball_areas;
  const bool structure = m.atoms.has_value();
  const bool excluded = !u.ms_ball_areas.empty();
  const auto excluded_json = [](const std::optional<double>& measure) {
    return measure ? nlohmann::ordered_json(*measure) : nlohmann::ordered_json(nullptr);
  };

  if (opt.json) {
    nlohmann::ordered_json j;
    j["atoms"] = n;
    j["probe"] = structure ? nlohmann::ordered_json(opt.input.probe) : nlohmann::ordered_json(nullptr);
    j["sa_area"] = u.sa_area;
    j["sa_volume"] = u.sa_volume;
    j["ms_volume"] = excluded_json(u.ms_volume);
    j["ms_area"] = excluded_json(u.ms_area);
    j["radii"] = structure ? std::string(molecule::kRadiusTable) : std::string("file");
    if (opt.per_atom) {
      j["per_atom"] = nlohmann::ordered_json::array();
      for (std::size_t i = 0; i < n; ++i) {
        nlohmann::ordered_json p;
        if (structure)
          p = atom_json((*m.atoms)[i]);
        else
          p["index"] = i;
        p["area"] = areas[i];
        p["volume"] = u.ball_volumes[i];
        if (excluded) {
          p["ms_area"] = u.ms_ball_areas[i];
          p["ms_volume"] = u.ms_ball_volumes[i];
        }
        j["per_atom"].push_back(p);
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
                                  u.sa_area, u.sa_volume)
                          .c_str());
    if (u.ms_area)
      std::printf("%s", fmt::format("solvent-excluded area      {:.3f} A^2\nsolvent-excluded volume    {:.3f} A^3\n",
                                    *u.ms_area, *u.ms_volume)
                            .c_str());
    if (opt.per_atom) {
      std::printf("%s%s\n", structure ? "serial name residue seq_num chain area volume" : "index area volume",
                  excluded ? " ms_area ms_volume" : "");
      for (std::size_t i = 0; i < n; ++i) {
        std::string line;
        if (structure) {
          const molecule::Atom& a = (*m.atoms)[i];
          line = fmt::format("{} {} {} {}{} {}", a.serial, a.name, a.residue_name, a.seq_num,
                             molecule::icode_text(a.icode), a.chain);
        } else {
          line = fmt::format("{}", i);
        }
        line += fmt::format(" {:.3f} {:.3f}", areas[i], u.ball_volumes[i]);
        if (excluded) line += fmt::format(" {:.3f} {:.3f}", u.ms_ball_areas[i], u.ms_ball_volumes[i]);
        std::printf("%s\n", line.c_str());
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
      "complex; per atom (its power cell's share) with --per-atom");
  add_input_options(*sub, opt->input);
  sub->add_flag("--json", opt->json, "Print one JSON object on stdout instead of a summary");
  sub->add_flag("--per-atom", opt->per_atom,
                "Also print every atom's (ball's) SAS area and volume and its solvent-excluded area and volume, "
                "split by power cell (about 3 times as long as without it)");
  sub->add_flag("--sa-only", opt->sa_only,
                "Skip the solvent-excluded (molecular) surface, which takes several times as long as the SAS: "
                "ms_volume and ms_area are null");
  return {sub, [opt] { return run_surface(*opt); }};
}

}  // namespace alphapocket
