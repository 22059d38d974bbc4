// SPDX-License-Identifier: Apache-2.0
// structure.cif: the atoms a pocket search used, and the hetero groups it
// left out (the ligands), as a minimal mmCIF file inside the output
// directory. The viewer scripts (pockets.pml, pockets.cxc) load it by a
// relative path, so the directory can be moved, zipped and shared, and
// they select atoms by its atom ids, so no name from the input ever
// reaches a script.
//
// Atom i of Structure::atoms has id i + 1; the heavy atoms of the hetero
// groups that were not kept follow. One conformer (the one searched, no
// altloc column), one model. Author chain ids, residue numbers and
// insertion codes as in the input; names that CIF cannot hold as a bare
// word have their whitespace and control characters replaced by '_'.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "molecule/structure.hpp"

namespace molecule {

struct StructureCopy {
  std::string cif;
  // Atom ids of the hetero groups (kept or not), ascending.
  std::vector<std::size_t> ligand_ids;
};

// `title` goes into the leading comment (made printable ASCII).
StructureCopy structure_copy(const Structure& structure, const std::string& title);

}  // namespace molecule
