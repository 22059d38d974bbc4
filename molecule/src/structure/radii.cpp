// SPDX-License-Identifier: Apache-2.0
#include "molecule/radii.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include <gemmi/elem.hpp>

namespace molecule {
namespace {

struct TypeRadius {
  std::string_view type;
  double radius;
};

// ProtOr types and radii (Tsai et al. 1999, Table 2), then the types
// FreeSASA adds for nucleotides, water, selenium and ASX/GLX.
constexpr TypeRadius kTypes[] = {
    {"C3H0", 1.61}, {"C3H1", 1.76}, {"C4H1", 1.88}, {"C4H2", 1.88}, {"C4H3", 1.88},  {"N3H0", 1.64},  {"N3H1", 1.64},
    {"N3H2", 1.64}, {"N4H3", 1.64}, {"O1H0", 1.42}, {"O2H1", 1.46}, {"S2H0", 1.77},  {"S2H1", 1.77},  {"P4H0", 1.80},
    {"O2H0", 1.46}, {"O2H2", 1.46}, {"N2H0", 1.64}, {"N2H2", 1.64}, {"SE2H0", 1.90}, {"SE2H1", 1.90}, {"X1H0", 1.50},
};

struct AtomType {
  std::string_view atom, type;
};
using Atoms = std::span<const AtomType>;

// Atoms shared by several residues.
constexpr AtomType kPeptide[] = {{"N", "N3H1"}, {"CA", "C4H1"}, {"C", "C3H0"}, {"O", "O1H0"}, {"OXT", "O2H1"}};
constexpr AtomType kPhosphateSugar[] = {{"OP3", "O2H1"}, {"P", "P4H0"},   {"OP1", "O1H0"}, {"OP2", "O2H1"},
                                        {"O5'", "O2H0"}, {"C5'", "C4H2"}, {"C4'", "C4H1"}, {"O4'", "O2H0"},
                                        {"C3'", "C4H1"}, {"O3'", "O2H1"}, {"C1'", "C4H1"}};
constexpr AtomType kRibose2[] = {{"C2'", "C4H1"}, {"O2'", "O2H1"}};
constexpr AtomType kDeoxyribose2[] = {{"C2'", "C4H2"}};

// Side chains. GLY's CA has two hydrogens, PRO's N none.
constexpr AtomType kAla[] = {{"CB", "C4H3"}};
constexpr AtomType kArg[] = {{"CB", "C4H2"}, {"CG", "C4H2"},  {"CD", "C4H2"}, {"NE", "N3H1"},
                             {"CZ", "C3H0"}, {"NH1", "N3H2"}, {"NH2", "N3H2"}};
constexpr AtomType kAsn[] = {{"CB", "C4H2"}, {"CG", "C3H0"}, {"OD1", "O1H0"}, {"ND2", "N3H2"}};
constexpr AtomType kAsp[] = {{"CB", "C4H2"}, {"CG", "C3H0"}, {"OD1", "O1H0"}, {"OD2", "O2H1"}};
constexpr AtomType kCys[] = {{"CB", "C4H2"}, {"SG", "S2H1"}};
constexpr AtomType kGln[] = {{"CB", "C4H2"}, {"CG", "C4H2"}, {"CD", "C3H0"}, {"OE1", "O1H0"}, {"NE2", "N3H2"}};
constexpr AtomType kGlu[] = {{"CB", "C4H2"}, {"CG", "C4H2"}, {"CD", "C3H0"}, {"OE1", "O1H0"}, {"OE2", "O2H1"}};
constexpr AtomType kGly[] = {{"CA", "C4H2"}};
constexpr AtomType kHis[] = {{"CB", "C4H2"},  {"CG", "C3H0"},  {"ND1", "N3H1"},
                             {"CD2", "C3H1"}, {"CE1", "C3H1"}, {"NE2", "N3H1"}};
constexpr AtomType kIle[] = {{"CB", "C4H1"}, {"CG1", "C4H2"}, {"CG2", "C4H3"}, {"CD1", "C4H3"}};
constexpr AtomType kLeu[] = {{"CB", "C4H2"}, {"CG", "C4H1"}, {"CD1", "C4H3"}, {"CD2", "C4H3"}};
constexpr AtomType kLys[] = {{"CB", "C4H2"}, {"CG", "C4H2"}, {"CD", "C4H2"}, {"CE", "C4H2"}, {"NZ", "N4H3"}};
constexpr AtomType kMet[] = {{"CB", "C4H2"}, {"CG", "C4H2"}, {"SD", "S2H0"}, {"CE", "C4H3"}};
constexpr AtomType kPhe[] = {{"CB", "C4H2"},  {"CG", "C3H0"},  {"CD1", "C3H1"}, {"CD2", "C3H1"},
                             {"CE1", "C3H1"}, {"CE2", "C3H1"}, {"CZ", "C3H1"}};
constexpr AtomType kPro[] = {{"N", "N3H0"}, {"CB", "C4H2"}, {"CG", "C4H2"}, {"CD", "C4H2"}};
constexpr AtomType kSer[] = {{"CB", "C4H2"}, {"OG", "O2H1"}};
constexpr AtomType kThr[] = {{"CB", "C4H1"}, {"OG1", "O2H1"}, {"CG2", "C4H3"}};
constexpr AtomType kTrp[] = {{"CB", "C4H2"},  {"CG", "C3H0"},  {"CD1", "C3H1"}, {"CD2", "C3H0"}, {"NE1", "N3H1"},
                             {"CE2", "C3H0"}, {"CE3", "C3H1"}, {"CZ2", "C3H1"}, {"CZ3", "C3H1"}, {"CH2", "C3H1"}};
constexpr AtomType kTyr[] = {{"CB", "C4H2"},  {"CG", "C3H0"},  {"CD1", "C3H1"}, {"CD2", "C3H1"},
                             {"CE1", "C3H1"}, {"CE2", "C3H1"}, {"CZ", "C3H0"},  {"OH", "O2H1"}};
constexpr AtomType kVal[] = {{"CB", "C4H1"}, {"CG1", "C4H3"}, {"CG2", "C4H3"}};
// Selenomethionine, selenocysteine, pyrrolysine; ASX and GLX (Asn or Asp,
// Gln or Glu) with the ambiguous atoms XD1/XD2, XE1/XE2.
constexpr AtomType kMse[] = {{"CB", "C4H2"}, {"CG", "C4H2"}, {"SE", "SE2H0"}, {"CE", "C4H3"}};
constexpr AtomType kSec[] = {{"CB", "C4H2"}, {"SE", "SE2H1"}};
constexpr AtomType kPyl[] = {{"CB", "C4H2"},  {"CG", "C4H2"},  {"CD", "C4H2"},  {"CE", "C4H2"}, {"NZ", "N3H1"},
                             {"C2", "C3H0"},  {"O2", "O1H0"},  {"CA2", "C4H1"}, {"N2", "N2H0"}, {"CE2", "C3H1"},
                             {"CD2", "C4H2"}, {"CG2", "C4H1"}, {"CB2", "C4H3"}};
constexpr AtomType kAsx[] = {{"CB", "C4H2"}, {"CG", "C3H0"}, {"XD1", "X1H0"}, {"XD2", "X1H0"}};
constexpr AtomType kGlx[] = {{"CB", "C4H2"}, {"CG", "C4H2"}, {"CD", "C3H0"}, {"XE1", "X1H0"}, {"XE2", "X1H0"}};

// Bases.
constexpr AtomType kAdenine[] = {{"N9", "N3H0"}, {"C8", "C3H1"}, {"N7", "N2H0"}, {"C5", "C3H0"}, {"C6", "C3H0"},
                                 {"N6", "N3H2"}, {"N1", "N2H0"}, {"C2", "C3H1"}, {"N3", "N2H0"}, {"C4", "C3H0"}};
constexpr AtomType kGuanine[] = {{"N9", "N3H0"}, {"C8", "C3H1"}, {"N7", "N2H0"}, {"C5", "C3H0"},
                                 {"C6", "C3H0"}, {"O6", "O1H0"}, {"N1", "N3H1"}, {"C2", "C3H0"},
                                 {"N2", "N3H2"}, {"N3", "N2H0"}, {"C4", "C3H0"}};
constexpr AtomType kHypoxanthine[] = {{"N9", "N3H0"}, {"C8", "C3H1"}, {"N7", "N2H0"}, {"C5", "C3H0"}, {"C6", "C3H0"},
                                      {"O6", "O1H0"}, {"N1", "N3H1"}, {"C2", "C3H1"}, {"N3", "N2H0"}, {"C4", "C3H0"}};
constexpr AtomType kCytosine[] = {{"N1", "N3H0"}, {"C2", "C3H0"}, {"O2", "O1H0"}, {"N3", "N2H0"},
                                  {"C4", "C3H0"}, {"N4", "N3H2"}, {"C5", "C3H1"}, {"C6", "C3H1"}};
constexpr AtomType kThymine[] = {{"N1", "N3H0"}, {"C2", "C3H0"}, {"O2", "O1H0"}, {"N3", "N3H1"}, {"C4", "C3H0"},
                                 {"O4", "O1H0"}, {"C5", "C3H0"}, {"C7", "C4H3"}, {"C6", "C3H1"}};
constexpr AtomType kUracil[] = {{"N1", "N3H0"}, {"C2", "C3H0"}, {"O2", "O1H0"}, {"N3", "N3H1"},
                                {"C4", "C3H0"}, {"O4", "O1H0"}, {"C5", "C3H1"}, {"C6", "C3H1"}};

// Water and the terminal caps (acetyl, amide N).
constexpr AtomType kWater[] = {{"O", "O2H2"}};
constexpr AtomType kAce[] = {{"C", "C3H1"}, {"O", "O1H0"}, {"CH3", "C4H3"}};
constexpr AtomType kNh2[] = {{"N", "N2H2"}};

struct ResidueTypes {
  constexpr ResidueTypes(std::string_view n, Atoms a, Atoms b = {}, Atoms c = {}) : name(n), parts{a, b, c} {}
  std::string_view name;
  // Searched in order: the first part naming the atom gives its type (a
  // side chain before the backbone it may override).
  std::array<Atoms, 3> parts;
};

constexpr ResidueTypes kResidues[] = {
    {"ALA", kAla, kPeptide},
    {"ARG", kArg, kPeptide},
    {"ASN", kAsn, kPeptide},
    {"ASP", kAsp, kPeptide},
    {"CYS", kCys, kPeptide},
    {"GLN", kGln, kPeptide},
    {"GLU", kGlu, kPeptide},
    {"GLY", kGly, kPeptide},
    {"HIS", kHis, kPeptide},
    {"ILE", kIle, kPeptide},
    {"LEU", kLeu, kPeptide},
    {"LYS", kLys, kPeptide},
    {"MET", kMet, kPeptide},
    {"PHE", kPhe, kPeptide},
    {"PRO", kPro, kPeptide},
    {"SER", kSer, kPeptide},
    {"THR", kThr, kPeptide},
    {"TRP", kTrp, kPeptide},
    {"TYR", kTyr, kPeptide},
    {"VAL", kVal, kPeptide},
    {"MSE", kMse, kPeptide},
    {"SEC", kSec, kPeptide},
    {"PYL", kPyl, kPeptide},
    {"ASX", kAsx, kPeptide},
    {"GLX", kGlx, kPeptide},
    {"A", kAdenine, kRibose2, kPhosphateSugar},
    {"C", kCytosine, kRibose2, kPhosphateSugar},
    {"G", kGuanine, kRibose2, kPhosphateSugar},
    {"I", kHypoxanthine, kRibose2, kPhosphateSugar},
    {"U", kUracil, kRibose2, kPhosphateSugar},
    {"T", kThymine, kDeoxyribose2, kPhosphateSugar},  // as FreeSASA: no O2'
    {"DA", kAdenine, kDeoxyribose2, kPhosphateSugar},
    {"DC", kCytosine, kDeoxyribose2, kPhosphateSugar},
    {"DG", kGuanine, kDeoxyribose2, kPhosphateSugar},
    {"DI", kHypoxanthine, kDeoxyribose2, kPhosphateSugar},
    {"DT", kThymine, kDeoxyribose2, kPhosphateSugar},
    {"DU", kUracil, kDeoxyribose2, kPhosphateSugar},
    {"HOH", kWater},
    {"ACE", kAce},
    {"NH2", kNh2},
};

constexpr const TypeRadius* find_type(std::string_view type) {
  for (const TypeRadius& t : kTypes)
    if (t.type == type) return &t;
  return nullptr;
}

// Every type named in the residue table has a radius.
constexpr bool all_types_known() {
  for (const ResidueTypes& r : kResidues)
    for (const Atoms part : r.parts)
      for (const AtomType& a : part)
        if (!find_type(a.type)) return false;
  return true;
}
static_assert(all_types_known());

constexpr std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

const AtomType* find_protor(std::string_view residue, std::string_view atom) {
  for (const ResidueTypes& r : kResidues) {
    if (r.name != residue) continue;
    for (const Atoms part : r.parts)
      for (const AtomType& a : part)
        if (a.atom == atom) return &a;
    return nullptr;
  }
  return nullptr;
}

gemmi::El find_element(std::string_view symbol) {
  symbol = trimmed(symbol);
  if (symbol.empty() || symbol.size() > 2) return gemmi::El::X;
  const char text[3] = {symbol[0], symbol.size() > 1 ? symbol[1] : '\0', '\0'};
  return gemmi::find_element(text);
}

}  // namespace

double element_radius(std::string_view element) {
  const gemmi::El el = find_element(element);
  switch (el) {
    // Mantina et al. 2009 where they differ from gemmi's (Bondi) values.
    case gemmi::El::H:
    case gemmi::El::D:
      return 1.10;
    case gemmi::El::Li:
      return 1.81;
    case gemmi::El::Br:
      return 1.83;
    case gemmi::El::X:
      return -1;
    default:
      break;
  }
  // gemmi has no van der Waals radius beyond lawrencium (1.0 stands in).
  if (gemmi::Element(el).atomic_number() > 103) return -1;
  // gemmi stores 2-decimal values as floats: give the nearest double.
  return std::round(gemmi::vdw_radius(el) * 100.0) / 100.0;
}

AtomRadius atom_radius(std::string_view residue_name, std::string_view atom_name, std::string_view element) {
  if (const AtomType* a = find_protor(trimmed(residue_name), trimmed(atom_name)))
    return {find_type(a->type)->radius, RadiusSource::ProtOr, a->type};
  if (const double r = element_radius(element); r > 0) return {r, RadiusSource::Element, {}};
  return {kDefaultRadius, RadiusSource::Default, {}};
}

}  // namespace molecule
