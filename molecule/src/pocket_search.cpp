// SPDX-License-Identifier: Apache-2.0
#include "molecule/pocket_search.hpp"

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

#include "alpha/error.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/buried_surface.hpp"
#include "molecule/ligandability_model.hpp"
#include "molecule/site_clusters.hpp"
#include "molecule/site_features.hpp"
#include "molecule/site_recentering.hpp"

namespace molecule {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PocketSearch search_pockets(const Structure& structure, const CavityOptions& options, SiteRanking ranking) {
  PocketSearch out;
  const auto start = std::chrono::steady_clock::now();
  AtomBalls balls = atom_balls(structure.atoms, options.probe);
  std::vector<double> radii;
  radii.reserve(structure.atoms.size());
  for (const Atom& a : structure.atoms) radii.push_back(a.radius);
  out.triangulation = std::make_unique<alpha::Triangulation>(std::move(balls.points), std::move(balls.weights));
  out.complex = std::make_unique<alpha::AlphaComplex>(*out.triangulation);
  out.complex_seconds = seconds_since(start);

  const auto cavities_start = std::chrono::steady_clock::now();
  out.cavities = find_cavities(*out.complex, radii, options);
  out.cavities_seconds = seconds_since(cavities_start);
  const auto ranking_start = std::chrono::steady_clock::now();
  Cavities& cav = out.cavities;
  const LigandabilityModel& model = default_ligandability_model();
  const SiteFeatures features(structure, cav);
  for (std::vector<Cavity>* list : {&cav.pockets, &cav.voids})
    for (Cavity& c : *list) {
      c.ligandability = model.margin(features(c));
      c.probability = model.probability(c.ligandability);
    }
  std::erase_if(cav.sites, [&](const Site& s) { return !(cav.cavity(s).probability >= kMinSiteProbability); });
  if (ranking == SiteRanking::probability) {
    std::stable_sort(cav.sites.begin(), cav.sites.end(), [&](const Site& a, const Site& b) {
      return cav.cavity(a).ligandability > cav.cavity(b).ligandability;
    });
    cluster_site_centers(cav);
    std::vector<alpha::Vec3> centers;
    for (const Site& s : cav.sites) centers.push_back(s.center);
    center_sites_on_buried_surface(cav, BuriedSurface(structure.atoms, centers, kRecenteringRadius));
  }
  out.ranking_seconds = seconds_since(ranking_start);
  return out;
}

SiteRanking parse_site_ranking(const std::string& name) {
  if (name == "probability") return SiteRanking::probability;
  if (name == "geometric") return SiteRanking::geometric;
  throw alpha::Error("'" + name + "' is not a ranking (probability or geometric)", alpha::ErrorKind::Misuse);
}

}  // namespace molecule
