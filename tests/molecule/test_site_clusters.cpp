// SPDX-License-Identifier: Apache-2.0
// Site clusters (ranking/site_clusters.hpp): hand-made rankings whose
// clusters and centres are known, and on a real structure: every site's
// centre is a convex combination of the cavity centres within the radius.
#include <catch2/catch.hpp>

#include <vector>

#include "molecule/pocket_search.hpp"
#include "ranking/site_clusters.hpp"
#include "ranking/site_recentering.hpp"
#include "molecule/structure.hpp"

namespace {

using alpha::Vec3;

molecule::Cavities ranked(const std::vector<std::pair<Vec3, double>>& centre_probability) {
  molecule::Cavities c;
  for (const auto& [x, p] : centre_probability) {
    molecule::Cavity cav;
    cav.center = x;
    cav.probability = p;
    c.sites.push_back({false, c.pockets.size(), {}});
    c.pockets.push_back(cav);
  }
  return c;
}

}  // namespace

TEST_CASE("site clusters: the head takes the near, likely, lower-ranked sites once", "[site_clusters]") {
  // 0 heads 1 (6 A, 0.625 of its probability) and 3 (10 A exactly); 2 is
  // too unlikely (0.59 of 0.8 < 0.6) and heads 4 (8 A from it, 12 A from
  // 0); 5 is too far from everyone (> 10 A).
  molecule::Cavities c = ranked({{{0, 0, 0}, 0.8},
                                 {{6, 0, 0}, 0.5},
                                 {{0, 4, 0}, 0.472},
                                 {{0, 0, 10}, 0.5},
                                 {{0, 12, 0}, 0.3},
                                 {{30, 0, 0}, 0.29}});
  molecule::cluster_site_centers(c);
  const double w0 = 0.8 + 0.5 + 0.5;
  CHECK(c.sites[0].center.x == Approx(0.5 * 6 / w0));
  CHECK(c.sites[0].center.y == 0);
  CHECK(c.sites[0].center.z == Approx(0.5 * 10 / w0));
  CHECK(c.sites[1].center.x == 6);  // taken: its own centre
  CHECK(c.sites[2].center.y == Approx((0.472 * 4 + 0.3 * 12) / (0.472 + 0.3)));
  CHECK(c.sites[2].center.x == 0);
  CHECK(c.sites[3].center.z == 10);
  CHECK(c.sites[4].center.y == 12);  // taken by 2
  CHECK(c.sites[5].center.x == 30);  // alone: exactly its own centre
}

TEST_CASE("site clusters: a lower-ranked site never joins a better one's cluster, a taken site heads none",
          "[site_clusters]") {
  // 1 is within reach of 0 but only 0.5 < 0.6 of 0.9: not taken; it then
  // heads 2 (0.35 >= 0.6 * 0.5), which 0 could not take (0.35 < 0.54).
  molecule::Cavities c = ranked({{{0, 0, 0}, 0.9}, {{5, 0, 0}, 0.5}, {{9, 0, 0}, 0.35}});
  molecule::cluster_site_centers(c);
  CHECK(c.sites[0].center.x == 0);
  CHECK(c.sites[1].center.x == Approx((0.5 * 5 + 0.35 * 9) / 0.85));
  CHECK(c.sites[2].center.x == 9);
}

TEST_CASE("site clusters: search_pockets' site centres lie among their cavities' neighbours", "[site_clusters]") {
  const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb");
  const molecule::PocketSearch by_model = molecule::search_pockets(s, {});
  const molecule::PocketSearch by_score = molecule::search_pockets(s, {}, molecule::SiteRanking::geometric);
  const molecule::Cavities& model = by_model.cavities;
  const molecule::Cavities& geometric = by_score.cavities;
  for (const molecule::Site& site : geometric.sites) {
    const Vec3& own = geometric.cavity(site).center;
    CHECK((site.center.x == own.x && site.center.y == own.y && site.center.z == own.z));
  }
  bool moved = false;
  for (const molecule::Site& site : model.sites) {
    const Vec3& own = model.cavity(site).center;
    // A probability-weighted mean of centres within the radius of its own,
    // then moved onto the buried surface within its radius
    // (test_site_recentering.cpp).
    CHECK(norm(site.center - own) <= molecule::kSiteClusterRadius + molecule::kRecenteringRadius);
    moved |= norm(site.center - own) > 0;
  }
  CHECK(moved);  // some site of 1a26A heads a cluster
}
