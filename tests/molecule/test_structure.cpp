// SPDX-License-Identifier: Apache-2.0
// Reading structure files (molecule/structure.hpp): the same atoms from PDB,
// mmCIF and gzip forms of one entry; selection counts checked against an
// independent count of the PDB records; alternate locations, hydrogens,
// waters, hetero groups, chains and models on real files; one-line errors
// for bad files.
#include <catch2/catch.hpp>

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "molecule/radii.hpp"
#include "molecule/structure.hpp"

namespace {

namespace fs = std::filesystem;
using molecule::Atom;
using molecule::read_structure;
using molecule::Structure;
using molecule::StructureOptions;

std::string data(const std::string& name) { return std::string(ALPHAPOCKET_TEST_DATA) + "/" + name; }

StructureOptions keep_all() {
  StructureOptions o;
  o.keep_hydrogens = o.keep_waters = o.keep_hetero = true;
  return o;
}

// Everything but the serial number (PDB files count TER records in it).
auto fields(const Atom& a) {
  return std::tie(a.name, a.element, a.altloc, a.occupancy, a.b_factor, a.residue_name, a.seq_num, a.icode, a.chain,
                  a.hetero, a.position, a.radius);
}

void check_same_atoms(const std::vector<Atom>& a, const std::vector<Atom>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    INFO("atom " << i << ": " << a[i].chain << " " << a[i].residue_name << " " << a[i].seq_num << " " << a[i].name);
    CHECK(fields(a[i]) == fields(b[i]));
  }
}

void check_same(const Structure& a, const Structure& b) {
  check_same_atoms(a.atoms, b.atoms);
  REQUIRE(a.hetero_groups.size() == b.hetero_groups.size());
  for (std::size_t i = 0; i < a.hetero_groups.size(); ++i) {
    CHECK(a.hetero_groups[i].residue_name == b.hetero_groups[i].residue_name);
    CHECK(a.hetero_groups[i].chain == b.hetero_groups[i].chain);
    CHECK(a.hetero_groups[i].seq_num == b.hetero_groups[i].seq_num);
    check_same_atoms(a.hetero_groups[i].atoms, b.hetero_groups[i].atoms);
  }
  const auto& ra = a.report;
  const auto& rb = b.report;
  CHECK(std::tie(ra.atoms_in_model, ra.kept, ra.dropped_chain, ra.dropped_altloc, ra.dropped_water, ra.dropped_hetero,
                 ra.dropped_hydrogen, ra.hetero_groups) ==
        std::tie(rb.atoms_in_model, rb.kept, rb.dropped_chain, rb.dropped_altloc, rb.dropped_water, rb.dropped_hetero,
                 rb.dropped_hydrogen, rb.hetero_groups));
}

// The text of a file, gunzipped with zlib's own gz reader if need be (not
// the code under test).
std::string file_text(const std::string& path) {
  gzFile f = gzopen(path.c_str(), "rb");
  REQUIRE(f != nullptr);
  std::string text;
  char buf[1 << 16];
  int n = 0;
  while ((n = gzread(f, buf, sizeof buf)) > 0) text.append(buf, std::size_t(n));
  gzclose(f);
  return text;
}

// Atoms of a model, kept, and dropped for each reason.
struct Counts {
  std::size_t atoms = 0, kept = 0, chain = 0, altloc = 0, water = 0, hetero = 0, hydrogen = 0;
};

void check_report(const molecule::StructureReport& r, const Counts& c) {
  CHECK(r.atoms_in_model == c.atoms);
  CHECK(r.kept == c.kept);
  CHECK(r.dropped_chain == c.chain);
  CHECK(r.dropped_altloc == c.altloc);
  CHECK(r.dropped_water == c.water);
  CHECK(r.dropped_hetero == c.hetero);
  CHECK(r.dropped_hydrogen == c.hydrogen);
  // Every atom of the model counted once: kept or dropped for one reason.
  CHECK(r.atoms_in_model ==
        r.kept + r.dropped_chain + r.dropped_altloc + r.dropped_water + r.dropped_hetero + r.dropped_hydrogen);
}

// An independent count of what the selection keeps and drops, straight
// from the fixed columns of the ATOM/HETATM records of one model of a PDB
// file. `chosen` is the altloc expected to win (found by hand for the
// file); every HETATM residue but water is taken as hetero (none of these
// files has HETATM polymer residues).
Counts count_pdb(const std::string& path, int model, const StructureOptions& opt, char chosen) {
  Counts c;
  std::istringstream in(file_text(path));
  int current = 1;
  bool in_model = true;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("MODEL", 0) == 0) {
      current = std::stoi(line.substr(10));
      in_model = current == model;
    }
    if (line.rfind("ENDMDL", 0) == 0) in_model = false;
    const bool het = line.rfind("HETATM", 0) == 0;
    if (!in_model || (!het && line.rfind("ATOM  ", 0) != 0)) continue;
    ++c.atoms;
    const char altloc = line[16];
    const std::string residue = line.substr(17, 3);
    const std::string chain = line.substr(21, 1);
    std::string element = line.substr(76, 2);
    element.erase(0, element.find_first_not_of(' '));
    const bool wanted = opt.chains.empty() || std::count(opt.chains.begin(), opt.chains.end(), chain);
    if (!wanted)
      ++c.chain;
    else if (altloc != ' ' && altloc != chosen)
      ++c.altloc;
    else if (residue == "HOH" && !opt.keep_waters)
      ++c.water;
    else if (residue != "HOH" && het && !opt.keep_hetero)
      ++c.hetero;
    else if ((element == "H" || element == "D") && !opt.keep_hydrogens)
      ++c.hydrogen;
    else
      ++c.kept;
  }
  return c;
}

void check_counts(const std::string& file, const StructureOptions& opt, char chosen) {
  INFO(file << " model " << opt.model << " waters " << opt.keep_waters << " hetero " << opt.keep_hetero << " hydrogens "
            << opt.keep_hydrogens);
  const Structure st = read_structure(file, opt);
  const Counts c = count_pdb(file, opt.model ? opt.model : 1, opt, chosen);
  check_report(st.report, c);
  CHECK(st.atoms.size() == c.kept);
}

const Atom* find_atom(const std::vector<Atom>& atoms, const std::string& chain, int seq, const std::string& name) {
  for (const Atom& a : atoms)
    if (a.chain == chain && a.seq_num == seq && a.name == name) return &a;
  return nullptr;
}

std::size_t count_residue(const std::vector<Atom>& atoms, const std::string& chain, int seq, const std::string& res) {
  return std::count_if(atoms.begin(), atoms.end(),
                       [&](const Atom& a) { return a.chain == chain && a.seq_num == seq && a.residue_name == res; });
}

// The error message of reading path (empty if it reads).
std::string error_of(const std::string& path, const StructureOptions& opt = {}) {
  try {
    read_structure(path, opt);
  } catch (const molecule::StructureError& e) {
    return e.what();
  }
  return {};
}

// The same for the bytes of a file.
std::string parse_error(std::string_view bytes, const std::string& name, const StructureOptions& options = {}) {
  try {
    molecule::parse_structure(bytes, name, options);
  } catch (const molecule::StructureError& e) {
    return e.what();
  }
  return {};
}

// A PDB ATOM/HETATM record.
std::string pdb_atom(const char* record, int serial, const char* name, char altloc, const char* residue, char chain,
                     int seq, double x, double y, double z, double occupancy, const char* element) {
  char line[100];
  std::snprintf(line, sizeof line, "%-6s%5d %-4s%c%3s %c%4d    %8.3f%8.3f%8.3f%6.2f%6.2f          %2s\n", record,
                serial, name, altloc, residue, chain, seq, x, y, z, occupancy, 10.0, element);
  return line;
}

}  // namespace

TEST_CASE("structure: PDB and mmCIF of one entry give the same atoms", "[structure]") {
  for (const auto& [pdb, cif] : {std::pair{"1UYD.pdb", "1UYD.cif"}, std::pair{"1fbl.pdb", "1fbl.cif.gz"}}) {
    INFO(pdb << " vs " << cif);
    for (const StructureOptions& opt : {StructureOptions{}, keep_all()}) {
      const Structure a = read_structure(data(pdb), opt);
      const Structure b = read_structure(data(cif), opt);
      CHECK(a.report.format == "PDB");
      CHECK(b.report.format == "mmCIF");
      check_same(a, b);
    }
  }
}

TEST_CASE("structure: gzipped equals plain", "[structure]") {
  const Structure plain = read_structure(data("1UYD.cif"), keep_all());
  const Structure gz = read_structure(data("1UYD.cif.gz"), keep_all());
  CHECK_FALSE(plain.report.gzipped);
  CHECK(gz.report.gzipped);
  check_same(plain, gz);
  for (std::size_t i = 0; i < plain.atoms.size(); ++i) CHECK(plain.atoms[i].serial == gz.atoms[i].serial);
}

TEST_CASE("structure: format from the content, not the name", "[structure]") {
  // An mmCIF text parsed under a .pdb name, and a PDB text under .cif.
  const std::string cif = file_text(data("1UYD.cif"));
  const std::string pdb = file_text(data("1UYD.pdb"));
  const Structure a = molecule::parse_structure(cif, "entry.pdb");
  const Structure b = molecule::parse_structure(pdb, "entry.cif");
  CHECK(a.report.format == "mmCIF");
  CHECK(b.report.format == "PDB");
  check_same(a, b);
  CHECK(a.report.models == 1);
  CHECK(a.report.model == 1);
}

TEST_CASE("structure: selection counts equal an independent count of the PDB records", "[structure]") {
  for (const char* file : {"1fbl.pdb", "1UYD.pdb", "1d3z_models_1_2.pdb.gz"}) {
    StructureOptions opt;
    check_counts(data(file), opt, 'A');
    opt.keep_waters = true;
    check_counts(data(file), opt, 'A');
    opt.keep_hetero = true;
    check_counts(data(file), opt, 'A');
    opt.keep_hydrogens = true;
    check_counts(data(file), opt, 'A');
  }
  StructureOptions second;
  second.model = 2;
  check_counts(data("1d3z_models_1_2.pdb.gz"), second, 'A');
  // And the numbers, checked by hand (grep of the files' records).
  // 1fbl: 2966 ATOM + 328 HETATM records: 295 waters, HTA (27), 4 Ca, 2 Zn.
  check_report(read_structure(data("1fbl.pdb")).report, {.atoms = 3294, .kept = 2966, .water = 295, .hetero = 33});
}

TEST_CASE("structure: counts of mmCIF files (checked by hand)", "[structure]") {
  // 5i55: 218 atoms; LYS 12 in two conformers of 9 atoms at 0.50 each;
  // 12 waters; MPD (8) and ACT (4); MSE 1 (HETATM, in the polymer) kept.
  const Structure s = read_structure(data("5i55.cif"));
  check_report(s.report, {.atoms = 218, .kept = 185, .altloc = 9, .water = 12, .hetero = 12});
  CHECK(count_residue(s.atoms, "A", 1, "MSE") == 8);
  const Atom* se = find_atom(s.atoms, "A", 1, "SE");
  REQUIRE(se);
  CHECK(se->hetero);
  CHECK(se->element == "Se");
  CHECK(se->radius == 1.90);
  // 1pfe: a DNA duplex strand (chain A) and echinomycin (chain B, a
  // depsipeptide), a chloride, two quinoxalines, 80 waters; 24 atoms in
  // other conformers. Echinomycin's N2C and NCY (14 kept atoms) are HETATM
  // residues gemmi does not know as amino acids: ligand, not receptor.
  const Structure p = read_structure(data("1pfe.cif.gz"));
  check_report(p.report, {.atoms = 342, .kept = 199, .altloc = 24, .water = 80, .hetero = 39});
}

TEST_CASE("structure: alternate locations keep the highest occupancy, ties the first", "[structure]") {
  SECTION("a tie: 1UYD ILE 203 CD1 at 0.50/0.50 keeps A") {
    const Structure s = read_structure(data("1UYD.pdb"));
    const Atom* cd1 = find_atom(s.atoms, "A", 203, "CD1");
    REQUIRE(cd1);
    CHECK(cd1->altloc == 'A');
    CHECK(cd1->position == alpha::Vec3{-9.411, 20.395, 11.153});
    CHECK(count_residue(s.atoms, "A", 203, "ILE") == 8);
  }
  SECTION("1pfe: B (0.53) over A (0.47); one residue of each mixed pair") {
    StructureOptions with_hetero;
    with_hetero.keep_hetero = true;  // N2C and NCY are hetero residues
    const Structure s = read_structure(data("1pfe.cif.gz"), with_hetero);
    const Atom* c4 = find_atom(s.atoms, "A", 1, "C4'");
    REQUIRE(c4);
    CHECK(c4->altloc == 'B');
    CHECK(c4->position == alpha::Vec3{-10.276, 20.030, 19.329});
    CHECK(count_residue(s.atoms, "A", 1, "DG") == 19);  // 15 + 4 of the 2x4 in conformers
    // Microheterogeneity: N2C (A, 0.56) or NCY (B, 0.44) at 3, and the
    // reverse at 7: the 0.56 residue stays, the other goes.
    CHECK(count_residue(s.atoms, "B", 3, "N2C") == 7);
    CHECK(count_residue(s.atoms, "B", 3, "NCY") == 0);
    CHECK(count_residue(s.atoms, "B", 7, "NCY") == 7);
    CHECK(count_residue(s.atoms, "B", 7, "N2C") == 0);
  }
  SECTION("per residue by mean occupancy; a name missing from the chosen conformer keeps its best") {
    std::string pdb;
    int serial = 0;
    // Residue 1: A (0.3) and B (0.7) for CB; OG only in A and C (0.2, 0.1).
    for (const char* name : {"N", "CA", "C", "O"}) {
      ++serial;
      pdb += pdb_atom("ATOM", serial, name, ' ', "SER", 'A', 1, serial, 0, 0, 1, "");
    }
    pdb += pdb_atom("ATOM", ++serial, "CB", 'A', "SER", 'A', 1, 0, 1, 0, 0.3, "C");
    pdb += pdb_atom("ATOM", ++serial, "CB", 'B', "SER", 'A', 1, 0, 2, 0, 0.7, "C");
    pdb += pdb_atom("ATOM", ++serial, "OG", 'A', "SER", 'A', 1, 0, 3, 0, 0.2, "O");
    pdb += pdb_atom("ATOM", ++serial, "OG", 'C', "SER", 'A', 1, 0, 4, 0, 0.1, "O");
    // Residue 2: three conformers, C has the highest mean (0.4 vs 0.3, 0.3).
    for (char alt : {'A', 'B', 'C'}) {
      const double occ = alt == 'C' ? 0.4 : 0.3;
      pdb += pdb_atom("ATOM", ++serial, "CB", alt, "ALA", 'A', 2, 5, alt, 0, occ, "C");
    }
    const Structure s = molecule::parse_structure(pdb, "altlocs.pdb");
    const Atom* cb1 = find_atom(s.atoms, "A", 1, "CB");
    const Atom* og1 = find_atom(s.atoms, "A", 1, "OG");
    const Atom* cb2 = find_atom(s.atoms, "A", 2, "CB");
    REQUIRE((cb1 && og1 && cb2));
    CHECK(cb1->altloc == 'B');  // mean 0.7 over A's (0.3 + 0.2) / 2
    CHECK(og1->altloc == 'A');  // no OG in B: the best of A and C
    CHECK(cb2->altloc == 'C');
    CHECK(s.atoms.size() == 7);
    CHECK(s.report.dropped_altloc == 4);
  }
}

TEST_CASE("structure: hydrogens and models", "[structure]") {
  const std::string file = data("1d3z_models_1_2.pdb.gz");  // NMR ubiquitin with hydrogens, 2 models
  const Structure heavy = read_structure(file);
  CHECK(heavy.report.models == 2);
  CHECK(heavy.report.model == 1);
  CHECK(heavy.report.dropped_hydrogen == 629);
  CHECK(heavy.atoms.size() == 602);
  CHECK(std::none_of(heavy.atoms.begin(), heavy.atoms.end(), [](const Atom& a) { return a.element == "H"; }));

  StructureOptions with_h;
  with_h.keep_hydrogens = true;
  const Structure all = read_structure(file, with_h);
  CHECK(all.atoms.size() == 1231);
  const Atom* h = find_atom(all.atoms, "A", 1, "H1");
  REQUIRE(h);
  CHECK(h->element == "H");
  CHECK(h->radius == 1.10);

  StructureOptions second;
  second.model = 2;
  const Structure m2 = read_structure(file, second);
  CHECK(m2.report.model == 2);
  REQUIRE(m2.atoms.size() == heavy.atoms.size());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < m2.atoms.size(); ++i) {
    CHECK(m2.atoms[i].name == heavy.atoms[i].name);
    moved += !(m2.atoms[i].position == heavy.atoms[i].position);
  }
  CHECK(moved > m2.atoms.size() / 2);  // another conformation of the same atoms

  StructureOptions first;
  first.model = 1;
  check_same(read_structure(file, first), heavy);
  StructureOptions third;
  third.model = 3;
  CHECK(error_of(file, third) == file + ": no model 3 (models: 1, 2)");
}

TEST_CASE("structure: waters and hetero groups", "[structure]") {
  const std::string file = data("1fbl.pdb");
  const Structure plain = read_structure(file);
  CHECK(std::none_of(plain.atoms.begin(), plain.atoms.end(), [](const Atom& a) { return a.hetero; }));
  // Ligands come back in any case: 4 Ca, 2 Zn ions and the inhibitor HTA.
  REQUIRE(plain.hetero_groups.size() == 7);
  std::multiset<std::string> names;
  for (const auto& g : plain.hetero_groups) {
    names.insert(g.residue_name);
    CHECK(g.chain == "A");
    for (const Atom& a : g.atoms) CHECK(a.residue_name == g.residue_name);
  }
  CHECK(names == std::multiset<std::string>{"CA", "CA", "CA", "CA", "ZN", "ZN", "HTA"});
  const auto hta = std::find_if(plain.hetero_groups.begin(), plain.hetero_groups.end(),
                                [](const auto& g) { return g.residue_name == "HTA"; });
  CHECK(hta->seq_num == 900);
  CHECK(hta->atoms.size() == 27);
  CHECK(plain.report.hetero_groups == 7);

  StructureOptions waters;
  waters.keep_waters = true;
  const Structure w = read_structure(file, waters);
  CHECK(w.atoms.size() == plain.atoms.size() + 295);
  CHECK(std::count_if(w.atoms.begin(), w.atoms.end(), [](const Atom& a) { return a.residue_name == "HOH"; }) == 295);

  StructureOptions hetero;
  hetero.keep_hetero = true;
  const Structure h = read_structure(file, hetero);
  CHECK(h.atoms.size() == plain.atoms.size() + 33);
  const Atom* zn = find_atom(h.atoms, "A", 997, "ZN");
  REQUIRE(zn);
  CHECK(zn->hetero);
  CHECK(zn->element == "Zn");
  CHECK(zn->radius == 1.39);
  CHECK(h.hetero_groups.size() == 7);  // the same list, whether kept or not
}

TEST_CASE("structure: chains", "[structure]") {
  const std::string file = data("1pfe.cif.gz");
  StructureOptions a, b, ab;
  a.chains = {"A"};
  b.chains = {"B"};
  ab.chains = {"A", "B"};
  const Structure sa = read_structure(file, a);
  const Structure sb = read_structure(file, b);
  CHECK(sa.atoms.size() == 161);  // the DNA strand: 171 atoms, 10 in the other conformer
  CHECK(sb.atoms.size() == 38);   // echinomycin: 66 atoms, 14 in the other residues, 14 of N2C/NCY
  CHECK(std::all_of(sa.atoms.begin(), sa.atoms.end(), [](const Atom& x) { return x.chain == "A"; }));
  CHECK(std::all_of(sb.atoms.begin(), sb.atoms.end(), [](const Atom& x) { return x.chain == "B"; }));
  check_same(read_structure(file, ab), read_structure(file));
  CHECK(sa.report.dropped_chain + sb.report.dropped_chain == sa.report.atoms_in_model);
  // Ligands of the selected chains only.
  for (const auto& g : sb.hetero_groups) CHECK(g.chain == "B");
  StructureOptions z;
  z.chains = {"Z"};
  CHECK(error_of(file, z) == file + ": no chain 'Z' in model 1 (chains: A, B)");
}

TEST_CASE("structure: an unknown element gets the default radius and one warning", "[structure]") {
  std::string pdb;
  int serial = 0;
  for (int i = 0; i < 4; ++i) pdb += pdb_atom("HETATM", ++serial, "C1", ' ', "LIG", 'A', i + 1, i, i * i, 0, 1, "C");
  for (int i = 0; i < 3; ++i) pdb += pdb_atom("HETATM", ++serial, "Q1", ' ', "LIG", 'A', i + 1, 9, i, 1, 1, "QQ");
  StructureOptions hetero;
  hetero.keep_hetero = true;
  const Structure s = molecule::parse_structure(pdb, "unknown.pdb", hetero);
  REQUIRE(s.atoms.size() == 7);
  const Atom* q = find_atom(s.atoms, "A", 2, "Q1");
  REQUIRE(q);
  CHECK(q->element == "X");
  CHECK(q->radius == molecule::kDefaultRadius);
  REQUIRE(s.report.warnings.size() == 1);
  CHECK(s.report.warnings[0] == "3 atoms of unknown element 'QQ' (on line 5; first: atom Q1 of LIG A1) given radius 1.8 A");
}

TEST_CASE("structure: warnings count only the kept atoms", "[structure]") {
  // A protein of 4 atoms and a ligand with 2 atoms of unknown element "QX".
  std::string pdb;
  int serial = 0;
  for (int i = 0; i < 4; ++i) pdb += pdb_atom("ATOM", ++serial, "CA", ' ', "ALA", 'A', i + 1, 3.8 * i, 0, 0, 1, "C");
  for (int i = 0; i < 2; ++i) pdb += pdb_atom("HETATM", ++serial, "Q1", ' ', "LIG", 'A', 10, 9, i, 1, 1, "QX");
  pdb += pdb_atom("HETATM", ++serial, "C1", ' ', "LIG", 'A', 10, 9, 2, 1, 1, "C");

  // Dropped (the default): no warning, but the ligand atoms have radii.
  const Structure s = molecule::parse_structure(pdb, "ligand.pdb");
  CHECK(s.atoms.size() == 4);
  CHECK(s.report.dropped_hetero == 3);
  CHECK(s.report.warnings.empty());
  REQUIRE(s.hetero_groups.size() == 1);
  const auto& ligand = s.hetero_groups[0].atoms;
  REQUIRE(ligand.size() == 3);  // in the canonical order: C1, then the two Q1 by position
  CHECK(ligand[0].radius == 1.70);
  CHECK(ligand[1].element == "X");
  CHECK(ligand[1].radius == molecule::kDefaultRadius);
  CHECK(ligand[2].radius == molecule::kDefaultRadius);

  // Kept: one warning for the two atoms.
  StructureOptions hetero;
  hetero.keep_hetero = true;
  const Structure h = molecule::parse_structure(pdb, "ligand.pdb", hetero);
  CHECK(h.atoms.size() == 7);
  CHECK(h.report.warnings ==
        std::vector<std::string>{"2 atoms of unknown element 'QX' (on line 5; first: atom Q1 of LIG A10) given radius 1.8 A"});
}

TEST_CASE("structure: PDB coordinates must be numbers", "[structure]") {
  // A real file: the first ATOM record's x, y, z replaced by words; the
  // last HETATM record's z blank.
  std::string text = file_text(data("1fkgA.pdb"));
  REQUIRE(parse_error(text, "x.pdb").empty());
  std::string words = text;
  const std::size_t first = words.find("ATOM  ");
  REQUIRE(first == 0);
  words.replace(first + 30, 24, "     abc     def     ghi");
  CHECK(parse_error(words, "x.pdb") ==
        "x.pdb: line 1: bad coordinates in ATOM record (columns 31-54: '     abc     def     ghi')");
  std::string blank = text;
  const std::size_t last = blank.rfind("\nHETATM") + 1;
  const auto line_of = [&](std::size_t pos) { return std::count(blank.begin(), blank.begin() + pos, '\n') + 1; };
  const std::string xy = blank.substr(last + 30, 16);
  blank.replace(last + 46, 8, "        ");
  CHECK(parse_error(blank, "x.pdb") == "x.pdb: line " + std::to_string(line_of(last)) +
                                  ": bad coordinates in HETATM record (columns 31-54: '" + xy + "        ')");

  // Four atoms, the third record edited.
  const auto with_third = [](const std::function<void(std::string&)>& edit, const std::string& eol = "\n") {
    std::string pdb;
    for (int i = 0; i < 4; ++i) {
      std::string line = pdb_atom("ATOM", i + 1, "CA", ' ', "ALA", 'A', i + 1, 3.8 * i, 1, 0, 1, "C");
      line.pop_back();  // the "\n"
      if (i == 2) edit(line);
      pdb += line + eol;
    }
    return pdb;
  };
  const auto with_y = [&](const std::string& y, const std::string& eol = "\n") {
    return with_third([&](std::string& line) { line.replace(38, 8, y); }, eol);
  };
  for (const char* y : {"     abc", "        ", "  1.5x  ", " 1.2.3  ", " - 1.000", "     nan", "   1.5e3", "   1 2  ",
                        "       -", "       .", "\t  1.000"}) {
    INFO("'" << y << "'");
    std::string shown = y;  // as quoted: a control character becomes '?'
    std::replace(shown.begin(), shown.end(), '\t', '?');
    CHECK(parse_error(with_y(y), "x.pdb") ==
          "x.pdb: line 3: bad coordinates in ATOM record (columns 31-54: '   7.600" + shown + "   0.000')");
  }
  // Numbers written in other ways still read, with Windows line ends too.
  for (const auto& [y, value] : std::vector<std::pair<std::string, double>>{
           {"  +1.000", 1}, {"     -2.", -2}, {"      .5", 0.5}, {"-0.25   ", -0.25}, {"       7", 7}}) {
    INFO("'" << y << "'");
    for (const char* eol : {"\n", "\r\n"}) {
      const Structure st = molecule::parse_structure(with_y(y, eol), "x.pdb");
      REQUIRE(st.atoms.size() == 4);
      CHECK(st.atoms[2].position.y == value);
    }
  }
  // A record cut inside the z field (gemmi takes "\r\n" for its last columns).
  const std::string cut = with_third([](std::string& line) { line.resize(53); }, "\r\n");
  CHECK(parse_error(cut, "x.pdb") == "x.pdb: line 3: ATOM record shorter than 54 columns ('" +
                                         cut.substr(cut.find("ATOM      3"), 53) + "')");
  // Records after END are not read, nor checked.
  CHECK(molecule::parse_structure(with_y("   1.000") + "END\n" + with_y("     abc"), "x.pdb").atoms.size() == 4);
}

TEST_CASE("structure: an mmCIF _atom_site without a column gemmi needs", "[structure]") {
  const std::string text = file_text(data("1UYD.cif"));
  // Tags renamed, as if the columns were missing.
  const auto without = [&](const std::vector<std::string>& columns) {
    std::string cif = text;
    for (const std::string& c : columns) {
      const std::string tag = "\n_atom_site." + c + " ";
      const std::size_t at = cif.find(tag);
      REQUIRE(at != std::string::npos);
      cif.replace(at, tag.size(), "\n_atom_site." + c + "_gone ");
    }
    return parse_error(cif, "x.cif");
  };
  for (const std::string c : {"id", "type_symbol", "label_alt_id", "label_asym_id", "Cartn_x", "Cartn_y", "Cartn_z",
                              "occupancy", "B_iso_or_equiv", "auth_seq_id"})
    CHECK(without({c}) == "x.cif: mmCIF _atom_site lacks column(s) _atom_site." + c);
  CHECK(without({"occupancy", "Cartn_y"}) ==
        "x.cif: mmCIF _atom_site lacks column(s) _atom_site.Cartn_y, _atom_site.occupancy");
  // Optional columns: still read.
  CHECK(without({"pdbx_formal_charge", "group_PDB"}).empty());
}

TEST_CASE("structure: bad files give one line naming the file", "[structure]") {
  const std::string bad = data("bad");
  const auto expect_error = [](const std::string& path, const std::string& message) {
    INFO(path);
    const std::string e = error_of(path);
    CHECK(e == path + ": " + message);
    CHECK(e.find('\n') == std::string::npos);
  };
  expect_error(bad + "/missing.pdb", "cannot open: no such file");
  expect_error(bad, "is a directory, not a file");
  expect_error(bad + "/empty.pdb", "file is empty");
  expect_error(bad + "/not_structure.pdb", "not a PDB or mmCIF file (no data_ block, no ATOM or HETATM records)");
  expect_error(bad + "/three_atoms.pdb", "only 3 atoms after the selection, at least 4 are needed");
  expect_error(bad + "/truncated.pdb.gz", "truncated gzip data (unexpected end of file)");
  expect_error(bad + "/corrupt.pdb.gz", "corrupt gzip data (incorrect data check)");
  // gemmi's messages, made one line, with the file (and line) in front.
  CHECK(error_of(bad + "/truncated.cif") == bad + "/truncated.cif:3:1: Wrong number of values in the loop");
  CHECK(error_of(bad + "/short_line.pdb") ==
        bad + "/short_line.pdb: line 2: ATOM record shorter than 54 columns ('ATOM      1  N   ALA A   1      11.104   6.134')");

  // Other bad bytes, through parse_structure.
  CHECK(parse_error(std::string("\x7f"
                                "ELF\0\0\0\0binary",
                                15),
                    "x.pdb") == "x.pdb: binary data, not a PDB or mmCIF file");
  CHECK(parse_error("ATOM  plain text", "x.pdb.gz") == "x.pdb.gz: not gzip data (no gzip header)");
  CHECK(parse_error("  \n\n ", "x.cif") == "x.cif: file is empty");
  CHECK(parse_error("data_x\n_cell.length_a 1\n", "x.cif") == "x.cif: no atoms in the file");
  // Only waters: nothing left, and the message says why.
  std::string waters;
  for (int i = 0; i < 5; ++i) waters += pdb_atom("HETATM", i + 1, "O", ' ', "HOH", 'A', i + 1, i, 0, 0, 1, "O");
  CHECK(parse_error(waters, "w.pdb") ==
        "w.pdb: no atoms left after the selection (model 1 has 5 atoms; dropped: 5 water)");
  // Errors are alpha::Error too.
  CHECK_THROWS_AS(read_structure(bad + "/empty.pdb"), alpha::Error);
}

TEST_CASE("structure: summary line", "[structure]") {
  CHECK(molecule::summary(read_structure(data("1UYD.pdb")).report) ==
        "PDB, model 1: kept 1644 of 1950 atoms; dropped: 1 altloc, 277 water, 28 hetero; 1 hetero group");
  CHECK(molecule::summary(read_structure(data("1d3z_models_1_2.pdb.gz")).report) ==
        "PDB (gzip), model 1 of 2: kept 602 of 1231 atoms; dropped: 629 hydrogen; 0 hetero groups");
}

TEST_CASE("structure: structure file names", "[structure]") {
  for (const char* name : {"a.pdb", "A.PDB", "x/1abc.ent", "1abc.cif", "1abc.mmCIF", "1abc.cif.gz", "1abc.pdb.GZ"})
    CHECK(molecule::is_structure_file(name));
  for (const char* name : {"points.xyz", "a.gz", "pdb", "a.pdb.bz2", "a.cif.gz.txt"})
    CHECK_FALSE(molecule::is_structure_file(name));
}

TEST_CASE("structure: mmCIF coordinates that are not numbers within 1e6 A name the line and the text", "[structure]") {
  const std::string text = file_text(data("1UYD.cif"));
  // The x coordinate of the first atom (" 6.484 " in its row) replaced.
  const auto with_x = [&](const std::string& x) {
    std::string cif = text;
    const std::size_t at = cif.find(" 6.484 ");
    REQUIRE(at != std::string::npos);
    cif.replace(at, 7, " " + x + " ");
    return cif;
  };
  const std::string at = "x.cif: line 927: _atom_site.Cartn_x is ";
  CHECK(parse_error(with_x("1e20"), "x.cif") == at + "'1e20', beyond 1e6 A");
  CHECK(parse_error(with_x("1e300"), "x.cif") == at + "'1e300', beyond 1e6 A");
  CHECK(parse_error(with_x("-2e6"), "x.cif") == at + "'-2e6', beyond 1e6 A");
  CHECK(parse_error(with_x("?"), "x.cif") == at + "'?', unknown: not a coordinate");
  CHECK(parse_error(with_x("."), "x.cif") == at + "'.', inapplicable: not a coordinate");
  CHECK(parse_error(with_x("abc"), "x.cif") == at + "'abc', not a number");
  CHECK(parse_error(with_x("inf"), "x.cif") == at + "'inf', not a number");
  const Structure far = molecule::parse_structure(with_x("999999.0"), "x.cif");
  REQUIRE(find_atom(far.atoms, "A", 16, "N"));
  CHECK(find_atom(far.atoms, "A", 16, "N")->position.x == 999999.0);
}

TEST_CASE("structure: old-format PDB columns 73-80 (id code and line number) are not read", "[structure]") {
  // HOLE's gramicidin example: "1GRM 125" in columns 73-80 of every record
  // (line numbers from 10 up fail gemmi as a charge "52"). Read as
  // Biopython 1.80 reads it: 272 atoms, elements C 198, N 40, O 34.
  const std::string text = file_text(data("1grm_single.pdb"));
  const Structure s = molecule::parse_structure(text, "1grm.pdb", keep_all());
  REQUIRE(s.atoms.size() == 272);
  std::map<std::string, int> elements;
  for (const Atom& a : s.atoms) ++elements[a.element];
  CHECK(elements == std::map<std::string, int>{{"C", 198}, {"N", 40}, {"O", 34}});
  CHECK(s.report.warnings == std::vector<std::string>{"columns 73-80 hold an old-format id code and line number "
                                                      "(line 125: '1GRM 125'): ignored, elements taken from the "
                                                      "atom names"});
  // The same atoms as the file with those columns blanked.
  std::string blanked;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) blanked += line.substr(0, 72) + "\n";
  const Structure b = molecule::parse_structure(blanked, "1grm.pdb", keep_all());
  check_same(s, b);
  CHECK(b.report.warnings.empty());
}

TEST_CASE("structure: a PDB charge gemmi cannot read names the line and the text", "[structure]") {
  const auto four = [](const std::string& charge) {
    std::string pdb;
    for (int i = 0; i < 4; ++i) {
      std::string line = pdb_atom("ATOM", i + 1, "CA", ' ', "ALA", 'A', i + 1, 3.8 * i, 1, 0, 1, "C");
      line.pop_back();
      pdb += line + (i == 2 ? charge : "") + "\n";
    }
    return pdb;
  };
  for (const char* bad : {"1E", "E1", "12", "2*"}) {
    INFO(bad);
    CHECK(parse_error(four(bad), "x.pdb") ==
          "x.pdb: line 3: bad charge in ATOM record (columns 79-80: '" + std::string(bad) + "')");
  }
  for (const char* good : {"2+", "+2", "1-", "  ", "1 ", "1", "+ "}) {
    INFO(good);
    CHECK(molecule::parse_structure(four(good), "x.pdb").atoms.size() == 4);
  }
}

TEST_CASE("structure: the atoms do not depend on the order of the records", "[structure]") {
  // Two conformers of equal occupancy, B listed first: A is kept (the
  // smallest letter, not the first in the file), and the atoms come in
  // the canonical order whatever the order of the records.
  std::vector<std::string> records;
  for (int i = 0; i < 4; ++i)
    records.push_back(pdb_atom("ATOM", i + 1, i % 2 ? "CA" : "N", ' ', "ALA", 'A', i / 2 + 1, 3.8 * i, 0, 0, 1, "C"));
  records.push_back(pdb_atom("ATOM", 5, "CB", 'B', "ALA", 'A', 2, 9, 1, 0, 0.5, "C"));
  records.push_back(pdb_atom("ATOM", 6, "CB", 'A', "ALA", 'A', 2, 9, 2, 0, 0.5, "C"));
  std::sort(records.begin(), records.end());
  std::vector<Structure> reads;
  do {
    std::string pdb;
    for (const std::string& r : records) pdb += r;
    reads.push_back(molecule::parse_structure(pdb, "x.pdb"));
  } while (std::next_permutation(records.begin(), records.end()));
  REQUIRE(reads.size() == 720);
  for (const Structure& s : reads) {
    REQUIRE(s.atoms.size() == 5);
    CHECK(find_atom(s.atoms, "A", 2, "CB")->altloc == 'A');
    check_same(s, reads.front());
  }
  CHECK(reads.front().atoms[0].name == "CA");  // residue 1: CA before N
}

TEST_CASE("structure: atoms alike in identity are ordered by position, whatever the order of the records",
          "[structure]") {
  // Duplicate names: two CB without altloc (both kept); CA in altlocs A and
  // B and two CG in B only, all of occupancy 0.5: A is chosen (a tie: the
  // smallest letter) and one CG kept, by position, not the first in the
  // file. A water in the same chain stays after the residue.
  std::vector<std::string> records{
      pdb_atom("ATOM", 1, "CA", 'A', "ALA", 'A', 1, 1.5, 0, 0, 0.5, "C"),
      pdb_atom("ATOM", 2, "CA", 'B', "ALA", 'A', 1, 1.5, 0.3, 0, 0.5, "C"),
      pdb_atom("ATOM", 3, "CB", ' ', "ALA", 'A', 1, 2, 1.5, 0, 1, "C"),
      pdb_atom("ATOM", 3, "CB", ' ', "ALA", 'A', 1, 2, -1.5, 0, 1, "C"),
      pdb_atom("ATOM", 5, "CG", 'B', "ALA", 'A', 1, 3, 2, 1, 0.5, "C"),
      pdb_atom("ATOM", 6, "CG", 'B', "ALA", 'A', 1, 3, 2, -1, 0.5, "C"),
      pdb_atom("HETATM", 7, "O", ' ', "HOH", 'A', 9, 5, 5, 5, 1, "O"),
  };
  StructureOptions waters;
  waters.keep_waters = waters.keep_hetero = true;
  std::sort(records.begin(), records.end());
  std::vector<Structure> reads;
  do {
    std::string pdb;
    for (const std::string& r : records) pdb += r;
    reads.push_back(molecule::parse_structure(pdb, "x.pdb", waters));
  } while (std::next_permutation(records.begin(), records.end()));
  REQUIRE(reads.size() == 5040);
  for (const Structure& s : reads) check_same(s, reads.front());
  const std::vector<Atom>& atoms = reads.front().atoms;
  std::vector<std::string> names;
  for (const Atom& a : atoms) names.push_back(a.residue_name + ":" + a.name + (a.altloc ? std::string(1, a.altloc) : ""));
  CHECK(names == std::vector<std::string>{"ALA:CAA", "ALA:CB", "ALA:CB", "ALA:CGB", "HOH:O"});
  REQUIRE(atoms.size() == 5);
  CHECK(atoms[1].position.y == -1.5);  // the two CB by position
  CHECK(atoms[3].position.z == -1);    // the CG kept: the smaller position
}

TEST_CASE("structure: the canonical order over chains and residues, whatever the order of the records",
          "[structure]") {
  // Five chains (digits, capitals and small letters compare as bytes),
  // residue numbers with negatives, atoms of a residue out of name order,
  // two atoms alike but for position; records shuffled (seeded): the
  // atoms come sorted by chain, number, residue name, name, position
  // (the oracle: a sort by those fields).
  std::vector<std::string> records;
  int serial = 0;
  for (const char chain : {'b', 'B', '1', 'A', 'a'})
    for (const int seq : {7, -2, 0, 12, 3})
      for (const char* name : {"N", "CA", "C", "O", "CB", "CB"})
        records.push_back(pdb_atom("ATOM", ++serial, name, ' ', "SER", chain, seq, seq + 0.1 * serial, chain, 0, 1,
                                   name[0] == 'O' ? "O" : name[0] == 'N' ? "N" : "C"));
  std::mt19937 rng(16);
  for (int trial = 0; trial < 4; ++trial) {
    std::string pdb;
    for (const std::string& r : records) pdb += r;
    const std::vector<Atom> atoms = molecule::parse_structure(pdb, "x.pdb").atoms;
    REQUIRE(atoms.size() == records.size());
    std::vector<Atom> oracle = atoms;
    std::shuffle(oracle.begin(), oracle.end(), rng);
    std::sort(oracle.begin(), oracle.end(), [](const Atom& a, const Atom& b) {
      return std::tie(a.chain, a.seq_num, a.residue_name, a.name, a.position.x) <
             std::tie(b.chain, b.seq_num, b.residue_name, b.name, b.position.x);
    });
    check_same_atoms(atoms, oracle);
    CHECK(atoms.front().chain == "1");
    CHECK(atoms.front().seq_num == -2);
    std::shuffle(records.begin(), records.end(), rng);
  }
}

TEST_CASE("structure: bad mmCIF values name the line and the text", "[structure]") {
  const std::string text = file_text(data("1UYD.cif"));
  // The first atom's row (line 927) with one field replaced.
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string cif = text;
    const std::size_t at = cif.find(from);
    REQUIRE(at != std::string::npos);
    cif.replace(at, from.size(), to);
    return cif;
  };
  const std::string row = "ATOM   1    N  N   . GLU A 1 16  ? 6.484   28.442 39.441 1.00 52.44 ? 16   GLU";
  const auto error = [&](const std::string& from, const std::string& to) {
    std::string changed = row;
    REQUIRE(changed.find(from) != std::string::npos);
    changed.replace(changed.find(from), from.size(), to);
    return parse_error(with(row, changed), "x.cif");
  };
  CHECK(error(" . GLU", " VAL GLU") == "x.cif: line 927: _atom_site.label_alt_id is 'VAL', not a single character");
  CHECK(error("52.44 ?", "52.44 1E") == "x.cif: line 927: _atom_site.pdbx_formal_charge is '1E', not an integer");
  CHECK(error("? 16   GLU", "? A   GLU") ==
        "x.cif: line 927: _atom_site.auth_seq_id is 'A', not a residue number (an integer, optionally followed by "
        "the insertion code)");
  CHECK(error("16  ? 6.484", "16  AB 6.484") ==
        "x.cif: line 927: _atom_site.pdbx_PDB_ins_code is 'AB', not a single character");

  // Lines counted through quoted values, comments and text fields.
  std::string cif = "data_t\n# a comment\nloop_\n";
  for (const char* tag : {"group_PDB", "id", "type_symbol", "label_atom_id", "label_alt_id", "label_comp_id",
                          "label_asym_id", "label_seq_id", "pdbx_PDB_ins_code", "Cartn_x", "Cartn_y", "Cartn_z",
                          "occupancy", "B_iso_or_equiv", "auth_seq_id", "auth_asym_id", "pdbx_PDB_model_num"})
    cif += std::string("_atom_site.") + tag + "\n";  // lines 4-20
  cif += "ATOM 1 C \"C1' x\" . ALA A 1 ? 0 0 0 1 10 1 A 1\n";                      // line 21
  cif += "ATOM 2 C 'C2 # not a comment' . ALA A 1 ? 1 0 0 1 10 1 A 1 # a comment\n";  // line 22
  cif += "ATOM 3 C\n;C3\n;\n. ALA A 1 ? 0 1 0 1 10 1 A 1\n";                          // lines 23-26
  cif += "ATOM 4 C C4 . ALA A 1 ? 0 0 abc 1 10 1 A 1\n";                             // line 27
  CHECK(parse_error(cif, "t.cif") == "t.cif: line 27: _atom_site.Cartn_z is 'abc', not a number");
}

TEST_CASE("structure: mmCIF without its data_ line and PDB coordinates beyond 1e6 A are named", "[structure]") {
  const std::string text = file_text(data("1UYD.cif"));
  const std::string no_data = text.substr(text.find('\n') + 1);  // "data_1UYD" is the first line
  REQUIRE(text.rfind("data_", 0) == 0);
  const std::string message = parse_error(no_data, "x.cif");
  CHECK(message.rfind("x.cif: line ", 0) == 0);
  CHECK(message.find(": mmCIF without a data_ block (its first line must be data_NAME)") != std::string::npos);

  std::string pdb;
  for (int i = 0; i < 4; ++i) pdb += pdb_atom("ATOM", i + 1, "CA", ' ', "ALA", 'A', i + 1, 3.8 * i, 0, 0, 1, "C");
  pdb += pdb_atom("ATOM", 5, "CA", ' ', "ALA", 'A', 5, 0, 0, 0, 1, "C").replace(30, 8, "-9999999");
  CHECK(parse_error(pdb, "x.pdb") == "x.pdb: line 5: coordinate '-9999999' (columns 31-38) is beyond 1e6 A");
}

TEST_CASE("structure: files beyond max_input_mib are refused, gzip without inflating the rest", "[structure]") {
  const std::string text = file_text(data("1UYD.cif"));  // about 0.4 MiB
  REQUIRE(text.size() < (1u << 20));
  // 1UYD.cif, then 3 MiB of blanks: 3.4 MiB, gzipped to a few KiB.
  const std::string padded = text + std::string(3u << 20, ' ');
  uLongf size = compressBound(uLong(padded.size())) + 64;
  std::string gz(size, '\0');
  z_stream z{};
  REQUIRE(deflateInit2(&z, 9, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) == Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(padded.data()));
  z.avail_in = uInt(padded.size());
  z.next_out = reinterpret_cast<Bytef*>(gz.data());
  z.avail_out = uInt(gz.size());
  REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
  gz.resize(z.total_out);
  deflateEnd(&z);
  REQUIRE(gz.size() < 64u << 10);

  StructureOptions small;
  small.max_input_mib = 2;
  CHECK(parse_error(gz, "x.cif.gz", small) ==
        "x.cif.gz: decompresses to more than 2 MiB, the limit for a structure file (a gzip bomb? --max-input-mb "
        "raises it)");
  CHECK(parse_error(padded, "x.cif", small) ==
        "x.cif: is 3 MiB, more than the limit for a structure file of 2 MiB (--max-input-mb raises it)");
  small.max_input_mib = 4;  // within the limit: read as usual
  CHECK(molecule::parse_structure(gz, "x.cif.gz", small).atoms.size() ==
        molecule::parse_structure(text, "x.cif", small).atoms.size());
}
