// SPDX-License-Identifier: Apache-2.0
// What `track` (molecule/track.hpp) finds over the frames: each frame's
// cavities as observations, the tracks that follow them, the splits and
// merges, and the frequency and density grids.
#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "alpha/geometry.hpp"
#include "molecule/structure.hpp"

namespace molecule {

enum class CavityKind { pocket, void_, tunnel };
// "pocket", "void", "tunnel".
const char* kind_name(CavityKind kind);

// One cavity in one frame.
struct Observation {
  std::size_t frame = 0;  // position in TrackResult::frames
  std::size_t track = 0;  // index into TrackResult::tracks
  std::size_t rank = 0;   // in its frame's list (pockets, voids, tunnels), from 1
  double sa_volume = 0, ms_volume = 0;  // A^3 (0 for tunnels)
  double probability = 0;               // NaN for tunnels
  std::size_t mouths = 0;
  double bottleneck_radius = 0;  // tunnels; NaN for pockets and voids
  double length = 0;             // tunnels, A
  alpha::Vec3 center{};          // pockets and voids: the cavity's centre; tunnels: the bottleneck
};

struct Track {
  std::size_t id = 0;  // from 1, in order of appearance (frame, then kind, then rank)
  CavityKind kind = CavityKind::pocket;
  std::vector<std::size_t> observations;  // into TrackResult::observations, by frame
  std::map<std::string, std::size_t> residues;  // residue id ("A:TYR:42") -> frames lining it
  std::optional<std::size_t> split_from;        // track index it split from
  std::optional<std::size_t> merged_into;       // track index it merged into
};

struct TrackEvent {
  std::size_t frame = 0;  // position in TrackResult::frames
  std::string event;      // "split" or "merge"
  std::size_t track = 0, other = 0;  // track split from other / merged into other (indices)
};

// A regular grid over space; point (i, j, k) at origin + spacing * (i, j,
// k), numbered with k fastest (OpenDX's order).
struct SpaceGrid {
  alpha::Vec3 origin{};
  double spacing = 1;
  std::size_t nx = 0, ny = 0, nz = 0;
  std::size_t size() const { return nx * ny * nz; }
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return (i * ny + j) * nz + k; }
  alpha::Vec3 point(std::size_t p) const {
    const std::size_t k = p % nz, j = p / nz % ny, i = p / nz / ny;
    return {origin.x + spacing * double(i), origin.y + spacing * double(j), origin.z + spacing * double(k)};
  }
};

struct FrameInfo {
  std::size_t index = 0;
  double time = 0;
  std::string name;
  std::size_t atoms = 0;
  // Wall clock of its analysis, and of its stages: the alpha complex, the
  // cavities, their ranking, the tunnels, the grid and tracking summary.
  double seconds = 0;
  double complex_seconds = 0, cavities_seconds = 0, ranking_seconds = 0, tunnels_seconds = 0, grid_seconds = 0;
};

struct TrackResult {
  std::vector<FrameInfo> frames;
  std::vector<Observation> observations;  // by frame, then kind, then rank
  std::vector<Track> tracks;              // by id
  std::vector<TrackEvent> events;
  SpaceGrid grid;
  // Share of the frames in which a pocket or void holds the grid point (0-1).
  std::vector<float> frequency;
  // Mean per frame of the number of pocket and void cells whose orthocentre
  // (the centre of its empty sphere, fpocket's alpha sphere centre) lies in
  // the 2 A cube centred on the grid point (mdpocket's density).
  std::vector<float> density;
  Structure first_structure;  // the first frame's atoms, for the viewer script
  bool time_in_ps = false;    // frames' times are a trajectory's (else frame numbers)
  double transient = 0.5;     // TrackOptions::transient
  double seconds = 0;         // the whole run, wall clock

  double frequency_of(const Track& t) const { return double(t.observations.size()) / double(frames.size()); }
};

// Mean, least and greatest of one measure over a track's observations.
struct TrackStats {
  double mean = 0, min = 0, max = 0;
};
TrackStats track_stats(const TrackResult& r, const Track& t, double Observation::*measure);

}  // namespace molecule
