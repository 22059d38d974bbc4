// SPDX-License-Identifier: Apache-2.0
// The molecular (solvent-excluded) surface of real proteins
// (alpha::ErodedUnion on the atoms of molecule::read_structure): its volume
// against a Monte Carlo estimate from an independent nearest-point test
// (depth_oracle.hpp), its area against minus the derivative of its volume
// in the probe radius with the SAS fixed (two different integrals over the
// probe layer), and both between the van der Waals and SA unions.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "alpha/eroded_union.hpp"
#include "ball_union.hpp"
#include "depth_oracle.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/structure.hpp"
#include "molecule/surface.hpp"

namespace {

// The union of the atoms' balls.
testing::BallUnion union_of(const molecule::AtomBalls& b) {
  return testing::BallUnion::of_weighted(b.points, b.weights);
}

}  // namespace

TEST_CASE("molecular surface: area = -dV/dr, and between the vdW and SA unions, on real proteins", "[surface]") {
  for (const char* name : {"1fkgA.pdb", "1ytjA.pdb"}) {
    INFO(name);
    const auto atoms = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/" + name).atoms;
    const testing::BallUnion sas = union_of(molecule::atom_balls(atoms, 1.4)),
                             vdw = union_of(molecule::atom_balls(atoms, 0));
    const auto eroded = [&](double r) {
      const alpha::LayerShare layer = alpha::ErodedUnion(*sas.u, r).layer();
      return std::pair{sas.u->volume() - layer.volume, layer.area};
    };
    const auto [volume, area] = eroded(1.4);
    const double h = 1e-4;
    CHECK(area == Approx(-(eroded(1.4 + h).first - eroded(1.4 - h).first) / (2 * h)).epsilon(2e-5));
    CHECK(vdw.u->volume() < volume);
    CHECK(volume < sas.u->volume());
    CHECK(area < vdw.u->area());  // the probe bridges the crevices between atoms
    CHECK(eroded(1.4) == std::pair{volume, area});  // deterministic
  }
}

TEST_CASE("molecular surface: the volume of 1fkgA against Monte Carlo", "[surface]") {
  const auto atoms = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb").atoms;
  const molecule::AtomBalls b = molecule::atom_balls(atoms, 1.4);
  std::vector<double> radii;
  for (double w : b.weights) radii.push_back(std::sqrt(w));
  const testing::BallUnion sas = union_of(b);
  const double volume = sas.u->volume() - alpha::ErodedUnion(*sas.u, 1.4).layer().volume;
  CHECK(molecule::measure_surface(atoms).ms_volume == volume);  // the surface job measures the same
  const auto [mc, sigma] = testing::DepthOracle(b.points, radii, 1.4).volume_deeper(1.4, 400000, 11);
  INFO("volume " << volume << " Monte Carlo " << mc << " +- " << sigma);
  CHECK(std::fabs(volume - mc) <= 4.5 * sigma);  // sigma: 0.3 % of the volume
}
