// pockets.pml: a PyMOL script that shows the cavities on the structure
// (`pymol OUTDIR/pockets.pml`, or `@OUTDIR/pockets.pml` inside PyMOL).
//
// It loads the structure file (by the path given: absolute, so the script
// works from any directory; of a file with several models it keeps the
// model searched), shows it as a grey cartoon under a light surface, and
// for each pocket and void of rank N
//   - the selection pocket_N / void_N: its lining atoms (by chain, residue
//     number and insertion code, and atom name), shown as sticks;
//   - the colour ap_pocket_N / ap_void_N (molecule::rank_color, the same as
//     the meshes), given to those atoms, so the surface is coloured there
//     (where pockets share atoms, the better rank's colour wins);
//   - the pseudo-atom object pocket_N_center / void_N_center at its centre,
//     shown as a sphere; all of them are grouped as "centers".
#pragma once
#include <string>

#include "molecule/pocket_report.hpp"

namespace molecule {

// structure_path is written into the script as given (make it absolute).
std::string pymol_script(const PocketRun& run, const std::string& structure_path);

}  // namespace molecule
