// SPDX-License-Identifier: Apache-2.0
// Meshes of the molecular surface (alpha::eroded_union_mesh): closed,
// consistently oriented 2-manifolds without crossing triangles (exact
// test), whose area and volume approach ErodedUnion's analytic ones, on
// degenerate inputs (one ball, touching balls, coplanar centres) and on
// real proteins; and the casts of real proteins' cavities
// (alpha::cells_mesh), whose volumes approach their ms_volume.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "alpha/eroded_union.hpp"
#include "alpha/eroded_union_mesh.hpp"
#include "ball_union.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/pocket_meshes.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/structure.hpp"
#include "surface_mesh_checks.hpp"

namespace {

struct Measured {
  testing::SurfaceReport mesh;
  double volume, area;  // analytic
};

// The surface mesh of the union eroded by r, its checks and the analytic measures.
Measured measure(const alpha::UnionOfBalls& u, double r, double spacing, bool intersections = true) {
  const alpha::ErodedUnion eu(u, r);
  const alpha::LayerShare layer = eu.layer();
  const auto start = std::chrono::steady_clock::now();
  const alpha::ErodedUnionMesh m = alpha::eroded_union_mesh(eu, spacing);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Measured out{testing::surface_report(m.mesh), u.volume() - layer.volume, layer.area};
  INFO(out.mesh.summary() << "; analytic volume " << out.volume << " area " << out.area << "; " << seconds << " s, "
                          << m.mesh.triangles.size() << " triangles");
  CHECK(out.mesh.closed_manifold());
  CHECK(m.share_cells.size() == m.mesh.points.size());
  if (intersections) CHECK(testing::intersecting_pairs(m.mesh) == 0);
  return out;
}

testing::BallUnion balls(std::vector<alpha::Vec3> c, std::vector<double> r) {
  return testing::BallUnion(testing::BallSet{std::move(c), std::move(r)}, true);
}

}  // namespace

TEST_CASE("surface mesh: one ball is a sphere of radius R - r", "[surface_mesh]") {
  const testing::BallUnion b = balls({{0.3, -1.2, 2.5}}, {3.2});
  const Measured m = measure(*b.u, 1.4, 0.3);
  const double R = 1.8, pi = std::numbers::pi;
  CHECK(m.volume == Approx(4 * pi * R * R * R / 3).epsilon(1e-9));
  CHECK(m.mesh.volume == Approx(m.volume).epsilon(0.01));
  CHECK(m.mesh.area == Approx(m.area).epsilon(0.01));
  CHECK(m.mesh.components == 1);
  // Finer spacing, closer (vertices on the sphere: the error falls as the spacing squared).
  const Measured fine = measure(*b.u, 1.4, 0.15);
  CHECK(std::fabs(fine.mesh.volume - m.volume) < std::fabs(m.mesh.volume - m.volume) / 2.5);
}

TEST_CASE("surface mesh: touching, overlapping and coplanar balls", "[surface_mesh]") {
  SECTION("two balls whose eroded bodies touch: one or two components, closed either way") {
    // Eroded radii 1.8 each, centres 3.6 apart: the bodies touch at a point.
    const testing::BallUnion b = balls({{0, 0, 0}, {3.6, 0, 0}}, {3.2, 3.2});
    const Measured m = measure(*b.u, 1.4, 0.25);
    CHECK(m.mesh.volume == Approx(m.volume).epsilon(0.01));
    CHECK(m.mesh.area == Approx(m.area).epsilon(0.01));
  }
  SECTION("two overlapping balls: a reentrant torus between them") {
    const testing::BallUnion b = balls({{0, 0, 0}, {4.0, 0.1, 0}}, {3.2, 3.0});
    const Measured m = measure(*b.u, 1.4, 0.25);
    CHECK(m.mesh.components == 1);
    CHECK(m.mesh.volume == Approx(m.volume).epsilon(0.01));
    CHECK(m.mesh.area == Approx(m.area).epsilon(0.01));
  }
  SECTION("coplanar centres on a square grid, with reentrant vertices and a lattice-aligned plane") {
    std::vector<alpha::Vec3> c;
    std::vector<double> r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) c.push_back({2.5 * i, 2.5 * j, 0}), r.push_back(3.0);
    const testing::BallUnion b = balls(c, r);
    const Measured m = measure(*b.u, 1.4, 0.5);
    CHECK(m.mesh.components == 1);
    CHECK(m.mesh.volume == Approx(m.volume).epsilon(0.01));
    CHECK(m.mesh.area == Approx(m.area).epsilon(0.01));
  }
}

TEST_CASE("surface mesh: real proteins within 1% of the analytic molecular volume and area", "[surface_mesh]") {
  for (const char* name : {"1fkgA.pdb", "1ytjA.pdb", "1UYD.pdb"}) {
    INFO(name);
    const auto atoms = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/" + name).atoms;
    const molecule::AtomBalls ab = molecule::atom_balls(atoms, 1.4);
    const testing::BallUnion u = testing::BallUnion::of_weighted(ab.points, ab.weights);
    const Measured m = measure(*u.u, 1.4, molecule::kDefaultMeshResolution);
    CHECK(m.mesh.volume == Approx(m.volume).epsilon(0.01));
    CHECK(m.mesh.area == Approx(m.area).epsilon(0.01));
  }
}

TEST_CASE("cast mesh: real proteins' casts are closed and within 1% of ms_volume", "[surface_mesh]") {
  // A cast's volume is its cavity's ms_volume up to the lattice's error
  // (docs/outputs.md, Meshes; both split space by the same regions). Its creases
  // bent back (cells_mesh), 1a26A's pocket 10 of 7 A^3, its mouth rims long
  // for its volume, is -2.2% off at cast_spacing (-2.4% unbent); with
  // cast_mesh's finer second pass every cast of these five proteins is
  // within 1% (-0.95% at worst; 1a26A's pocket 10 -0.6%).
  std::size_t asserted = 0;
  for (const std::string path : {std::string(ALPHAPOCKET_TEST_DATA) + "/1fbl.pdb", std::string(ALPHAPOCKET_TEST_DATA) + "/1UYD.pdb",
                                 std::string(ALPHAPOCKET_TEST_DATA) + "/3stdA.pdb", std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb",
                                 std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb"}) {
    const molecule::Structure st = molecule::read_structure(path);
    const molecule::CavityOptions options;
    const molecule::PocketSearch search = molecule::search_pockets(st, options);
    const alpha::UnionOfBalls balls(search.shape->complex());
    const alpha::ErodedUnion eu(balls, options.probe);
    const auto check = [&](const molecule::Cavity& c, bool is_void, std::size_t rank) {
      const alpha::SurfaceMesh m = molecule::cast_mesh(eu, c, molecule::kDefaultMeshResolution);
      const testing::SurfaceReport report = testing::surface_report(m);
      INFO(path << (is_void ? " void " : " pocket ") << rank << ": ms_volume " << c.ms_volume << ", " << report.summary());
      CHECK(report.closed_manifold());
      CHECK(testing::intersecting_pairs(m) == 0);
      CHECK(report.volume == Approx(c.ms_volume).epsilon(0.01));
      ++asserted;
    };
    for (std::size_t i = 0; i < search.cavities.pockets.size(); ++i) check(search.cavities.pockets[i], false, i + 1);
    for (std::size_t i = 0; i < search.cavities.voids.size(); ++i) check(search.cavities.voids[i], true, i + 1);
  }
  CHECK(asserted >= 55);
}
