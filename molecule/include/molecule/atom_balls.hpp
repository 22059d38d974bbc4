// SPDX-License-Identifier: Apache-2.0
// The atoms as the weighted points every search is built on: atom i is the
// ball of radius r_i + probe (r_i its van der Waals radius), i.e. the
// weighted point (x_i, (r_i + probe)^2); alpha_sq = 0 is then the
// solvent-accessible model.
#pragma once
#include <vector>

#include "alpha/geometry.hpp"
#include "molecule/structure.hpp"

namespace molecule {

// The weight of a ball of radius `radius` grown by the probe.
inline double ball_weight(double radius, double probe) { return (radius + probe) * (radius + probe); }

struct AtomBalls {
  std::vector<alpha::Vec3> points;
  std::vector<double> weights;  // ball_weight(radius, probe) per atom
};

AtomBalls atom_balls(const std::vector<Atom>& atoms, double probe);

}  // namespace molecule
