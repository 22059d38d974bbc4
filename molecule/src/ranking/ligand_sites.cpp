// SPDX-License-Identifier: Apache-2.0
#include "molecule/ligand_sites.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "cavities/cavity_space.hpp"

namespace molecule {
namespace {

using alpha::Vec3;

struct Tetrahedron {
  std::array<Vec3, 4> v;
  Vec3 center;          // of its bounding sphere (the centroid)
  double radius = 0;    // of its bounding sphere
};

// A site's space, with a box around it to skip far sites at once.
struct SiteSpace {
  std::vector<Tetrahedron> cells;
  Vec3 lo{}, hi{};
};

SiteSpace site_space(const alpha::Triangulation& t, const Cavity& c) {
  SiteSpace s;
  constexpr double inf = std::numeric_limits<double>::infinity();
  s.lo = {inf, inf, inf};
  s.hi = {-inf, -inf, -inf};
  for (const alpha::Index id : c.cells) {
    Tetrahedron tet;
    for (int k = 0; k < 4; ++k) tet.v[k] = t.point(t.cell(id).v[k]);
    tet.center = 0.25 * (tet.v[0] + tet.v[1] + tet.v[2] + tet.v[3]);
    for (const Vec3& p : tet.v) {
      tet.radius = std::max(tet.radius, norm(p - tet.center));
      s.lo = {std::min(s.lo.x, p.x), std::min(s.lo.y, p.y), std::min(s.lo.z, p.z)};
      s.hi = {std::max(s.hi.x, p.x), std::max(s.hi.y, p.y), std::max(s.hi.z, p.z)};
    }
    s.cells.push_back(tet);
  }
  return s;
}

double box_distance(const Vec3& p, const SiteSpace& s) {
  const auto gap = [](double x, double lo, double hi) { return std::max({lo - x, 0.0, x - hi}); };
  const Vec3 d{gap(p.x, s.lo.x, s.hi.x), gap(p.y, s.lo.y, s.hi.y), gap(p.z, s.lo.z, s.hi.z)};
  return norm(d);
}

// 0 inside the tetrahedron (or on it), else the distance to its nearest face.
double tetrahedron_distance(const Vec3& p, const Tetrahedron& t) {
  // A flat tetrahedron (zero volume) holds nothing: only its faces count.
  bool inside = tetrahedron_volume(t.v[0], t.v[1], t.v[2], t.v[3]) != 0;
  for (int k = 0; k < 4 && inside; ++k) {
    const auto& f = alpha::kFacet[k];  // sees vertex k on its positive side
    const Vec3 &a = t.v[f[0]], &b = t.v[f[1]], &c = t.v[f[2]];
    inside = dot(cross(b - a, c - a), p - a) * dot(cross(b - a, c - a), t.v[k] - a) >= 0;
  }
  if (inside) return 0;
  double d = std::numeric_limits<double>::infinity();
  for (const auto& f : alpha::kFacet) d = std::min(d, point_triangle_distance(p, t.v[f[0]], t.v[f[1]], t.v[f[2]]));
  return d;
}

// Distance of p to the space, no farther than `bound` looked for (returns
// a value > bound when the space is farther).
double space_distance(const Vec3& p, const SiteSpace& s, double bound) {
  if (box_distance(p, s) > bound) return std::numeric_limits<double>::infinity();
  double best = std::numeric_limits<double>::infinity();
  for (const Tetrahedron& t : s.cells) {
    if (norm(p - t.center) - t.radius > std::min(best, bound)) continue;
    best = std::min(best, tetrahedron_distance(p, t));
    if (best == 0) break;
  }
  return best;
}

bool same_residue(const Atom& a, const HeteroGroup& g) {
  return a.chain == g.chain && a.seq_num == g.seq_num && a.icode == g.icode && a.residue_name == g.residue_name;
}

LigandSite kept_group_site(const Structure& structure, const Cavities& cavities, std::size_t group) {
  const HeteroGroup& g = structure.hetero_groups[group];
  LigandSite out;
  out.group = group;
  for (std::size_t rank = 1; rank <= cavities.sites.size(); ++rank) {
    const Cavity& c = cavities.cavity(cavities.sites[rank - 1]);
    const std::size_t n = std::size_t(std::count_if(c.lining_atoms.begin(), c.lining_atoms.end(), [&](alpha::Index i) {
      return same_residue(structure.atoms[i], g);
    }));
    if (n > 0) {
      out.site = rank;
      out.atoms_in_site = n;
      break;
    }
  }
  return out;
}

}  // namespace

std::vector<LigandSite> ligand_sites(const Structure& structure, const PocketSearch& search) {
  const Cavities& cavities = search.cavities;
  std::vector<SiteSpace> spaces;  // made on first need: most structures have few groups
  std::vector<LigandSite> out;
  for (std::size_t group = 0; group < structure.hetero_groups.size(); ++group) {
    const HeteroGroup& g = structure.hetero_groups[group];
    if (g.kept) {
      out.push_back(kept_group_site(structure, cavities, group));
      continue;
    }
    if (spaces.empty())
      for (const Site& s : cavities.sites)
        spaces.push_back(site_space(search.shape->triangulation(), cavities.cavity(s)));
    LigandSite best;
    best.group = group;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < spaces.size(); ++k) {
      double distance = std::numeric_limits<double>::infinity();
      std::size_t inside = 0;
      for (const Atom& a : g.atoms) {
        const double d = space_distance(a.position, spaces[k], std::max(best.distance, 0.0));
        distance = std::min(distance, d);
        inside += d == 0;
      }
      if (inside > 0) best.holding.emplace_back(k + 1, inside);
      // Nearer; ties: the better rank, seen first.
      if (distance < best.distance) {
        best.nearest_site = k + 1;
        best.distance = distance;
        best.atoms_in_site = inside;
      }
    }
    if (best.nearest_site == 0) best.distance = 0;
    if (best.nearest_site > 0 && best.distance <= kLigandSiteDistance) best.site = best.nearest_site;
    out.push_back(best);
  }
  return out;
}

}  // namespace molecule
