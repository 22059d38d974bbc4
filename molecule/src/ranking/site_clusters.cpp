// SPDX-License-Identifier: Apache-2.0
#include "ranking/site_clusters.hpp"

#include <vector>

namespace molecule {

void cluster_site_centers(Cavities& cavities) {
  std::vector<Site>& sites = cavities.sites;
  std::vector<bool> taken(sites.size(), false);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Cavity& head = cavities.cavity(sites[i]);
    sites[i].center = head.center;
    if (taken[i]) continue;
    alpha::Vec3 sum = head.probability * head.center;
    double weight = head.probability;
    bool joined = false;
    for (std::size_t j = i + 1; j < sites.size(); ++j) {
      const Cavity& c = cavities.cavity(sites[j]);
      if (taken[j] || norm(c.center - head.center) > kSiteClusterRadius ||
          !(c.probability >= kSiteClusterShare * head.probability))
        continue;
      taken[j] = joined = true;
      sum = sum + c.probability * c.center;
      weight += c.probability;
    }
    if (joined) sites[i].center = (1 / weight) * sum;
  }
}

}  // namespace molecule
