// SPDX-License-Identifier: Apache-2.0
#include "ranking/site_recentering.hpp"

namespace molecule {

void center_sites_on_buried_surface(Cavities& cavities, const BuriedSurface& surface) {
  for (Site& s : cavities.sites) {
    alpha::Vec3 sum{};
    double n = 0;
    surface.visit_buried(s.center, kRecenteringRadius, [&](const alpha::Vec3& p) { sum = sum + p, n += 1; });
    if (n > 0) s.center = (1 / n) * sum;
  }
}

}  // namespace molecule
