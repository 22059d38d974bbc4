// SPDX-License-Identifier: Apache-2.0
// Residues as the outputs name them: an atom's residue id and the residues
// a set of atoms (a cavity's lining, a tunnel's wall) belongs to.
#pragma once
#include <string>
#include <vector>

#include "molecule/structure.hpp"

namespace molecule {

// "A:TYR:42", with the insertion code appended ("A:TYR:42B"): the residue
// of an atom as pockets.csv and report.json name it.
std::string residue_id(const Atom& atom);

// The residues of the given atoms (indices into atoms, any order), each
// once, in order of their first atom in the file: one representative atom
// index per residue.
std::vector<alpha::Index> residues_of(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& indices);

}  // namespace molecule
