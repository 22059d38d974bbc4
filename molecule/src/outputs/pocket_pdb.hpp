// SPDX-License-Identifier: Apache-2.0
// pockets.pdb: the cavities as pseudo-atoms in PDB format, fpocket-style,
// for ChimeraX, PyMOL, VMD or any other structure viewer (open it together
// with the structure: the coordinates are the same).
//
// One residue per cavity, residue name STP, residue number = its rank,
// chain P for pockets and V for voids; its HETATM records are
//   CEN  the cavity's centre (Cavity::center), B-factor 0;
//   SNK  one per sink of the cavity's flow (an empty tetrahedron that
//        drains nowhere, see alpha::DiscreteFlow): the orthocentre of the
//        tetrahedron, B-factor = the radius of its orthosphere in A (0 when
//        negative), i.e. how far the cavity widens there beyond the
//        probe-inflated atoms.
// Element column C. REMARK lines at the top say what the file holds; it
// ends with END.
#pragma once
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "molecule/cavities.hpp"
#include "molecule/tunnel_paths.hpp"

namespace molecule {

struct PocketPdb {
  std::string text;
  // Pseudo-atoms the PDB columns cannot hold, left out of text (a REMARK
  // says how many): coordinates outside -999.999 .. 9999.999 (structures
  // from large mmCIF files), more than 99999 pseudo-atoms or 9999 cavities
  // of one kind. report.json has every cavity.
  std::size_t left_out = 0;
};

// A sink of a cavity's flow as pockets.pdb's SNK atom has it: the
// orthocentre of the tetrahedron and its orthosphere's radius (0 when
// negative), A. The viewer scripts draw the same spheres.
struct SinkSphere {
  alpha::Vec3 center;
  double radius = 0;
};
std::vector<SinkSphere> sink_spheres(const alpha::AlphaComplex& ac, const Cavity& cavity);

// The file; `title` goes into the first REMARK (made printable ASCII: a
// newline in a file name cannot start a record).
PocketPdb pocket_pdb(const alpha::AlphaComplex& ac, const Cavities& cavities, const std::string& title);

// tunnels.pdb: one pseudo-atom TUN per profile point of the way through
// each cycle (chain C) and of each tunnel (T) and pore (P) after them
// (residue TUN, residue number = its rank in report.json: the cycles
// 1..cycles.size(), then the paths), B-factor = the radius there (the HOLE
// and CAVER convention, read by ChimeraX, VMD and PyMOL).
PocketPdb tunnel_pdb(const std::vector<TunnelPath>& cycles, const std::vector<TunnelPath>& paths,
                     const std::string& title);

}  // namespace molecule
