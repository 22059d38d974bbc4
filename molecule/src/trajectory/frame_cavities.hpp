// SPDX-License-Identifier: Apache-2.0
// What tracking keeps of one frame's analysis: each pocket, void and
// tunnel with its measures, its lining atoms and residues by name, and the
// grid points of its space (molecule/track_result.hpp); and the frame's
// contribution to the density grid. The analysis itself (triangulation,
// complex) is dropped once this is taken.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "molecule/analysis.hpp"
#include "molecule/track_result.hpp"

namespace molecule {

struct FrameCavity {
  CavityKind kind = CavityKind::pocket;
  Observation measures;                   // frame and track not set
  std::vector<std::string> lining_atoms;  // "A:TYR:42:OH", sorted, unique
  std::vector<std::string> residues;      // "A:TYR:42", sorted, unique
  std::vector<std::uint32_t> space;       // grid point indices, sorted
};

struct FrameCavities {
  FrameInfo info;
  std::vector<FrameCavity> cavities;       // pockets, voids, tunnels, each by rank
  std::vector<std::uint32_t> density_hits;  // one grid point per cell orthocentre and cube point, any order
};

// The grid of a run: the first frame's atoms' bounding box grown by
// `margin`, points `spacing` apart. Throws alpha::Error (limit exceeded)
// past 2^31 points.
SpaceGrid grid_around(const std::vector<Atom>& atoms, double spacing, double margin);

// The cavities of `analysis` on `grid`.
FrameCavities frame_cavities(const Analysis& analysis, const SpaceGrid& grid);

}  // namespace molecule
