// SPDX-License-Identifier: Apache-2.0
// The files of `alphapocket track`'s output directory, formatted from a
// molecule::TrackResult (docs/trajectories.md describes each):
//   frames.csv     one row per cavity per frame (frame, time, track id, volumes, probability, mouths, bottleneck)
//   tracks.csv     one row per track (frequency, life, volume statistics, residues with their frequency)
//   events.csv     splits and merges
//   frequency.dx   OpenDX grid: share of frames with pocket or void space at each point (0-1)
//   density.dx     OpenDX grid: cavity cells' orthocentres per frame around each point
//   structure.cif  the first frame's atoms
//   track.pml      PyMOL: the first frame, the frequency grid's 0.5 isosurface and the top pockets
//   volumes.svg    the SA volume of the top pockets over time
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "molecule/track.hpp"

namespace molecule {

// Pockets shown in track.pml and volumes.svg.
inline constexpr std::size_t kTopTracks = 5;

// The pocket tracks, most frequent first (ties: larger mean SA volume, then id).
std::vector<std::size_t> top_pockets(const TrackResult& result);

// (file name, content) of every output, in the order above.
std::vector<std::pair<std::string, std::string>> track_output_files(const TrackResult& result);

// The names of those files.
std::vector<std::string> track_output_names();

// OpenDX text of a grid's values.
std::string opendx(const SpaceGrid& grid, const std::vector<float>& values, const std::string& title);

}  // namespace molecule
