// SPDX-License-Identifier: Apache-2.0
// pockets.cxc: a ChimeraX command script with the content of pockets.pml
// (`chimerax OUTDIR/pockets.cxc`, or `open OUTDIR/pockets.cxc` inside
// ChimeraX, which runs it from the script's own directory).
//
// Model #1 is structure.cif (the atoms searched and the ligands); the
// atom specs name its atoms by serial number (its atom ids), so no text of
// the input reaches ChimeraX's parser. Each pocket or void of rank N gets
// the named spec pocket_N / void_N (lining atoms; the shown sites' as
// sticks with carbons in the site's colour), markers at its sinks (model
// #2.K, K its position in ViewerScene::cavities, named pocket_N_space) and
// at its centre (#3.K, pocket_N_center); the tunnels' bottlenecks are
// cyan markers (#4.K, tunnel_N_bottleneck), each tunnel or pore with a
// path a chain of markers of its radius profile (#5.K, tunnel_N_path, in
// tunnel_color) with its lining residues named tunnel_N, the ligands ("ligands") sticks
// with yellow carbons, the molecule a grey cartoon under a transparent
// grey surface; the view is on the best site. ChimeraX is not in Debian:
// the script is checked by tests/viewer/check_cxc.py, a reader of exactly
// the commands written here.
#pragma once
#include <string>

#include "molecule/pocket_run.hpp"
#include "outputs/viewer_scene.hpp"

namespace molecule {

std::string chimerax_script(const PocketRun& run, const ViewerScene& scene);

}  // namespace molecule
