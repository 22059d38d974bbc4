// SPDX-License-Identifier: Apache-2.0
// The buried part of the solvent-accessible surface, as points, where a
// site's ligand lies (ranking/site_recentering.hpp). As P2Rank samples
// the surface: kSurfacePointsPerAtom points spread evenly (a Fibonacci
// lattice) on each atom's sphere of radius (its radius + kSurfacePointProbe),
// those inside another atom's such sphere left out, thinned to the first
// (by atom, then lattice order) of each cube of kSurfacePointSpacing; a
// point is buried when at least kBuriedPointAtoms atoms lie within
// kBuriedPointRadius of it (P2Rank's protrusion), the surface of a groove
// or pocket rather than of a knob.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "alpha/geometry.hpp"
#include "alpha/point_grid.hpp"
#include "molecule/structure.hpp"

namespace molecule {

inline constexpr double kSurfacePointProbe = 1.6;  // A, P2Rank's
inline constexpr int kSurfacePointsPerAtom = 30;
inline constexpr double kSurfacePointSpacing = 1.0;  // A
inline constexpr double kBuriedPointRadius = 10;     // A
inline constexpr int kBuriedPointAtoms = 95;

class BuriedSurface {
public:
  explicit BuriedSurface(const std::vector<Atom>& atoms);
  // Only what is near `centers`: the points within `radius` of one of them
  // are the whole surface's, in the same order (the thinning per cube is
  // local); points farther away may be missing or differ.
  BuriedSurface(const std::vector<Atom>& atoms, std::span<const alpha::Vec3> centers, double radius);
  // The surface points, in order (buried or not).
  const std::vector<alpha::Vec3>& points() const { return points_; }
  // The atoms within kBuriedPointRadius of points()[k], counted when first
  // asked for (a BuriedSurface is used by one thread).
  int atoms_near(std::size_t k) const;
  // Calls f(point) for every buried point within `radius` of `center`, in order.
  template <class F> void visit_buried(const alpha::Vec3& center, double radius, F f) const {
    grid_.visit(center, radius, [&](alpha::Index k) {
      if (norm(points_[k] - center) <= radius && atoms_near(k) >= kBuriedPointAtoms) f(points_[k]);
    });
  }

private:
  void index_atoms();
  // The points of the atoms with sampled[i] set.
  void sample(const std::vector<char>& sampled);

  const std::vector<Atom>& atoms_;
  alpha::PointGrid atom_grid_, grid_;
  double reach_ = 0;  // the largest sphere's radius
  std::vector<alpha::Vec3> points_;
  mutable std::vector<int> atoms_near_;  // -1: not counted yet
};

// Every surface point as CSV (x,y,z,atoms_near), for training/.
std::string surface_points_csv(const std::vector<Atom>& atoms);

}  // namespace molecule
