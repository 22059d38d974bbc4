// SPDX-License-Identifier: Apache-2.0
// Atomic radii: the ProtOr united-atom radii of
//
//   J. Tsai, R. Taylor, C. Chothia, M. Gerstein, "The packing density in
//   proteins: standard radii and volumes", J. Mol. Biol. 290:253-266 (1999)
//
// by residue and atom name, as FreeSASA assigns them by default (its
// "protor" classifier), so that areas computed here can be compared with
// `freesasa` output atom for atom. United-atom radii include the hydrogens
// bonded to the atom: hydrogens are meant to be left out (keeping them adds
// their own balls on top).
//
// Each atom of a known residue has a ProtOr type (e.g. C3H1: a carbon with
// three bonded heavy atoms and one hydrogen), and each type one radius:
//
//   C3H0 1.61   C3H1 1.76   C4H1, C4H2, C4H3 1.88
//   N3H0, N3H1, N3H2, N4H3 1.64     O1H0 1.42   O2H1 1.46   S2H0, S2H1 1.77
//
// and, beyond the paper, the types FreeSASA adds: P4H0 1.80 (phosphate P),
// O2H0 and O2H2 1.46 (ester O, water), N2H0 and N2H2 1.64, SE2H0 and
// SE2H1 1.90 (selenomethionine, selenocysteine), X1H0 1.50 (the ambiguous
// O/N atoms of ASX and GLX).
//
// Known residues: the 20 amino acids, MSE, SEC, PYL, ASX, GLX; the
// nucleotides A C G I U T and DA DC DG DI DT DU; HOH; the caps ACE and NH2.
// The peptide backbone (N CA C O OXT) is known for the amino acids, the
// sugar-phosphate backbone (OP1 OP2 OP3 P O5' C5' C4' O4' C3' O3' C2' O2'
// C1') for the nucleotides.
//
// Any other atom (ligands, modified residues, unusual atom names) gets the
// van der Waals radius of its element, the values FreeSASA guesses:
// Mantina et al., J. Phys. Chem. A 113:5806 (2009) for the main group
// (H 1.10, C 1.70, N 1.55, O 1.52, P 1.80, S 1.80, Se 1.90, ...) and Bondi
// (1964) or later tabulations (as in gemmi's table) for the other elements
// (Zn 1.39, Fe 1.26, ...). Deuterium gets the radius of hydrogen. An element
// that is not recognised gets kDefaultRadius.
#pragma once
#include <string_view>

namespace molecule {

// The name of this radius table, for logs and reports.
inline constexpr std::string_view kRadiusTable = "ProtOr";

// The radius given to an atom whose element is not recognised, in Angstrom.
inline constexpr double kDefaultRadius = 1.80;

enum class RadiusSource {
  ProtOr,   // from the residue and atom name
  Element,  // the van der Waals radius of the element
  Default,  // unknown element: kDefaultRadius
};

struct AtomRadius {
  double value = kDefaultRadius;  // Angstrom
  RadiusSource source = RadiusSource::Default;
  std::string_view type;  // the ProtOr type ("C3H1"), empty unless source is ProtOr
};

// The radius of an atom. Names are matched exactly as written in structure
// files (upper case: "ALA", "CB", "O5'"), surrounding blanks ignored; the
// element symbol is case-insensitive ("SE", "Se").
AtomRadius atom_radius(std::string_view residue_name, std::string_view atom_name, std::string_view element);

inline double radius(std::string_view residue_name, std::string_view atom_name, std::string_view element) {
  return atom_radius(residue_name, atom_name, element).value;
}

// The van der Waals radius of an element (case-insensitive symbol), or a
// negative value when the symbol is not an element.
double element_radius(std::string_view element);

}  // namespace molecule
