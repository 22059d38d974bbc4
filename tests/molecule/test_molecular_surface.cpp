// SPDX-License-Identifier: Apache-2.0
// The molecular (solvent-excluded) surface of real proteins
// (alpha::ErodedUnion on the atoms of molecule::read_structure): its volume
// against a Monte Carlo estimate from an independent nearest-point test
// (depth_oracle.hpp), its area against minus the derivative of its volume
// in the probe radius with the SAS fixed (two different integrals over the
// probe layer), and both between the van der Waals and SA unions; per atom
// the same on a fragment, by power cell, and under reordering.
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
    // The atoms in reverse order: the same surface, to the accuracy of the
    // eroded union's integration (the order moves it by up to 2e-5).
    const std::vector<molecule::Atom> reversed(atoms.rbegin(), atoms.rend());
    const testing::BallUnion sas_reversed = union_of(molecule::atom_balls(reversed, 1.4));
    const alpha::LayerShare layer = alpha::ErodedUnion(*sas_reversed.u, 1.4).layer();
    CHECK(sas_reversed.u->volume() - layer.volume == Approx(volume).epsilon(1e-4));
    CHECK(layer.area == Approx(area).epsilon(1e-4));
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

TEST_CASE("molecular surface per atom: sums, -dV/dr and Monte Carlo by power cell on a fragment, permutation",
          "[surface]") {
  // The first 60 atoms of 1fkgA (about 8 residues): buried and exposed
  // atoms, carbonyl oxygens whose centres lie outside their power cells.
  auto atoms = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb").atoms;
  atoms.resize(60);
  const molecule::Surface s = molecule::measure_surface(atoms, {1.4, true, true});
  REQUIRE(s.ms_ball_areas.size() == atoms.size());
  REQUIRE(s.ms_ball_volumes.size() == atoms.size());
  double area = 0, volume = 0;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    area += s.ms_ball_areas[i];
    volume += s.ms_ball_volumes[i];
    CHECK(s.ms_ball_volumes[i] <= s.ball_volumes[i]);  // the MS body lies inside the SAS union
  }
  CHECK(area == Approx(*s.ms_area).epsilon(1e-12));
  CHECK(volume == Approx(*s.ms_volume).epsilon(1e-12));
  CHECK(molecule::measure_surface(atoms).ms_area == s.ms_area);  // the same totals without the split
  CHECK(molecule::measure_surface(atoms).ms_ball_areas.empty());

  // Each atom's area against minus the derivative of its volume in the
  // probe (the SAS fixed): the surface moves at unit speed, its power cell
  // stays (co-area formula per cell).
  const molecule::AtomBalls b = molecule::atom_balls(atoms, 1.4);
  const testing::BallUnion sas = union_of(b);
  const auto per_atom = [&](double r) {
    std::vector<alpha::LayerShare> shares;
    alpha::ErodedUnion(*sas.u, r).layer(shares);
    return shares;
  };
  const double h = 1e-4;
  const auto inner = per_atom(1.4 + h), outer = per_atom(1.4 - h);
  std::vector<double> radii;
  for (double w : b.weights) radii.push_back(std::sqrt(w));
  const auto [mc, sigma] = testing::DepthOracle(b.points, radii, 1.4).cell_volumes_deeper(1.4, 1000000, 23);
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    INFO("atom " << i << " " << atoms[i].name << " area " << s.ms_ball_areas[i] << " volume " << s.ms_ball_volumes[i]
                 << " Monte Carlo " << mc[i] << " +- " << sigma[i]);
    CHECK(s.ms_ball_areas[i] == Approx((inner[i].volume - outer[i].volume) / (2 * h)).epsilon(5e-3).margin(5e-3));
    CHECK(std::fabs(s.ms_ball_volumes[i] - mc[i]) <= 4.5 * sigma[i] + 0.01);
  }

  // Reversed input order: the arrays reversed, to the quadrature's
  // precision (pieces are cut and integrated from other corners; the
  // total area's own precision is about 2e-4).
  std::vector<molecule::Atom> reversed(atoms.rbegin(), atoms.rend());
  const molecule::Surface r = molecule::measure_surface(reversed, {1.4, true, true});
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const std::size_t j = atoms.size() - 1 - i;
    CHECK(r.ms_ball_areas[j] == Approx(s.ms_ball_areas[i]).epsilon(2e-3).margin(2e-3));
    CHECK(r.ms_ball_volumes[j] == Approx(s.ms_ball_volumes[i]).epsilon(2e-4).margin(1e-3));
  }
}
