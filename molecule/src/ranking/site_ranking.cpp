// SPDX-License-Identifier: Apache-2.0
#include "molecule/site_ranking.hpp"

#include <algorithm>
#include <vector>

#include "alpha/error.hpp"
#include "molecule/ligandability_model.hpp"
#include "molecule/site_features.hpp"
#include "ranking/buried_surface.hpp"
#include "ranking/site_clusters.hpp"
#include "ranking/site_recentering.hpp"

namespace molecule {

void rank_sites(const Structure& structure, Cavities& cav, SiteRanking ranking, bool place_centers) {
  const LigandabilityModel& model = default_ligandability_model();
  const SiteFeatures features(structure, cav);
  for (std::vector<Cavity>* list : {&cav.pockets, &cav.voids})
    for (Cavity& c : *list) {
      const std::vector<double> f = features(c);
      c.ligandability = model.margin(f);
      c.probability = model.probability(c.ligandability);
      c.rank_score = model.rank_score(f);
    }
  // A void that holds a ligand is a site whatever its probability: the
  // model ranks it, the rule keeps it.
  std::erase_if(cav.sites,
                [&](const Site& s) { return !s.is_void && !(cav.cavity(s).probability >= kMinSiteProbability); });
  if (ranking == SiteRanking::probability) {
    std::stable_sort(cav.sites.begin(), cav.sites.end(), [&](const Site& a, const Site& b) {
      return cav.cavity(a).rank_score > cav.cavity(b).rank_score;
    });
    if (!place_centers) return;
    cluster_site_centers(cav);
    std::vector<alpha::Vec3> centers;
    for (const Site& s : cav.sites) centers.push_back(s.center);
    center_sites_on_buried_surface(cav, BuriedSurface(structure.atoms, centers, kRecenteringRadius));
  }
}

SiteRanking parse_site_ranking(const std::string& name) {
  if (name == "probability") return SiteRanking::probability;
  if (name == "geometric") return SiteRanking::geometric;
  throw alpha::Error("'" + name + "' is not a ranking (probability or geometric)", alpha::ErrorKind::Misuse);
}

}  // namespace molecule
