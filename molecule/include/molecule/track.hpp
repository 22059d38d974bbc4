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

namespace molecule {

// One frame of a trajectory or member of an ensemble.
struct Frame {
  std::size_t index = 0;  // position in the input, from 0 (before --begin/--stride)
  double time = 0;        // ps for trajectories; the index for models and file lists
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

// Frames given as coordinates (Python's arrays): coordinates[k] holds
// every atom of `topology`'s model in its file order (Atom::file_index),
// A; times[k] (or k if empty).
std::unique_ptr<FrameSource> frames_from_coordinates(Structure topology,
                                                     std::vector<std::vector<alpha::Vec3>> coordinates,
                                                     std::vector<double> times = {});

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
  double transient = 0.5;     // TrackOptions::transient
  double seconds = 0;         // the whole run, wall clock

  double frequency_of(const Track& t) const { return double(t.observations.size()) / double(frames.size()); }
};

// Reads, searches and follows the frames; `progress(done)` after each
// frame when given. Throws AnalysisError naming the frame.
TrackResult track(FrameSource& frames, const TrackOptions& options,
                  const std::function<void(std::size_t)>& progress = {});

}  // namespace molecule
