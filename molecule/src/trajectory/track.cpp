// SPDX-License-Identifier: Apache-2.0
// The driver of molecule/track.hpp: frames read in order, analysed a batch
// at a time on threads, then followed and counted on the grids in order.
#include <algorithm>
#include <chrono>
#include <new>

#include "molecule/track.hpp"
#include "util/parallel_for.hpp"
#include "trajectory/frame_cavities.hpp"
#include "trajectory/pocket_tracker.hpp"

namespace molecule {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TrackResult track(FrameSource& frames, const TrackOptions& options, const std::function<void(std::size_t)>& progress) {
  if (options.stride == 0) throw AnalysisError(FailureKind::Misuse, "--stride must be at least 1");
  if (!(options.grid_spacing >= 0.1)) throw AnalysisError(FailureKind::Misuse, "--grid-spacing must be at least 0.1 A");
  const auto start = std::chrono::steady_clock::now();
  TrackResult result;
  result.transient = options.transient;
  PocketTracker tracker(options.min_lining_overlap);
  AnalysisOptions analysis = options.analysis;
  analysis.report = false;
  analysis.cavities.tunnels = false;  // Cavities::tunnels are the report's: track follows the tunnel paths
  analysis.cavities.site_centers = false;  // the report's too: track starts tunnels from the sites' cells
  analysis.outputs.meshes = false;  // no frame's meshes are made: the search keeps no solvent bodies
  const unsigned jobs = std::max(1u, options.jobs);
  if (jobs > 1) analysis.cavities.threads = 1;  // the frames are the threads' work
  std::vector<std::uint32_t> in_cavity, density;
  bool more = true;
  while (more) {
    // The next batch of frames taken.
    std::vector<Frame> batch;
    while (batch.size() < 2 * std::size_t(jobs)) {
      std::optional<Frame> f = frames.next();
      if (!f || f->index >= options.end) {
        more = false;
        break;
      }
      if (f->index < options.begin || (f->index - options.begin) % options.stride != 0) continue;
      if (result.frames.empty() && batch.empty()) {
        result.grid = grid_around(f->structure.atoms, options.grid_spacing, options.grid_margin);
        result.first_structure = f->structure;
        result.time_in_ps = f->time_in_ps;
        in_cavity.assign(result.grid.size(), 0);
        density.assign(result.grid.size(), 0);
      }
      batch.push_back(std::move(*f));
    }
    std::vector<FrameCavities> found(batch.size());
    std::vector<std::size_t> order(batch.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    parallel_for(order, jobs, [&](std::size_t k) {
      const auto t0 = std::chrono::steady_clock::now();
      Frame& f = batch[k];
      FrameInfo info{f.index, f.time, f.name, f.structure.atoms.size(), 0};
      try {
        const Analysis a = analyse_structure(f.name, std::move(f.structure), analysis);
        const auto t1 = std::chrono::steady_clock::now();
        found[k] = frame_cavities(a, result.grid);
        info.grid_seconds = seconds_since(t1);
        info.complex_seconds = a.search.complex_seconds;
        info.cavities_seconds = a.search.cavities_seconds;
        info.ranking_seconds = a.search.ranking_seconds;
        info.tunnels_seconds = a.tunnels_seconds;
      } catch (const std::bad_alloc&) {
        throw AnalysisError(FailureKind::LimitExceeded, f.name + ": out of memory");
      }
      info.seconds = seconds_since(t0);
      found[k].info = info;
    });
    for (FrameCavities& f : found) {
      for (std::uint32_t p : f.density_hits) ++density[p];
      std::vector<std::uint32_t> space;
      for (const FrameCavity& c : f.cavities)
        if (c.kind != CavityKind::tunnel) space.insert(space.end(), c.space.begin(), c.space.end());
      std::sort(space.begin(), space.end());
      space.erase(std::unique(space.begin(), space.end()), space.end());
      for (std::uint32_t p : space) ++in_cavity[p];
      tracker.add(std::move(f), result);
      if (progress) progress(result.frames.size());
    }
  }
  if (result.frames.empty())
    throw AnalysisError(FailureKind::BadInput, "no frame in the range asked for (--begin/--end/--stride)");
  const double n = double(result.frames.size());
  result.frequency.resize(in_cavity.size());
  result.density.resize(density.size());
  for (std::size_t p = 0; p < in_cavity.size(); ++p) {
    result.frequency[p] = float(in_cavity[p] / n);
    result.density[p] = float(density[p] / n);
  }
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace molecule
