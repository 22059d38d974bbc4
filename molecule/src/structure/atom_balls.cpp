// SPDX-License-Identifier: Apache-2.0
#include "molecule/atom_balls.hpp"

namespace molecule {

AtomBalls atom_balls(const std::vector<Atom>& atoms, double probe) {
  AtomBalls b;
  b.points.reserve(atoms.size());
  b.weights.reserve(atoms.size());
  for (const Atom& a : atoms) {
    b.points.push_back(a.position);
    b.weights.push_back(ball_weight(a.radius, probe));
  }
  return b;
}

}  // namespace molecule
