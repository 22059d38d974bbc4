// SPDX-License-Identifier: Apache-2.0
// A GROMACS .gro file as PDB text, for the structure reader: ATOM records
// in the file's order (coordinates nm -> A, chain A, the element from the
// atom name), so that a .gro file can be a trajectory's topology.
#pragma once
#include <string>
#include <string_view>

namespace molecule {

bool is_gro_file(const std::string& path);

// Throws StructureError naming `name` and the line for a malformed file.
std::string gro_as_pdb(std::string_view gro, const std::string& name);

}  // namespace molecule
