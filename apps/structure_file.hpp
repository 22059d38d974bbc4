// Minimal reading of macromolecular structure files (PDB, mmCIF, optionally
// gzipped) through gemmi: the coordinates of all atoms of the first model.
// A proper molecule layer (radii per element, hydrogens, waters, altlocs)
// comes later; this is only enough to triangulate real structures.
#pragma once
#include <string>
#include <vector>

#include "alpha/geometry.hpp"

namespace alphapocket {

// Whether the file name looks like a structure file: .pdb .ent .cif .mmcif,
// each optionally followed by .gz (case-insensitive).
bool is_structure_file(const std::string& path);

// Atom positions of the first model; throws std::runtime_error with one line
// naming the file when it cannot be read or holds no atoms.
std::vector<alpha::Vec3> read_structure_atoms(const std::string& path);

}  // namespace alphapocket
