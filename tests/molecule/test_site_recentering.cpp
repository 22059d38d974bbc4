// SPDX-License-Identifier: Apache-2.0
// The buried surface (ranking/buried_surface.hpp) against brute force on
// a real structure: each point on its atom's sphere and outside every
// other, one per cube, every free lattice point's cube kept, the atom
// counts; and the site centres (ranking/site_recentering.hpp): the mean
// of the buried points within the radius, recomputed by brute force, or
// the old centre where there is none; the surface built only around the
// centres gives the same points there.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "ranking/buried_surface.hpp"
#include "molecule/pocket_search.hpp"
#include "ranking/site_clusters.hpp"
#include "ranking/site_recentering.hpp"
#include "molecule/structure.hpp"

namespace {

using alpha::Vec3;

std::array<long, 3> cube(const Vec3& p) {
  const double s = molecule::kSurfacePointSpacing;
  return {long(std::floor(p.x / s)), long(std::floor(p.y / s)), long(std::floor(p.z / s))};
}

double sphere(const molecule::Atom& a) { return a.radius + molecule::kSurfacePointProbe; }

}  // namespace

TEST_CASE("buried surface: points on the solvent-accessible surface, one per cube, counted by brute force",
          "[site_recentering]") {
  const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb");
  const std::vector<molecule::Atom>& atoms = s.atoms;
  const molecule::BuriedSurface surface(atoms);
  const std::vector<Vec3>& points = surface.points();
  REQUIRE(points.size() > 100);
  std::set<std::array<long, 3>> cubes;
  std::size_t buried = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3& p = points[k];
    bool on_some = false, inside_other = false;
    int near = 0;
    for (const molecule::Atom& a : atoms) {
      const double d = norm(p - a.position);
      on_some |= std::fabs(d - sphere(a)) <= 1e-9;
      inside_other |= d < sphere(a) - 1e-9;
      near += d <= molecule::kBuriedPointRadius;
    }
    CHECK(on_some);
    CHECK_FALSE(inside_other);
    CHECK(surface.atoms_near(k) == near);
    buried += near >= molecule::kBuriedPointAtoms;
    CHECK(cubes.insert(cube(p)).second);  // one point per cube
  }
  CHECK(buried > 0);
  CHECK(buried < points.size());
  // Every lattice point outside the other atoms' spheres has its cube kept
  // (sampled: every 7th atom).
  const double pi = std::acos(-1.0), turn = pi * (1 + std::sqrt(5.0));
  for (std::size_t i = 0; i < atoms.size(); i += 7)
    for (int j = 0; j < molecule::kSurfacePointsPerAtom; ++j) {
      const double t = j + 0.5, z = 1 - 2 * t / molecule::kSurfacePointsPerAtom, r = std::sqrt(1 - z * z);
      const Vec3 p = atoms[i].position + sphere(atoms[i]) * Vec3{std::cos(turn * t) * r, std::sin(turn * t) * r, z};
      bool free = true;
      for (std::size_t o = 0; o < atoms.size(); ++o)
        free &= o == i || norm(p - atoms[o].position) >= sphere(atoms[o]) + 1e-9;
      if (free) CHECK(cubes.count(cube(p)) == 1);
    }
}

TEST_CASE("site recentering: each site at the mean of the buried points near its cluster centre",
          "[site_recentering]") {
  const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb");
  const molecule::PocketSearch search = molecule::search_pockets(s, {});
  molecule::Cavities clustered = search.cavities;
  molecule::cluster_site_centers(clustered);  // the centres before recentering
  const molecule::BuriedSurface surface(s.atoms);
  REQUIRE(search.cavities.sites.size() >= 3);
  std::size_t moved = 0;
  for (std::size_t k = 0; k < clustered.sites.size(); ++k) {
    const Vec3 before = clustered.sites[k].center;
    Vec3 sum{};
    double n = 0;
    for (std::size_t p = 0; p < surface.points().size(); ++p)
      if (norm(surface.points()[p] - before) <= molecule::kRecenteringRadius &&
          surface.atoms_near(p) >= molecule::kBuriedPointAtoms)
        sum = sum + surface.points()[p], n += 1;
    const Vec3 expected = n > 0 ? (1 / n) * sum : before;
    CHECK(norm(search.cavities.sites[k].center - expected) <= 1e-9);
    moved += n > 0;
  }
  CHECK(moved >= 3);
  // The surface built only around the centres (as search_pockets does)
  // has the same points near each, in the same order, and fewer in all.
  std::vector<Vec3> centers;
  for (const molecule::Site& site : clustered.sites) centers.push_back(site.center);
  const molecule::BuriedSurface near(s.atoms, centers, molecule::kRecenteringRadius);
  CHECK(near.points().size() < surface.points().size());
  for (const Vec3& c : centers) {
    std::vector<Vec3> whole, local;
    surface.visit_buried(c, molecule::kRecenteringRadius, [&](const Vec3& p) { whole.push_back(p); });
    near.visit_buried(c, molecule::kRecenteringRadius, [&](const Vec3& p) { local.push_back(p); });
    CHECK(!whole.empty());
    CHECK(local == whole);
  }
  // A site far from the molecule keeps its centre.
  molecule::Cavities far = clustered;
  far.sites.resize(1);
  far.sites[0].center = {1000, 0, 0};
  molecule::center_sites_on_buried_surface(far, surface);
  CHECK(far.sites[0].center.x == 1000);
}

TEST_CASE("site recentering: without placed centres the sites keep their order and their cavities' centres",
          "[site_recentering]") {
  const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb");
  const molecule::PocketSearch placed = molecule::search_pockets(s, {});
  molecule::CavityOptions options;
  options.site_centers = false;
  const molecule::PocketSearch unplaced = molecule::search_pockets(s, options);
  const molecule::Cavities &a = placed.cavities, &b = unplaced.cavities;
  REQUIRE(b.sites.size() == a.sites.size());
  REQUIRE(a.sites.size() >= 3);
  std::size_t moved = 0;
  for (std::size_t k = 0; k < a.sites.size(); ++k) {
    CHECK(b.sites[k].is_void == a.sites[k].is_void);
    CHECK(b.sites[k].index == a.sites[k].index);
    CHECK(b.cavity(b.sites[k]).probability == a.cavity(a.sites[k]).probability);
    CHECK(b.sites[k].center == b.cavity(b.sites[k]).center);
    moved += norm(a.sites[k].center - b.sites[k].center) > 1e-6;
  }
  CHECK(moved >= 3);  // the placed centres are elsewhere
}
