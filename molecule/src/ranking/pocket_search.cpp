// SPDX-License-Identifier: Apache-2.0
#include "molecule/pocket_search.hpp"

#include <chrono>
#include <utility>
#include <vector>

#include "molecule/atom_balls.hpp"

namespace molecule {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PocketSearch search_pockets(const Structure& structure, const CavityOptions& options, SiteRanking ranking,
                            bool keep_bodies) {
  PocketSearch out;
  const auto start = std::chrono::steady_clock::now();
  AtomBalls balls = atom_balls(structure.atoms, options.probe);
  std::vector<double> radii;
  radii.reserve(structure.atoms.size());
  for (const Atom& a : structure.atoms) radii.push_back(a.radius);
  out.shape.emplace(std::move(balls.points), std::move(balls.weights));
  out.complex_seconds = seconds_since(start);

  const auto cavities_start = std::chrono::steady_clock::now();
  out.cavities = find_cavities(out.shape->complex(), radii, options, keep_bodies ? &out.bodies : nullptr);
  out.cavities_seconds = seconds_since(cavities_start);
  const auto ranking_start = std::chrono::steady_clock::now();
  rank_sites(structure, out.cavities, ranking, options.site_centers);
  out.ranking_seconds = seconds_since(ranking_start);
  return out;
}

}  // namespace molecule
