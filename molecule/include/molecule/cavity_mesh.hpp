// Cavities and the molecule as triangle meshes (for write_mesh_file), with
// vertices at the atom centres: the polyhedral surfaces of the alpha
// complex that a viewer such as MeshLab shows next to the structure.
//
// A cavity's mesh is the boundary of the union of its empty tetrahedra,
// oriented OUTWARD FROM THE CAVITY SPACE (normals point from the cavity
// into the molecule, and out of a pocket through its mouths). It is closed
// and consistently oriented: every edge is run through as often in one
// direction as in the other, so its signed volume is the volume of the
// cavity's tetrahedra. Where two of them meet only at an edge or a vertex
// the surface is not a manifold there (write_mesh_file then writes a point
// once per sheet).
//   - lining triangles (the complex's triangles that wall the cavity in)
//     get the cavity's colour;
//   - mouth triangles (the empty triangles towards the outside, see
//     Cavity::mouths) get a light tint of it, so that a viewer shows the
//     openings; a void has none.
//
// The molecule's mesh is the boundary of its solvent-accessible alpha shape
// (the complex at alpha_sq = 0), oriented outward, in kMoleculeColor.
#pragma once
#include "alpha/alpha_complex.hpp"
#include "molecule/cavities.hpp"
#include "molecule/mesh_export.hpp"

namespace molecule {

// Throws alpha::Error when a cell of the cavity is not a finite cell of the
// complex's triangulation.
TriangleMesh cavity_mesh(const alpha::AlphaComplex& ac, const Cavity& cavity, Rgb color);

TriangleMesh molecule_mesh(const alpha::AlphaComplex& ac);

}  // namespace molecule
