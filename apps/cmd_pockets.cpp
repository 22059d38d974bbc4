// SPDX-License-Identifier: Apache-2.0
// alphapocket pockets FILE [-o OUTDIR] [options]   (every option: docs/cli.md)
//
// The product command: one structure through molecule::analyse (read,
// weighted alpha complex of the atoms, cavities, ranked sites, tunnels;
// docs/architecture.md), then OUTDIR (default <id>_pockets in the current
// directory) written with the files --outputs chooses (default
// report,csv,pml,pdb,tunnels,html: report.json, pockets.csv, sites.csv,
// structure.cif, pockets.pml, pockets.cxc, pockets.pdb, tunnels.csv,
// tunnel_profiles.csv, tunnels.pdb, and report.html, scene.mvsj, viewer/
// when the viewer files are installed; meshes/ only with --outputs all, --mesh
// or --mesh-resolution; docs/outputs.md), then a one-screen summary of the
// best sites and where each ligand of the file sits (or, with --json, the
// report) on stdout.
//
// OUTDIR describes one run, whole: it is written as a hidden sibling and
// swapped in with one rename (outputs/pocket_outputs.hpp), and a bad OUTDIR
// fails at once, before the work. SIGINT/SIGTERM end the run at once,
// leaving OUTDIR as it was (or complete) and no temporary behind.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "interrupt.hpp"
#include "molecule/analysis.hpp"
#include "util/atomic_file.hpp"
#include "ranking/buried_surface.hpp"
#include "molecule/cavities.hpp"
#include "molecule/ligand_sites.hpp"
#include "outputs/pocket_outputs.hpp"
#include "outputs/pocket_report.hpp"
#include "outputs/report_numbers.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/residues.hpp"
#include "molecule/site_features.hpp"
#include "molecule/structure.hpp"
#include "structure/structure_id.hpp"

namespace alphapocket {
namespace {

namespace fs = std::filesystem;

struct PocketsOptions {
  InputOptions input;  // FILE, --probe and the structure selection
  std::optional<std::string> output_dir;  // -o '' is refused, not the default
  molecule::AnalysisOptions analysis;  // --min-volume, --mesh; .outputs from --outputs
  // The library's default (no meshes: written when asked for), and html when Mol* is installed.
  std::string outputs = molecule::output_list(molecule::OutputSelection{}) + ",html";
  bool json = false;
  std::string features;  // --features FILE: the cavities' model features as CSV
  std::string surface_points;  // --surface-points FILE: ranking/buried_surface.hpp's points as CSV
};

// Sites shown in the summary, and its width in columns.
constexpr std::size_t kSummaryRows = 10;
constexpr std::size_t kSummaryWidth = 100;

// "1a26A.pdb" -> "1a26A_pockets"; "x.cif.gz" -> "x_pockets".
std::string default_output_dir(const std::string& file) { return molecule::structure_id(file) + "_pockets"; }

// "A:TYR:42 A:SER:43 ..." cut to fit `width` columns, with "(+N)" for the
// residues left out.
std::string residue_list(const std::vector<molecule::Atom>& atoms, const std::vector<alpha::Index>& lining,
                         std::size_t width) {
  const std::vector<alpha::Index> residues = molecule::residues_of(atoms, lining);
  std::string out;
  for (std::size_t k = 0; k < residues.size(); ++k) {
    const std::string id = molecule::residue_id(atoms[residues[k]]);
    const std::string more = " (+" + std::to_string(residues.size() - k) + ")";
    if (out.size() + 1 + id.size() + (k + 1 < residues.size() ? more.size() : 0) > width) return out + more;
    if (!out.empty()) out += ' ';
    out += id;
  }
  return out;
}

// "13 pockets, 1 void, 6 tunnels".
std::string cavity_counts(const molecule::Cavities& cavities) {
  const auto count = [](std::size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  return count(cavities.pockets.size(), "pocket") + ", " + count(cavities.voids.size(), "void") + ", " +
         count(cavities.tunnels.size(), "tunnel");
}

void print_summary(const PocketsOptions& opt, const std::string& outdir, const molecule::Structure& structure,
                   const molecule::Cavities& cavities) {
  const auto& sites = cavities.sites;
  std::printf("%s: %s\n", opt.input.file.c_str(), molecule::summary(structure.report).c_str());
  std::printf("solvent-accessible surface (probe %g A): area %.1f A^2, volume %.1f A^3\n", opt.input.probe,
              cavities.sa_area, cavities.sa_volume);
  std::printf("%s; written to %s/%s\n", cavity_counts(cavities).c_str(), outdir.c_str(),
              opt.analysis.outputs.meshes ? "" : " (--mesh ply adds the surface and cavity meshes)");
  if (!sites.empty()) {
    std::printf("\nsite  cavity         prob      score  SA vol A^3  MS vol A^3  depth A  mouths  lining residues\n");
    const std::size_t prefix = 76;  // columns before the residues
    for (std::size_t i = 0; i < std::min(sites.size(), kSummaryRows); ++i) {
      const molecule::Site& s = sites[i];
      const molecule::Cavity& c = cavities.cavity(s);
      std::printf("%4zu  %-10s %6.3f %10.3g %11.1f %11.1f %8.1f %7zu  %s\n", i + 1,
                  molecule::site_cavity_name(s).c_str(), c.probability, c.score, c.sa_volume, c.ms_volume, c.depth, c.mouths.size(),
                  residue_list(structure.atoms, c.lining_atoms, kSummaryWidth - prefix).c_str());
    }
    if (sites.size() > kSummaryRows)
      std::printf("(top %zu of %zu sites; all in %s/report.json, sites.csv)\n", kSummaryRows,
                  sites.size(), outdir.c_str());
  }
  if (!cavities.tunnels.empty()) {
    const molecule::Tunnel& t = cavities.tunnels.front();
    std::printf("\nwidest tunnel: bottleneck radius %.2f A between %s\n", t.bottleneck_radius,
                residue_list(structure.atoms, t.lining_atoms, kSummaryWidth).c_str());
  }
}

// One line per tunnel start (its widest tunnel) and for the widest pore.
void print_paths(const molecule::Analysis& a) {
  const auto line = [&](const std::string& what, const molecule::TunnelPath& p) {
    std::printf("%s: bottleneck radius %.2f A, length %.1f A, lined by %s\n", what.c_str(), p.bottleneck_radius,
                p.length, residue_list(a.structure.atoms, p.lining_atoms, kSummaryWidth - 40).c_str());
  };
  std::size_t last_start = std::size_t(-1);
  bool pore = false;
  for (const molecule::TunnelPath& p : a.paths) {
    if (!p.pore && p.start != last_start) {
      last_start = p.start;
      line("tunnel from " + a.tunnel_starts[p.start], p);
    } else if (p.pore && !pore) {
      pore = true;
      line("widest pore", p);
    }
  }
}

// One line per hetero group (Analysis::ligands), the ones in a site first
// by site rank, then the others in file order; at most kSummaryRows.
void print_ligands(const molecule::Analysis& a) {
  std::vector<const molecule::LigandSite*> order;
  for (const molecule::LigandSite& l : a.ligands) order.push_back(&l);
  std::stable_sort(order.begin(), order.end(), [](const molecule::LigandSite* x, const molecule::LigandSite* y) {
    const auto key = [](const molecule::LigandSite* l) { return l->site ? l->site : std::size_t(-1); };
    return key(x) < key(y);
  });
  const auto site_name = [&](std::size_t rank) {
    const molecule::Site& s = a.search.cavities.sites.at(rank - 1);
    return "site " + std::to_string(rank) + " (" + (s.is_void ? "void " : "pocket ") + std::to_string(s.index + 1) + ")";
  };
  // As report.json has it.
  const auto distance = [](const molecule::LigandSite& l) {
    return fmt::format("{:.1f}", molecule::report_number::length(l.distance));
  };
  // "; 14 in site 9": the other sites holding some of it.
  const auto elsewhere = [](const molecule::LigandSite& l) {
    std::string more;
    for (const auto& [rank, atoms] : l.holding)
      if (rank != l.site) more += "; " + std::to_string(atoms) + " in site " + std::to_string(rank);
    return more;
  };
  if (!order.empty()) std::printf("\n");
  for (std::size_t i = 0; i < std::min(order.size(), kSummaryRows); ++i) {
    const molecule::LigandSite& l = *order[i];
    const molecule::HeteroGroup& g = a.structure.hetero_groups.at(l.group);
    const std::string name = g.residue_name + " " + g.chain + ":" + std::to_string(g.seq_num) + molecule::icode_text(g.icode);
    std::string where;
    if (g.kept)
      where = "kept as protein, " + (l.site ? "lines " + site_name(l.site) : std::string("lines no site"));
    else if (l.site)
      where = "in " + site_name(l.site) + ", " + distance(l) + " A: " + std::to_string(l.atoms_in_site) + " of " +
              std::to_string(g.atoms.size()) + " heavy atoms inside its space" + elsewhere(l);
    else if (l.nearest_site)
      where = "in no site: nearest " + site_name(l.nearest_site) + " at " + distance(l) + " A";
    else
      where = "in no site";
    std::printf("ligand %s %s\n", name.c_str(), where.c_str());
  }
  if (order.size() > kSummaryRows)
    std::printf("(%zu of %zu hetero groups; all in report.json ligands)\n", kSummaryRows, order.size());
}

// Input the cavity search was not made for, said plainly: a C-alpha trace
// or backbone-only model (no side chains: the "pockets" are the gaps
// between backbone atoms) and a nucleic acid without protein (the ranking
// is fitted to proteins' ligand sites).
void warn_unsuited(const std::string& file, const molecule::Structure& structure) {
  static const std::set<std::string> kBackbone{"N", "CA", "C", "O", "OXT"};
  static const std::set<std::string> kNucleotides{"A", "C", "G", "U", "T", "I", "DA", "DC", "DG", "DT", "DU", "DI"};
  std::size_t protein = 0, side_chain = 0, ca = 0, nucleic = 0;
  for (const molecule::Atom& a : structure.atoms) {
    if (kNucleotides.count(a.residue_name)) {
      ++nucleic;
    } else if (!a.hetero) {
      ++protein;
      ca += a.name == "CA";
      side_chain += !kBackbone.count(a.name);
    }
  }
  if (protein > 0 && side_chain == 0)
    spdlog::warn("{}: {}: the cavities found are gaps between backbone atoms, not binding sites; use a full-atom model",
                 file, ca == protein ? "only C-alpha atoms (a C-alpha trace)" : "only backbone atoms (no side chains)");
  if (protein == 0 && nucleic > 0)
    spdlog::warn("{}: only nucleic acids: the site ranking is made for proteins' ligand sites (bench/README.md)",
                 file);
}

// -v: every site on stderr (the summary shows 10); -vv: with all their
// lining residues.
void log_sites(const molecule::Structure& structure, const molecule::Cavities& cavities) {
  std::size_t rank = 0;
  for (const molecule::Site& s : cavities.sites) {
    const molecule::Cavity& c = cavities.cavity(s);
    spdlog::debug("site {}: {}, score {:.3g}, SA volume {:.1f} A^3, centre ({:.2f}, {:.2f}, {:.2f})", ++rank,
                  molecule::site_cavity_name(s), c.score, c.sa_volume, s.center.x, s.center.y, s.center.z);
    spdlog::trace("site {} lining residues: {}", rank,
                  residue_list(structure.atoms, c.lining_atoms, std::string::npos));
  }
}

int run_pockets(const PocketsOptions& opt) {
  Stopwatch total_time;
  const std::string& file = opt.input.file;
  if (!molecule::is_structure_file(file))
    throw alpha::Error(file + ": not a structure file (.pdb .ent .cif .mmcif, optionally .gz)",
                       alpha::ErrorKind::BadInput);
  // First of all: a bad OUTDIR fails at once (nothing is created before
  // the outputs are written).
  const std::string outdir = opt.output_dir ? *opt.output_dir : default_output_dir(file);
  install_interrupt_handlers(1);
  molecule::AnalysisOptions options = opt.analysis;
  molecule::PocketOutputDir out(outdir, options.outputs, &temporaries());

  options.structure = opt.input.structure;
  options.cavities.probe = opt.input.probe;
  const molecule::Analysis analysis = molecule::analyse(file, options);
  log_analysis(analysis);
  warn_unsuited(file, analysis.structure);
  log_sites(analysis.structure, analysis.search.cavities);

  Stopwatch write_time;
  const std::vector<std::string> written = molecule::write_outputs(analysis, out);
  for (const std::string& warning : out.warnings()) spdlog::warn("{}", warning);
  if (!opt.features.empty())
    molecule::write_file_atomically(opt.features,
                                    molecule::site_features_csv(analysis.structure, analysis.search.cavities));
  if (!opt.surface_points.empty())
    molecule::write_file_atomically(opt.surface_points, molecule::surface_points_csv(analysis.structure.atoms));
  if (analysis.meshes)
    spdlog::info("meshes: {:.3f} s at resolution {} A", analysis.meshes->seconds, opt.analysis.mesh_resolution);
  spdlog::info("wrote {} files to {}/ in {:.3f} s; total {:.3f} s", written.size(), outdir, write_time.seconds(),
               total_time.seconds());

  if (opt.json) {
    std::puts(analysis.report->json.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
  } else {
    print_summary(opt, outdir, analysis.structure, analysis.search.cavities);
    print_ligands(analysis);
    print_paths(analysis);
  }
  flush_stdout();
  return 0;
}

}  // namespace

Subcommand add_pockets_command(CLI::App& app) {
  auto opt = std::make_shared<PocketsOptions>();
  CLI::App* sub = app.add_subcommand(
      "pockets", "Find the pockets, voids and tunnels of a structure; write report, CSV, PyMOL script, PDB (and meshes)");
  sub->footer(
      "Waters, hydrogens and hetero groups (ligands, ions) are left out unless kept with --keep-*; atoms get "
      "ProtOr radii. OUTDIR gets report.json, pockets.csv, sites.csv, pockets.pml (PyMOL), pockets.cxc (ChimeraX), "
      "structure.cif, pockets.pdb, tunnels.csv, tunnel_profiles.csv, tunnels.pdb, and meshes/ when asked for "
      "(--mesh FMT or --outputs all); see docs/outputs.md for their contents. -v logs every site, -vv with its lining residues.");
  add_input_options(*sub, opt->input);
  // Only structure files: atoms need radii and residues.
  sub->remove_option(sub->get_option("--weighted"));
  sub->get_option("FILE")->description("Structure file: .pdb .ent .cif .mmcif, optionally .gz");
  sub->add_option("-o,--output-dir", opt->output_dir,
                  "Directory for the results (created if missing; default: <name>_pockets in the current "
                  "directory)")
      ->type_name("OUTDIR")
      ->check(output_directory_name());
  add_cavity_options(*sub, opt->analysis);
  sub->add_option("-j,--jobs", opt->analysis.cavities.threads,
                  "Threads measuring the cavities (results identical for any number)")
      ->capture_default_str()
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u).description(""));
  add_outputs_option(*sub, opt->outputs, "OUTDIR");
  sub->add_flag("--json", opt->json, "Print report.json (on one line) instead of the summary");
  sub->add_option("--features", opt->features,
                  "Also write every pocket's and void's ligandability-model features to this CSV file (for training/)");
  sub->add_option("--surface-points", opt->surface_points,
                  "Also write the surface points that site centres move to, with their atom counts, to this CSV file "
                  "(for training/)");
  return {sub, [opt, sub] {
            opt->analysis.outputs = selected_outputs(*sub, opt->outputs);
            return run_pockets(*opt);
          }};
}

}  // namespace alphapocket
