// SPDX-License-Identifier: Apache-2.0
// alphapocket track TOPOLOGY [TRAJECTORY...] -o OUTDIR [--begin B] [--end E] [--stride S] [-j N]
//
// Pockets over an ensemble or a trajectory: every frame searched as
// `pockets` searches one structure, the pockets, voids and tunnels
// followed through the frames (molecule/track.hpp), and OUTDIR written
// whole (molecule/track_outputs.hpp lists its files; docs/trajectories.md
// explains them). Prints one line per top pocket.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "interrupt.hpp"
#include "outputs/pocket_outputs.hpp"
#include "util/staged_directory.hpp"
#include "molecule/track.hpp"
#include "trajectory/track_outputs.hpp"

namespace alphapocket {
namespace {

namespace fs = std::filesystem;

struct TrackCommandOptions {
  std::string topology;
  std::vector<std::string> trajectories;
  std::string output_dir;
  double probe = molecule::CavityOptions{}.probe;
  molecule::TrackOptions track;
};

// OUTDIR may be new, or hold an earlier run's files only: nothing else is replaced.
void check_output_dir(const fs::path& target, const std::string& name) {
  std::error_code ec;
  if (!fs::exists(target, ec)) return;
  if (!fs::is_directory(target, ec))
    throw alpha::Error(name + ": exists and is not a directory", alpha::ErrorKind::BadInput);
  std::set<std::string> ours;
  for (const std::string& f : molecule::track_output_names()) ours.insert(f);
  for (const fs::directory_entry& e : fs::directory_iterator(target, ec))
    if (!ours.count(e.path().filename().string()))
      throw alpha::Error(name + ": holds '" + e.path().filename().string() +
                             "', not an output of alphapocket track; choose a new or empty directory",
                         alpha::ErrorKind::BadInput);
}

int run_track(TrackCommandOptions& opt) {
  Stopwatch total;
  const fs::path target = molecule::output_directory_path(opt.output_dir);
  check_output_dir(target, opt.output_dir);  // a bad OUTDIR fails before the work
  install_interrupt_handlers(1);
  opt.track.analysis.cavities.probe = opt.probe;
  const std::unique_ptr<molecule::FrameSource> frames =
      molecule::open_frames(opt.topology, opt.trajectories, opt.track.analysis.structure);
  const molecule::TrackResult result =
      molecule::track(*frames, opt.track, [](std::size_t done) { spdlog::debug("frame {} done", done); });
  const auto files = molecule::track_output_files(result);
  molecule::StagedDirectory out(target, opt.output_dir, &temporaries());
  for (const auto& [name, content] : files) out.write(name, content);
  out.commit();
  // Where a frame's time goes (means; wall clock on its thread).
  molecule::FrameInfo mean;
  for (const molecule::FrameInfo& f : result.frames) {
    mean.seconds += f.seconds, mean.complex_seconds += f.complex_seconds, mean.cavities_seconds += f.cavities_seconds;
    mean.ranking_seconds += f.ranking_seconds, mean.tunnels_seconds += f.tunnels_seconds, mean.grid_seconds += f.grid_seconds;
  }
  const double n = double(result.frames.size());
  spdlog::info("{} frames, {:.4f} s a frame: complex {:.4f}, cavities {:.4f}, ranking {:.4f}, tunnels {:.4f}, "
               "grid {:.4f}, report and the rest; {:.3f} s in all; {} tracks; wrote {}/",
               result.frames.size(), mean.seconds / n, mean.complex_seconds / n, mean.cavities_seconds / n,
               mean.ranking_seconds / n, mean.tunnels_seconds / n, mean.grid_seconds / n, total.seconds(),
               result.tracks.size(), opt.output_dir);

  std::size_t merges = 0;
  for (const molecule::TrackEvent& e : result.events) merges += e.event == "merge";
  std::printf("%zu frames of %s; %zu tracks (%zu splits, %zu merges); written to %s/\n", result.frames.size(),
              opt.topology.c_str(), result.tracks.size(), result.events.size() - merges, merges,
              opt.output_dir.c_str());
  std::printf("\npocket  frames  frequency  mean SA vol A^3  mean MS vol A^3\n");
  std::size_t shown = 0;
  for (std::size_t t : molecule::top_pockets(result)) {
    if (shown++ == 10) break;
    const molecule::Track& track = result.tracks[t];
    std::printf("%6zu  %6zu  %9.2f  %15.1f  %15.1f\n", track.id, track.observations.size(), result.frequency_of(track),
                molecule::track_stats(result, track, &molecule::Observation::sa_volume).mean,
                molecule::track_stats(result, track, &molecule::Observation::ms_volume).mean);
  }
  flush_stdout();
  return 0;
}

}  // namespace

Subcommand add_track_command(CLI::App& app) {
  auto opt = std::make_shared<TrackCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "track", "Pockets over a trajectory or an ensemble: each frame searched, pockets followed through time");
  sub->footer(
      "Frames: the models of TOPOLOGY (a multi-model PDB or mmCIF, e.g. an NMR ensemble), then each further "
      "structure file (an ensemble of the same molecule). OUTDIR gets frames.csv, tracks.csv, events.csv, "
      "frequency.dx and density.dx (OpenDX), structure.cif, track.pml (PyMOL) and volumes.svg; see "
      "docs/trajectories.md.");
  sub->add_option("TOPOLOGY", opt->topology, "Structure file: .pdb .ent .cif .mmcif, optionally .gz")->required();
  sub->add_option("TRAJECTORY", opt->trajectories, "Further frames: structure files of the same molecule");
  sub->add_option("-o,--output-dir", opt->output_dir, "Directory for the results (created if missing)")
      ->type_name("OUTDIR")
      ->required()
      ->check(output_directory_name());
  add_structure_options(*sub, opt->track.analysis.structure, opt->probe);
  sub->remove_option(sub->get_option("--model"));  // every model is a frame
  add_cavity_options(*sub, opt->track.analysis);
  for (const char* meshes : {"--mesh", "--mesh-resolution"}) sub->remove_option(sub->get_option(meshes));
  const std::string group = "Frames";
  sub->add_option("--begin", opt->track.begin, "First frame taken (from 0)")->type_name("N")->group(group);
  sub->add_option("--end", opt->track.end, "Frames from this one on are not read")->type_name("N")->group(group);
  sub->add_option("--stride", opt->track.stride, "Take every N-th frame from --begin")
      ->capture_default_str()
      ->type_name("N")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40).description(""))
      ->group(group);
  sub->add_option("--grid-spacing", opt->track.grid_spacing, "Spacing of the frequency and density grids, A")
      ->capture_default_str()
      ->type_name("A")
      ->check(finite_number(0.1, 100))
      ->group(group);
  sub->add_option("--overlap", opt->track.min_lining_overlap,
                  "Share of lining atoms (Jaccard index) for a cavity to continue a track")
      ->capture_default_str()
      ->check(finite_number(0.01, 1))
      ->group(group);
  sub->add_option("-j,--jobs", opt->track.jobs, "Frames analysed at once, on threads (results identical for any number)")
      ->capture_default_str()
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u).description(""));
  return {sub, [opt] { return run_track(*opt); }};
}

}  // namespace alphapocket
