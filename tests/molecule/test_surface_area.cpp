// SPDX-License-Identifier: Apache-2.0
// Solvent-accessible surface area of real proteins (molecule::measure_surface
// on the atoms of molecule::read_structure, ProtOr radius + probe 1.4 A)
// against FreeSASA's Lee-Richards with many slices, in total and atom by
// atom. FreeSASA (Debian: freesasa) is the oracle; without it the test is
// not built.
#ifdef ALPHAPOCKET_FREESASA
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "freesasa_output.hpp"
#include "molecule/structure.hpp"
#include "molecule/surface.hpp"

namespace {

using AtomKey = std::tuple<std::string, int, std::string>;  // chain, residue number, atom name

// FreeSASA's per-atom SASA with Lee-Richards at `slices` slices per atom.
// Its defaults match ours: ProtOr radii, no HETATM records, no hydrogens.
std::map<AtomKey, double> freesasa_areas(const std::string& file, int slices) {
  std::map<AtomKey, double> areas;
  for (const FreesasaAtom& a : run_freesasa(ALPHAPOCKET_FREESASA, file,
                                            "--lee-richards --resolution=" + std::to_string(slices) +
                                                " --probe-radius=1.4"))
    areas[{a.chain, a.seq_num, a.name}] = a.area;
  return areas;
}

}  // namespace

TEST_CASE("surface: SASA equals FreeSASA's Lee-Richards on real proteins, in total and per atom",
          "[surface][freesasa]") {
  // 1ytjA has a peptide in HETATM records, 1fkgA hydrogens and a ligand.
  const std::string file = GENERATE(std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb",
                                    std::string(ALPHAPOCKET_TEST_DATA) + "/1ytjA.pdb",
                                    std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb",
                                    std::string(ALPHAPOCKET_TEST_DATA) + "/1UYD.pdb");
  INFO(file);
  // 1000 slices per atom: FreeSASA's total is then within about 1e-5 of
  // its limit (the exact area).
  const auto expected = freesasa_areas(file, 1000);
  // The same atoms as FreeSASA: no HETATM records at all.
  std::vector<molecule::Atom> atoms;
  for (molecule::Atom& a : molecule::read_structure(file).atoms)
    if (!a.hetero) atoms.push_back(std::move(a));
  REQUIRE(atoms.size() == expected.size());
  const molecule::Surface u = molecule::measure_surface(atoms, {.probe = 1.4, .excluded = false});

  double total = 0, worst = 0;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const molecule::Atom& a = atoms[i];
    const auto it = expected.find({a.chain, a.seq_num, a.name});
    REQUIRE(it != expected.end());
    total += it->second;
    worst = std::max(worst, std::fabs(u.ball_areas[i] - it->second));
    INFO(a.chain << " " << a.residue_name << " " << a.seq_num << " " << a.name);
    CHECK(u.ball_areas[i] == Approx(it->second).margin(0.05));
  }
  INFO("worst atom difference " << worst << " A^2");
  CHECK(u.sa_area == Approx(total).epsilon(5e-5));  // 100 times tighter than the 0.5 % required
}
#endif
