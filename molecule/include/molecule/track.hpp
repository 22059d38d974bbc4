// SPDX-License-Identifier: Apache-2.0
// Pockets over trajectories and ensembles: every frame searched as
// `alphapocket pockets` searches one structure (molecule::analyse), and
// its pockets, voids and tunnels followed from frame to frame.
//
// Identity (docs/trajectories.md): a cavity of frame t continues a track
// of the same kind (pocket, void, tunnel) when the two share lining atoms
// (Jaccard index of their lining atoms, named by chain, residue and atom
// name, at least TrackOptions::min_lining_overlap) and space (at least one
// common point of the grid below, when both hold one; a cavity too small
// to hold a grid point is matched by its lining alone). A track is
// compared with its last appearance, however long ago, so a pocket that
// closes and reopens keeps its identity. Pairs are taken best first, each
// track and each cavity once; a cavity left over that matches a track
// taken in this frame starts a new track SPLIT from it, and a track seen
// in the previous frame that is left over but matches a cavity taken by
// another track MERGED into that one.
//
// Space is sampled on one grid for the whole run (TrackOptions::
// grid_spacing, covering the first frame's atoms with a margin): a grid
// point belongs to a cavity when it lies in one of the cavity's empty
// tetrahedra and the probe's centre can be there (farther than r_i +
// probe from every atom centre, the space sa_volume measures). Tunnels
// own the grid points along their centrelines.
//
// Frames are analysed `jobs` at a time on threads and followed in frame
// order: the results do not depend on jobs, and memory holds at most
// 2 * jobs frames' analyses.
#pragma once
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "alpha/geometry.hpp"
#include "molecule/analysis.hpp"
#include "molecule/structure.hpp"
#include "molecule/track_result.hpp"

namespace molecule {

// One frame of a trajectory or member of an ensemble.
struct Frame {
  std::size_t index = 0;  // position in the input, from 0 (before --begin/--stride)
  double time = 0;        // ps for trajectories; the index for models and file lists
  bool time_in_ps = false;  // a trajectory's time, not an index
  std::string name;       // for messages: "1l2y.pdb model 3", "3pa3.pdb", "md.xtc frame 12"
  Structure structure;
};

// Frames in input order. next() returns nothing at the end; it throws
// alpha::Error naming the file for bad input.
class FrameSource {
public:
  virtual ~FrameSource() = default;
  virtual std::optional<Frame> next() = 0;
};

// The structure of a trajectory's atoms: a PDB, mmCIF or GROMACS .gro
// file, read as `options` says (its first model).
Structure read_topology(const std::string& file, const StructureOptions& options);

// The frames of `topology` and `trajectories`:
// - no trajectory: every model of `topology` (a multi-model PDB or mmCIF);
// - structure files: `topology` and each of them, one frame each (an
//   ensemble; atoms are matched by name, so the files may differ in atoms);
// - trajectory files (DCD; GROMACS XTC and TRR when built with
//   libgromacs): their frames, the atoms those of `topology` (PDB, mmCIF or
//   GROMACS .gro; its first model), whose atom count they must have.
// Each frame's atoms are selected as `options` says (its model ignored).
std::unique_ptr<FrameSource> open_frames(const std::string& topology, const std::vector<std::string>& trajectories,
                                         const StructureOptions& options);

// One frame's coordinates: every atom of a topology's model in its file
// order (Atom::file_index), A, and its time.
struct TimedCoordinates {
  std::optional<double> time;  // ps; none: the frame's number
  std::vector<alpha::Vec3> x;
};
using CoordinatesFunction = std::function<std::optional<TimedCoordinates>()>;

// Frames given one at a time by `next` (Python's arrays and iterators),
// nothing at the end; called from the thread that runs track(), one frame
// at a time, so that only the frames in flight are held. Frame k is named
// "frame k"; a frame without the topology's atom count throws alpha::Error
// (bad input).
std::unique_ptr<FrameSource> frames_from_function(Structure topology, CoordinatesFunction next);

struct TrackOptions {
  AnalysisOptions analysis;  // each frame's search, as `pockets` runs it
  std::size_t begin = 0;     // first frame taken (input position)
  std::size_t end = std::numeric_limits<std::size_t>::max();  // frames from here on are not read
  std::size_t stride = 1;    // every stride-th frame from begin
  unsigned jobs = 1;         // frames analysed at once, on threads
  double grid_spacing = 1;   // A, the frequency and density grids'
  double grid_margin = 6;    // A, around the first frame's atoms
  double min_lining_overlap = 0.3;  // Jaccard index of lining atoms for one identity
  double transient = 0.5;  // tracks present in fewer than this share of the frames are transient
};

// Reads, searches and follows the frames; `progress(done)` after each
// frame when given. Throws AnalysisError naming the frame.
TrackResult track(FrameSource& frames, const TrackOptions& options,
                  const std::function<void(std::size_t)>& progress = {});

}  // namespace molecule
