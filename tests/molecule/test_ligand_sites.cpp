// SPDX-License-Identifier: Apache-2.0
// Where hetero groups lie among the binding sites (molecule/ligand_sites.hpp)
// against brute force: every heavy atom against every cell of every site,
// inside by barycentric coordinates, outside by the distance to each face
// computed from its plane and edges; no pruning.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "molecule/ligand_sites.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/structure.hpp"
#include "mesh_checks.hpp"

namespace {

using alpha::Vec3;

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double t = std::clamp(dot(p - a, b - a) / dot(b - a, b - a), 0.0, 1.0);
  return norm(p - (a + t * (b - a)));
}

// The foot of p on the plane when it falls inside the triangle, else the nearest edge.
double face_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const Vec3 foot = p - (dot(p - a, n) / dot(n, n)) * n;
  const double ab = dot(cross(b - a, foot - a), n), bc = dot(cross(c - b, foot - b), n),
               ca = dot(cross(a - c, foot - c), n);
  double d = std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
  if ((ab >= 0 && bc >= 0 && ca >= 0) || (ab <= 0 && bc <= 0 && ca <= 0)) d = std::min(d, norm(p - foot));
  return d;
}

double det3(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

double cell_distance(const Vec3& p, const alpha::Triangulation& t, alpha::Index cell) {
  Vec3 v[4];
  for (int k = 0; k < 4; ++k) v[k] = t.point(t.cell(cell).v[k]);
  // Barycentric coordinates by Cramer's rule.
  const double d = det3(v[1] - v[0], v[2] - v[0], v[3] - v[0]);
  if (d != 0) {
    const double l1 = det3(p - v[0], v[2] - v[0], v[3] - v[0]) / d, l2 = det3(v[1] - v[0], p - v[0], v[3] - v[0]) / d,
                 l3 = det3(v[1] - v[0], v[2] - v[0], p - v[0]) / d;
    if (l1 >= 0 && l2 >= 0 && l3 >= 0 && l1 + l2 + l3 <= 1) return 0;
  }
  return std::min({face_distance(p, v[1], v[2], v[3]), face_distance(p, v[0], v[2], v[3]),
                   face_distance(p, v[0], v[1], v[3]), face_distance(p, v[0], v[1], v[2])});
}

void check_against_brute_force(const std::string& file, const molecule::StructureOptions& options,
                               std::size_t dropped_groups) {
  const molecule::Structure s = molecule::read_structure(file, options);
  const molecule::PocketSearch search = molecule::search_pockets(s, {});
  const molecule::Cavities& cav = search.cavities;
  const std::vector<molecule::LigandSite> found = molecule::ligand_sites(s, search);
  REQUIRE(found.size() == s.hetero_groups.size());
  std::size_t dropped = 0;
  for (std::size_t g = 0; g < found.size(); ++g) {
    const molecule::HeteroGroup& group = s.hetero_groups[g];
    INFO(file << ": " << group.residue_name << " " << group.chain << ":" << group.seq_num);
    CHECK(found[g].group == g);
    if (group.kept) continue;
    ++dropped;
    // Brute force: distance and atoms inside per site; the nearest (ties:
    // the best rank).
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_site = 0, best_inside = 0;
    std::vector<std::pair<std::size_t, std::size_t>> holding;
    for (std::size_t k = 0; k < cav.sites.size(); ++k) {
      double distance = std::numeric_limits<double>::infinity();
      std::size_t inside = 0;
      for (const molecule::Atom& a : group.atoms) {
        double d = std::numeric_limits<double>::infinity();
        for (const alpha::Index c : cav.cavity(cav.sites[k]).cells)
          d = std::min(d, cell_distance(a.position, search.shape->triangulation(), c));
        distance = std::min(distance, d);
        inside += d == 0;
      }
      if (inside > 0) holding.emplace_back(k + 1, inside);
      if (distance < best - 1e-9) {
        best = distance;
        best_site = k + 1;
        best_inside = inside;
      }
    }
    CHECK(found[g].nearest_site == best_site);
    CHECK(found[g].distance == Approx(best).margin(1e-6));
    CHECK(found[g].atoms_in_site == best_inside);
    CHECK(found[g].holding == holding);
    CHECK(found[g].site == (best <= molecule::kLigandSiteDistance ? best_site : 0));
  }
  CHECK(dropped == dropped_groups);
}

}  // namespace

TEST_CASE("ligand sites: the nearest site's space, as brute force finds it", "[ligand_sites]") {
  // 1A26: the inhibitor CNA in its site.
  check_against_brute_force(std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb", {}, 1);
  // 1FBL: an inhibitor, two zinc and four calcium ions, some far from any site.
  check_against_brute_force(std::string(ALPHAPOCKET_TEST_DATA) + "/1fbl.pdb", {}, 7);
  // 3STD: the inhibitor MQ0, whose site is a void once it is left out.
  check_against_brute_force(std::string(ALPHAPOCKET_TEST_DATA) + "/3stdA.pdb", {}, 1);
}

TEST_CASE("ligand sites: kept groups line their site", "[ligand_sites]") {
  molecule::StructureOptions options;
  options.keep_cofactors = true;  // 1FBL's zinc and calcium ions
  const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/1fbl.pdb", options);
  REQUIRE(s.hetero_groups.size() == 7);
  const molecule::PocketSearch search = molecule::search_pockets(s, {});
  const std::vector<molecule::LigandSite> found = molecule::ligand_sites(s, search);
  std::size_t kept = 0, lining = 0;
  for (std::size_t g = 0; g < found.size(); ++g) {
    const molecule::HeteroGroup& group = s.hetero_groups[g];
    INFO(group.residue_name << " " << group.seq_num);
    CHECK(group.kept == (group.residue_name == "ZN" || group.residue_name == "CA"));
    if (!group.kept) continue;
    ++kept;
    // Its site: the first by rank among whose lining atoms one of its atoms is.
    std::size_t expected = 0, atoms = 0;
    for (std::size_t k = 0; k < search.cavities.sites.size() && !expected; ++k)
      for (const alpha::Index i : search.cavities.cavity(search.cavities.sites[k]).lining_atoms) {
        const molecule::Atom& a = s.atoms[i];
        if (a.chain == group.chain && a.seq_num == group.seq_num && a.residue_name == group.residue_name) {
          expected = k + 1;
          ++atoms;
        }
      }
    CHECK(found[g].site == expected);
    CHECK(found[g].atoms_in_site == atoms);
    lining += expected > 0;
  }
  CHECK(kept == 6);
  CHECK(lining >= 1);  // the catalytic zinc lines the inhibitor's site
}

namespace {

// A closed shell of carbon atoms (residues GLY, one atom each) on a sphere of
// radius R about the origin, 1.2-1.4 A apart (no probe passes), around a
// benzene ring (BNZ, radius 1.4 A) at the centre when `benzene`: T4
// lysozyme L99A's cavity in miniature (181L is not among the data).
std::string shell_with_benzene(const std::filesystem::path& file, double radius, bool benzene) {
  std::ofstream out(file);
  const double pi = std::acos(-1.0), golden = pi * (3 - std::sqrt(5.0));
  const int n = int(std::ceil(4 * pi * radius * radius / (1.3 * 1.3)));
  char line[100];
  for (int i = 0; i < n; ++i) {  // a Fibonacci sphere: points evenly spread
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), phi = golden * i;
    std::snprintf(line, sizeof line, "ATOM  %5d  CA  GLY A%4d    %8.3f%8.3f%8.3f  1.00 20.00           C\n", i + 1,
                  i + 1, radius * r * std::cos(phi), radius * r * std::sin(phi), radius * z);
    out << line;
  }
  if (benzene)
    for (int k = 0; k < 6; ++k) {
      std::snprintf(line, sizeof line, "HETATM%5d  C%d  BNZ B 400    %8.3f%8.3f%8.3f  1.00 20.00           C\n",
                    n + k + 1, k + 1, 1.4 * std::cos(k * pi / 3), 1.4 * std::sin(k * pi / 3), 0.0);
      out << line;
    }
  out << "END\n";
  return file.string();
}

}  // namespace

TEST_CASE("ligand sites: a void that holds a small ligand is a site and holds it", "[ligand_sites]") {
  testing::TempDir dir;
  // R = 5.4 A: some 200 A^3 of MS volume (T4L L99A's benzene cavity: 209)
  // but far less free space than a drug-sized site (kLigandSiteVolume).
  const molecule::Structure s = molecule::read_structure(shell_with_benzene(dir / "shell.pdb", 5.4, true));
  REQUIRE(s.hetero_groups.size() == 1);
  const molecule::PocketSearch search = molecule::search_pockets(s, {});
  const molecule::Cavities& cav = search.cavities;
  REQUIRE(cav.voids.size() == 1);
  const molecule::Cavity& v = cav.voids.front();
  CHECK(v.sa_volume < molecule::kLigandSiteVolume);
  CHECK(v.ms_volume >= molecule::kLigandVoidVolume);
  CHECK(molecule::holds_ligand(v));
  std::size_t rank = 0;
  for (std::size_t k = 0; k < cav.sites.size(); ++k)
    if (cav.sites[k].is_void) rank = k + 1;
  REQUIRE(rank > 0);  // a site whatever its probability
  // The ligands summary places the benzene in it, all six atoms inside.
  const std::vector<molecule::LigandSite> found = molecule::ligand_sites(s, search);
  REQUIRE(found.size() == 1);
  CHECK(found[0].site == rank);
  CHECK(found[0].atoms_in_site == 6);

  // The geometric ranking keeps it too; a shell too small for a ligand
  // (R = 4.4 A: under 100 A^3 of MS volume) makes a void that is no site.
  const molecule::PocketSearch geometric = molecule::search_pockets(s, {}, molecule::SiteRanking::geometric);
  CHECK(std::any_of(geometric.cavities.sites.begin(), geometric.cavities.sites.end(),
                    [](const molecule::Site& site) { return site.is_void; }));
  const molecule::Structure small = molecule::read_structure(shell_with_benzene(dir / "small.pdb", 4.4, false));
  const molecule::PocketSearch none = molecule::search_pockets(small, {});
  REQUIRE(none.cavities.voids.size() == 1);
  CHECK(none.cavities.voids.front().ms_volume < molecule::kLigandVoidVolume);
  CHECK(std::none_of(none.cavities.sites.begin(), none.cavities.sites.end(),
                     [](const molecule::Site& site) { return site.is_void; }));
}
