// SPDX-License-Identifier: Apache-2.0
// Where `alphapocket pockets --tunnels-from SPEC` starts tunnels. SPEC is
//   auto       the deepest point of each of the top 3 sites (the default)
//   none       no tunnels
//   N          the deepest point of site N (1 = the best)
//   A:45,A:67  the centre of these residues' atoms (chain:number, an
//              insertion code appended: A:45B)
//   x,y,z      a point, A
// (a site's deepest point: its empty tetrahedron farthest from the bulk
// solvent along ways the tunnel probe passes; a point: the nearest node of
// the void graph the probe fits in; see molecule/tunnel_paths.hpp).
#pragma once
#include <string>
#include <vector>

#include "molecule/cavities.hpp"
#include "molecule/structure.hpp"
#include "molecule/tunnel_paths.hpp"

namespace molecule {

inline constexpr std::size_t kAutoTunnelSites = 3;

// Throws alpha::Error with one line for a SPEC that is none of the above,
// a site or residue that does not exist.
std::vector<TunnelStart> tunnel_starts(const std::string& spec, const Structure& structure, const Cavities& cavities);

}  // namespace molecule
