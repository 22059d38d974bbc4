// SPDX-License-Identifier: Apache-2.0
// pockets.pml: a PyMOL script that shows the cavities on the structure
// (`pymol OUTDIR/pockets.pml` from any directory, or `@OUTDIR/pockets.pml`
// inside PyMOL; tested with PyMOL 2.5).
//
// It loads structure.cif from its own directory (outputs/structure_copy.hpp:
// the atoms searched and the ligands, one conformer, one model) as the
// object named after the input file, shows it as a grey cartoon under a
// transparent grey surface (buried sites show through it), the ligands as
// sticks with yellow carbons, and for each pocket and void of rank N
//   - the colour ap_pocket_N / ap_void_N: its site rank's (rank_color, the
//     same as the meshes'; never repeated among the shown sites);
//   - the selection pocket_N / void_N: its lining atoms (by atom id);
//   - the object pocket_N_space / void_N_space: its space, spheres at its
//     sinks (pockets.pdb's SNK atoms), in its colour; pocket_N_center its
//     centre; grouped as "spaces" and "centers";
//   - for the first kShownSites sites, their lining residues as sticks
//     with carbons in the site's colour (the better site's where they
//     share residues); the other cavities' objects are disabled;
// the tunnels' bottlenecks (selections tunnel_N, cyan spheres
// tunnel_N_bottleneck), the tunnels and pores with a path (tunnel_N: the
// lining residues' atoms; tunnel_N_path: a chain of spheres, one per
// profile point, of its radius, in tunnel_color), all in the group
// "tunnels", and orients the view on the best site.
//
// The script holds only our own names and numbers: no text of the input
// (file, chain, residue or atom names) can reach PyMOL's command parser.
#pragma once
#include <string>

#include "molecule/pocket_run.hpp"
#include "outputs/viewer_scene.hpp"

namespace molecule {

std::string pymol_script(const PocketRun& run, const ViewerScene& scene);

}  // namespace molecule
