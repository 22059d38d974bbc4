// SPDX-License-Identifier: Apache-2.0
// ProtOr radii (molecule/radii.hpp): values from Tsai et al. (1999) by hand,
// and FreeSASA's own radii (the `freesasa` program, when installed) as the
// oracle for whole proteins and for the element fallback.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>

#include <unistd.h>

#include "freesasa_output.hpp"
#include "molecule/radii.hpp"
#include "molecule/structure.hpp"

using molecule::atom_radius;
using molecule::radius;
using molecule::RadiusSource;

TEST_CASE("radii: the table is ProtOr", "[radii]") { CHECK(molecule::kRadiusTable == "ProtOr"); }

TEST_CASE("radii: ProtOr values of known atoms (Tsai et al. 1999, Table 2)", "[radii]") {
  // Backbone of every amino acid: N 1.64 (N3H1), CA 1.88 (C4H1), C 1.61
  // (C3H0), O 1.42 (O1H0), OXT 1.46 (O2H1).
  for (const char* res : {"ALA", "ARG", "GLY", "PRO", "TRP", "MSE", "SEC", "PYL", "ASX", "GLX"}) {
    INFO(res);
    CHECK(radius(res, "N", "N") == 1.64);
    CHECK(radius(res, "CA", "C") == 1.88);
    CHECK(radius(res, "C", "C") == 1.61);
    CHECK(radius(res, "O", "O") == 1.42);
    CHECK(radius(res, "OXT", "O") == 1.46);
  }
  CHECK(radius("ALA", "CB", "C") == 1.88);  // C4H3
  CHECK(radius("GLY", "CA", "C") == 1.88);  // C4H2
  CHECK(radius("PHE", "CZ", "C") == 1.76);  // aromatic CH: C3H1
  CHECK(radius("PHE", "CG", "C") == 1.61);  // C3H0
  CHECK(radius("TYR", "OH", "O") == 1.46);  // O2H1
  CHECK(radius("ASP", "OD1", "O") == 1.42);
  CHECK(radius("LYS", "NZ", "N") == 1.64);  // N4H3
  CHECK(radius("MET", "SD", "S") == 1.77);  // S2H0
  CHECK(radius("CYS", "SG", "S") == 1.77);  // S2H1
  CHECK(radius("MSE", "SE", "SE") == 1.90);
  CHECK(radius("ASX", "XD1", "X") == 1.50);
  CHECK(radius("HOH", "O", "O") == 1.46);
  CHECK(radius("ACE", "CH3", "C") == 1.88);
  CHECK(radius("NH2", "N", "N") == 1.64);
  // Nucleotides: phosphate, sugar and bases.
  CHECK(radius("DA", "P", "P") == 1.80);
  CHECK(radius("A", "O2'", "O") == 1.46);
  CHECK(radius("DA", "C2'", "C") == 1.88);
  CHECK(radius("DT", "C7", "C") == 1.88);
  CHECK(radius("U", "C5", "C") == 1.76);
  CHECK(radius("DG", "O6", "O") == 1.42);
  CHECK(radius("C", "N4", "N") == 1.64);

  const auto cb = atom_radius("ALA", "CB", "C");
  CHECK(cb.source == RadiusSource::ProtOr);
  CHECK(cb.type == "C4H3");
  CHECK(atom_radius("TRP", "CZ2", "C").type == "C3H1");
  // Blanks around names (as in PDB columns) do not matter.
  CHECK(atom_radius(" ALA", " CB ", " C").type == "C4H3");
}

TEST_CASE("radii: other atoms fall back to the element", "[radii]") {
  // DNA has no O2'; an unknown residue or atom name uses the element.
  CHECK(atom_radius("DA", "O2'", "O").source == RadiusSource::Element);
  CHECK(radius("DA", "O2'", "O") == 1.52);
  CHECK(radius("ALA", "CX", "C") == 1.70);
  CHECK(radius("LIG", "CA", "C") == 1.70);
  CHECK(radius("LIG", "N1", "N") == 1.55);
  CHECK(radius("LIG", "O1", "O") == 1.52);
  CHECK(radius("LIG", "S1", "S") == 1.80);
  CHECK(radius("ZN", "ZN", "ZN") == 1.39);
  CHECK(radius("CA", "CA", "CA") == 2.31);  // calcium, not an alpha carbon
  CHECK(radius("HEM", "FE", "Fe") == 1.26);
  CHECK(radius("LIG", "SE1", "se") == 1.90);
  CHECK(radius("ALA", "H", "H") == 1.10);  // Mantina et al. 2009
  CHECK(radius("ALA", "D", "D") == 1.10);  // deuterium as hydrogen
  CHECK(radius("BR", "BR", "Br") == 1.83);
  CHECK(atom_radius("LIG", "C1", "C").type.empty());

  for (const char* unknown : {"Q", "", "  ", "XYZ", "X", "Rf", "Og"}) {
    INFO("'" << unknown << "'");
    const auto r = atom_radius("LIG", "Q1", unknown);
    CHECK(r.source == RadiusSource::Default);
    CHECK(r.value == molecule::kDefaultRadius);
    CHECK(molecule::element_radius(unknown) < 0);
  }
}

#ifdef ALPHAPOCKET_FREESASA
namespace {

namespace fs = std::filesystem;

using AtomKey = std::tuple<std::string, std::string, int, std::string>;  // chain, residue, number, atom

// The radius FreeSASA gave each atom of a file.
std::map<AtomKey, double> freesasa_radii(const std::string& file, const std::string& flags) {
  std::map<AtomKey, double> radii;
  for (const FreesasaAtom& a : run_freesasa(ALPHAPOCKET_FREESASA, file, flags))
    radii[{a.chain, a.residue_name, a.seq_num, a.name}] = a.radius;
  return radii;
}

std::string test_data(const std::string& name) { return std::string(ALPHAPOCKET_TEST_DATA) + "/" + name; }

}  // namespace

TEST_CASE("radii: equal to FreeSASA's ProtOr radii atom for atom on real proteins", "[radii][freesasa]") {
  // freesasa --hetatm keeps ligands and waters, skips hydrogens, and keeps
  // the first alternate location (ties in these files, as our choice).
  const std::string file =
      GENERATE(test_data("1fbl.pdb"), test_data("1UYD.pdb"), std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb");
  INFO(file);
  const auto expected = freesasa_radii(file, "--hetatm");
  molecule::StructureOptions keep_all;
  keep_all.keep_waters = keep_all.keep_hetero = true;
  const molecule::Structure st = molecule::read_structure(file, keep_all);
  REQUIRE(st.atoms.size() == expected.size());
  std::size_t protor = 0;
  for (const molecule::Atom& a : st.atoms) {
    const auto it = expected.find({a.chain, a.residue_name, a.seq_num, a.name});
    INFO(a.chain << " " << a.residue_name << " " << a.seq_num << " " << a.name);
    REQUIRE(it != expected.end());
    CHECK(std::fabs(a.radius - it->second) < 0.005);
    protor += atom_radius(a.residue_name, a.name, a.element).source == RadiusSource::ProtOr;
  }
  CHECK(protor > st.atoms.size() / 2);  // the comparison covers ProtOr radii, not only elements
}

TEST_CASE("radii: element radii equal FreeSASA's guesses", "[radii][freesasa]") {
  // One HETATM per element in an unknown residue: FreeSASA guesses the
  // radius from the element column (0 where it has no value).
  const char* elements[] = {"H",  "C",  "N",  "O",  "F",  "NA", "MG", "AL", "SI", "P",  "S",  "CL", "K",  "CA",
                            "SC", "TI", "V",  "CR", "MN", "FE", "CO", "NI", "CU", "ZN", "GA", "GE", "AS", "SE",
                            "BR", "KR", "RB", "SR", "Y",  "ZR", "MO", "RU", "RH", "PD", "AG", "CD", "IN", "SN",
                            "SB", "TE", "I",  "XE", "CS", "BA", "LA", "CE", "PR", "ND", "SM", "EU", "GD", "TB",
                            "DY", "HO", "ER", "TM", "YB", "LU", "HF", "TA", "W",  "RE", "OS", "IR", "PT", "AU",
                            "HG", "TL", "PB", "BI", "U",  "LI", "BE", "B",  "HE", "NE", "AR"};
  const fs::path dir = fs::temp_directory_path() / ("radii_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "elements.pdb").string();
  {
    std::ofstream out(file);
    int serial = 0;
    for (const char* e : elements) {
      ++serial;
      char line[128];
      std::snprintf(line, sizeof line, "HETATM%5d %-4s LIG A%4d    %8.3f%8.3f%8.3f  1.00  0.00          %2s\n", serial,
                    e, serial, 5.0 * serial, 0.0, 0.0, e);
      out << line;
    }
  }
  const auto expected = freesasa_radii(file, "--hetatm --hydrogen");
  fs::remove_all(dir);
  REQUIRE(expected.size() == std::size(elements));
  for (const auto& [key, r] : expected) {
    const std::string& element = std::get<3>(key);
    INFO(element);
    REQUIRE(r > 0);
    CHECK(std::fabs(molecule::element_radius(element) - r) < 0.005);
    CHECK(radius("LIG", element, element) == molecule::element_radius(element));
  }
}
#endif
