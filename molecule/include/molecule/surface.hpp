// SPDX-License-Identifier: Apache-2.0
// The surface job (`alphapocket surface`): the solvent-accessible (SA)
// area and volume of a set of balls, measured analytically as their union
// over the weighted alpha complex at alpha_sq = 0 (alpha::UnionOfBalls), the
// SA area of each ball, and for atoms the solvent-excluded (molecular, MS)
// surface: that union eroded by the probe (alpha::ErodedUnion).
//
// The result owns plain numbers only: the triangulation and complex it was
// measured on are gone when the function returns.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "alpha/geometry.hpp"
#include "molecule/cavities.hpp"
#include "molecule/structure.hpp"

namespace molecule {

struct SurfaceOptions {
  double probe = CavityOptions{}.probe;  // A, added to every atom radius (0: van der Waals balls)
  bool excluded = true;   // also the MS surface (several times the SA's time)
  bool excluded_per_atom = false;  // and its area and volume per atom (about twice the MS time)
};

struct Surface {
  std::size_t balls = 0;
  double sa_area = 0;    // A^2
  double sa_volume = 0;  // A^3
  // The solvent-excluded (molecular) surface: none for bare balls or
  // without SurfaceOptions::excluded.
  std::optional<double> ms_area, ms_volume;
  std::vector<double> ball_areas;    // SA area of each ball (atom), in input order; 0 for a buried one
  std::vector<double> ball_volumes;  // SA volume of each: its ball within its power cell (sum: sa_volume)
  // With SurfaceOptions::excluded_per_atom: the MS surface's area and the
  // volume it encloses inside each atom's power cell (the cell of
  // ball_volumes), in input order; they sum to ms_area and ms_volume up to
  // rounding. Buried atoms may get volume (their cells reach the surface).
  std::vector<double> ms_ball_areas, ms_ball_volumes;
  std::size_t hidden = 0;          // balls inside others (no power cell)
  double complex_seconds = 0, union_seconds = 0, excluded_seconds = 0;  // wall clock, for logs
};

// The atoms as balls of radius (atom radius + probe). Throws alpha::Error:
// BadInput for atoms the triangulation refuses (a coordinate out of range),
// Misuse for a negative or non-finite probe.
Surface measure_surface(const std::vector<Atom>& atoms, const SurfaceOptions& options = {});

// Balls given by centres and squared radii (weights; no probe, no MS
// surface). Any number >= 1 of balls, flat or not. Throws alpha::Error
// (BadInput: no balls, a negative or non-finite weight; Misuse: sizes differ).
Surface measure_balls(std::vector<alpha::Vec3> centres, std::vector<double> weights);

// A structure file's selected atoms (at least options.min_atoms; 1 is
// enough for a surface), measured; errors name the file.
Surface surface_of_file(const std::string& path, const StructureOptions& selection,
                        const SurfaceOptions& options = {});
// The same from the file's bytes (molecule::parse_structure); `name` stands
// for the file in messages.
Surface surface_of_content(const std::string& name, std::string_view content, const StructureOptions& selection,
                           const SurfaceOptions& options = {});

}  // namespace molecule
