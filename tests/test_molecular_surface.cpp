// The molecular (solvent-excluded) surface of real proteins
// (alpha::ErodedUnion on the atoms of molecule::read_structure): its area
// is minus the derivative of its volume in the probe radius with the SAS
// fixed (two different integrals over the probe layer), and it lies between
// the van der Waals and the solvent-accessible unions.
#include <catch2/catch.hpp>

#include <string>

#include "alpha/eroded_union.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/structure.hpp"

namespace {

struct Union {
  alpha::Triangulation t;
  alpha::AlphaComplex complex;
  alpha::UnionOfBalls balls;
  explicit Union(molecule::AtomBalls b) : t(std::move(b.points), std::move(b.weights)), complex(t), balls(complex) {}
};

}  // namespace

TEST_CASE("molecular surface: area = -dV/dr, and between the vdW and SA unions, on real proteins", "[surface]") {
  for (const char* name : {"1fkgA.pdb", "1ytjA.pdb"}) {
    INFO(name);
    const auto atoms = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/" + name).atoms;
    const Union sas(molecule::atom_balls(atoms, 1.4)), vdw(molecule::atom_balls(atoms, 0));
    const auto eroded = [&](double r) {
      const alpha::LayerShare layer = alpha::ErodedUnion(sas.balls, r).layer();
      return std::pair{sas.balls.volume() - layer.volume, layer.area};
    };
    const auto [volume, area] = eroded(1.4);
    const double h = 1e-4;
    CHECK(area == Approx(-(eroded(1.4 + h).first - eroded(1.4 - h).first) / (2 * h)).epsilon(2e-5));
    CHECK(vdw.balls.volume() < volume);
    CHECK(volume < sas.balls.volume());
    CHECK(area < vdw.balls.area());  // the probe bridges the crevices between atoms
    CHECK(eroded(1.4) == std::pair{volume, area});  // deterministic
  }
}
