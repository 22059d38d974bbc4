// SPDX-License-Identifier: Apache-2.0
// The meshes of `alphapocket pockets` (made by molecule::analyse when its
// outputs include them, Analysis::meshes; written by PocketOutputDir):
//
//   surface   the molecular (solvent-excluded) surface, alpha::eroded_union_mesh
//             of the probe-inflated atoms: each vertex painted in the colour
//             of the cavity whose wall it lines (the cavity whose cell's
//             share counts it, ErodedUnion::share_cell), grey elsewhere,
//             with the cavity's rank by colour (pocket_colors.hpp) as its
//             `site` (0 elsewhere); each face in the colour most of its
//             vertices have;
//   casts     per pocket and void, the space it holds as the molecular
//             surface bounds it (alpha::cells_mesh of its cells), capped
//             flat at its mouths, in its colour, every vertex's site its
//             rank by colour. Its volume approaches its cavity's
//             ms_volume (up to the lattice's error: both split space by
//             the same regions), within kCastTolerance (cast_mesh).
//
// Triangle size is set by `resolution`, the surface's lattice spacing in A
// (the casts' is finer: cast_spacing).
#pragma once
#include <vector>

#include "alpha/eroded_union.hpp"
#include "alpha/lattice_contour.hpp"
#include "molecule/mesh_export.hpp"
#include "molecule/pocket_search.hpp"

namespace molecule {

struct PocketMeshes {
  TriangleMesh surface;
  std::vector<TriangleMesh> pockets, voids;  // as in Cavities
  double seconds = 0;  // wall-clock time taken
};

// Default triangle size of the surface: within 1% of the analytic area
// and volume with room to spare (on pockets-dev the area is 0.53-0.70%
// short, the volume within 0.17%; at 0.9 A the area is up to 1.07% short:
// docs/outputs.md, Meshes), in under half a second for a 3,000-atom protein.
inline constexpr double kDefaultMeshResolution = 0.7;

// A cast's lattice is finer than the surface's: kCastResolution at the
// default resolution, in proportion otherwise. Its volume is what it is
// for, and a lattice's volume error goes as the spacing squared times the
// area, larger per volume for a cavity than for a whole protein. Finer
// still for a small cavity, which has more area per volume: below
// kFullResolutionCast of ms_volume the spacing is scaled by
// cbrt(ms_volume / kFullResolutionCast) (as many lattice cells across as
// such a cast), to at least a quarter: casts of a few A^3 are thin (1UYD's
// of 5.6 A^3: -3.7% at half, -1.8% at a quarter).
inline constexpr double kCastResolution = 0.5;      // A
inline constexpr double kFullResolutionCast = 150;  // A^3
double cast_spacing(double resolution, double ms_volume);

// The cast of a cavity (alpha::cells_mesh of its cells) at cast_spacing;
// if its volume is more than kCastTolerance off the cavity's ms_volume,
// again finer, by the error's square root (the lattice's error goes as the
// spacing squared), for half the tolerance, at most twice as fine. What is
// left of that error after the creases (cells_mesh) is mostly a cast's
// thin wedges between its mouths and the molecular surface, which a
// lattice misses where they are thinner than its spacing (pockets-dev:
// bench/README, Casts against ms_volume).
inline constexpr double kCastTolerance = 0.01;
alpha::SurfaceMesh cast_mesh(const alpha::ErodedUnion& eu, const Cavity& cavity, double resolution);

// Made of the search's solvent-excluded body (PocketSearch::bodies, eroded
// by the search's probe). Throws alpha::Error for a resolution that is not
// > 0 or a molecule too large for it (more than 2^31 lattice nodes), and
// for a search that kept no bodies (search_pockets without keep_bodies:
// Misuse).
PocketMeshes pocket_meshes(const PocketSearch& search, double resolution);

}  // namespace molecule
