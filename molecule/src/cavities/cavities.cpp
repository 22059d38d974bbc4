// SPDX-License-Identifier: Apache-2.0
#include "molecule/cavities.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>
#include <optional>
#include <queue>
#include <string>
#include <tuple>
#include <utility>

#include "alpha/discrete_flow.hpp"
#include "alpha/eroded_union.hpp"
#include "alpha/error.hpp"
#include "alpha/nearest_ball.hpp"
#include "alpha/persistent_basins.hpp"
#include "alpha/point_grid.hpp"
#include "molecule/atom_balls.hpp"
#include "cavities/cavity_space.hpp"
#include "cavities/nearest_triangle.hpp"
#include "util/parallel_for.hpp"

namespace molecule {
namespace {

using alpha::Index;
using alpha::Vec3;

void check_input(const alpha::AlphaComplex& ac, const std::vector<double>& radii, const CavityOptions& options) {
  const alpha::Triangulation& t = ac.triangulation();
  if (radii.size() != t.num_points())
    alpha::fail("find_cavities: " + std::to_string(radii.size()) + " radii for " + std::to_string(t.num_points()) +
                " points", alpha::ErrorKind::Misuse);
  if (!(options.probe >= 0) || !std::isfinite(options.probe)) alpha::fail("find_cavities: probe must be >= 0", alpha::ErrorKind::Misuse);
  if (!(options.split_persistence >= 0)) alpha::fail("find_cavities: split_persistence must be >= 0", alpha::ErrorKind::Misuse);
  if (std::isnan(options.split_volume) || std::isnan(options.split_min_volume))
    alpha::fail("find_cavities: split_volume or split_min_volume is not a number", alpha::ErrorKind::Misuse);
  if (!(options.burial_radius >= 0) || !std::isfinite(options.burial_radius))
    alpha::fail("find_cavities: burial_radius must be >= 0", alpha::ErrorKind::Misuse);
  if (std::isnan(options.min_volume)) alpha::fail("find_cavities: min_volume is not a number", alpha::ErrorKind::Misuse);
  for (Index i = 0; i < radii.size(); ++i) {
    const double r = radii[i];
    if (!(r >= 0) || !std::isfinite(r))
      alpha::fail("find_cavities: radius of point " + std::to_string(i) + " is not >= 0", alpha::ErrorKind::Misuse);
    const double w = ball_weight(r, options.probe);
    if (std::fabs(t.weight(i) - w) > 1e-9 * std::max(1.0, w))
      alpha::fail("find_cavities: the complex's weight of point " + std::to_string(i) +
                  " is not (radius + probe)^2", alpha::ErrorKind::Misuse);
  }
}

// An empty triangle between a cavity and the rest of the empty space, and
// whether that side is the outside.
using Opening = std::pair<Index, bool>;

// The openings grouped into mouths: triangles of one kind (to the outside
// or not) joined through shared edges. `openings` sorted.
std::vector<Mouth> group_mouths(const alpha::Simplices& s, const std::vector<Opening>& openings,
                                const CavitySpace& space) {
  std::vector<Index> parent(openings.size());
  std::iota(parent.begin(), parent.end(), Index(0));
  const auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  // (edge, kind, position in openings): the openings of one kind around an
  // edge sort next to each other, whatever other kind shares the edge.
  std::vector<std::tuple<Index, bool, Index>> by_edge;
  for (Index k = 0; k < openings.size(); ++k)
    for (Index e : s.triangle_edges(openings[k].first)) by_edge.emplace_back(e, openings[k].second, k);
  std::sort(by_edge.begin(), by_edge.end());
  for (std::size_t k = 1; k < by_edge.size(); ++k) {
    const auto& [edge_a, kind_a, a] = by_edge[k - 1];
    const auto& [edge_b, kind_b, b] = by_edge[k];
    if (edge_a != edge_b || kind_a != kind_b) continue;
    const Index ra = find(a), rb = find(b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<Mouth> mouths;
  std::vector<Index> mouth_of(openings.size(), alpha::kNone);
  for (Index k = 0; k < openings.size(); ++k) {
    Index& m = mouth_of[find(k)];
    if (m == alpha::kNone) {
      m = Index(mouths.size());
      mouths.emplace_back().to_outside = openings[k].second;
    }
    mouths[m].triangles.push_back(openings[k].first);
    mouths[m].area += space.open_area(openings[k].first);
  }
  std::stable_partition(mouths.begin(), mouths.end(), [](const Mouth& m) { return m.to_outside; });
  return mouths;
}

// A 1-cycle alive at the level, as a tunnel (see Tunnel::bottleneck_radius).
Tunnel make_tunnel(const alpha::AlphaComplex& ac, const alpha::PersistencePair& p, const std::vector<double>& radii,
                   double probe) {
  Tunnel tn;
  tn.birth_alpha_sq = ac.spectrum_value(p.birth);
  tn.death_alpha_sq = ac.spectrum_value(p.death);
  tn.bottleneck_triangle = p.death_simplex;
  const auto& tri = ac.simplices().triangle(p.death_simplex);
  tn.bottleneck_radius = std::numeric_limits<double>::infinity();
  for (Index i : tri) {
    const double grown_sq = ball_weight(radii[i], probe) + tn.death_alpha_sq;
    tn.bottleneck_radius = std::min(tn.bottleneck_radius, std::sqrt(grown_sq) - radii[i]);
  }
  // The triangle is critical, its own size the death: an attached one
  // enters with the tetrahedron it is a free face of, a pair that changes
  // no Betti number, so it creates the void the tetrahedron fills.
  tn.bottleneck_center = ac.size_kernel().center(alpha::Simplex(tri[0], tri[1], tri[2]));
  tn.lining_atoms.assign(tri.begin(), tri.end());
  std::sort(tn.lining_atoms.begin(), tn.lining_atoms.end());
  return tn;
}

// Per cell, the first level (entry rank) from which on it is cut off from
// the outside: no path of cells through absent triangles (entry >= level;
// their cells are absent too) reaches an infinite cell. That is the
// largest, over paths to the outside, of the smallest triangle entry on
// the path: a widest-path search from the infinite cells, largest first.
std::vector<Index> sealed_from(const alpha::AlphaComplex& ac) {
  const alpha::Triangulation& t = ac.triangulation();
  const alpha::Simplices& s = ac.simplices();
  std::vector<Index> sealed(t.num_cells(), 0);
  std::priority_queue<std::pair<Index, Index>> queue;  // (value, cell), largest value first
  for (Index c = 0; c < t.num_cells(); ++c)
    if (t.is_infinite(c)) queue.emplace(sealed[c] = alpha::kNever, c);
  while (!queue.empty()) {
    const auto [value, c] = queue.top();
    queue.pop();
    if (value != sealed[c]) continue;  // superseded
    const int inf = t.infinite_position(c);
    for (int k = 0; k < 4; ++k) {
      const Index n = t.cell(c).n[k];
      if (t.is_infinite(n) || (inf >= 0 && k != inf)) continue;  // outside already; not a finite triangle
      const Index through = std::min(value, ac.triangle_interval(s.cell_triangle(c, k)).entry);
      if (through > sealed[n]) queue.emplace(sealed[n] = through, n);
    }
  }
  return sealed;
}

// The tasks' positions by decreasing size (ties in order): the order in
// which the threads take them, the longest first.
std::vector<std::size_t> largest_first(const std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
  return order;
}

// Everything find_cavities shares between the cavities of one complex.
class CavityBuilder {
public:
  CavityBuilder(const alpha::AlphaComplex& ac, const std::vector<double>& radii, const CavityOptions& options)
      : ac_(ac), t_(ac.triangulation()), s_(ac.simplices()), radii_(radii), options_(options), level_(ac.level(0.0)),
        sealing_(std::async(options.threads > 1 ? std::launch::async : std::launch::deferred,
                            [&ac] { return sealed_from(ac); })),
        flow_(ac, level_), union_(std::make_unique<const alpha::UnionOfBalls>(ac)), space_(*union_),
        excluded_(std::make_unique<const alpha::ErodedUnion>(*union_, options.probe)),
        sealed_from_(sealing_.get()),
        atoms_(std::max(options.burial_radius, 1.0)), nearest_(t_.points(), radii, options.probe) {
    for (Index i = 0; i < t_.num_points(); ++i) atoms_.add(t_.point(i), i);
    atoms_.finish();
  }

  Index level() const { return level_; }

  // The two bodies, given away: the builder is done with them.
  SolventBodies bodies() && { return {std::move(union_), std::move(excluded_)}; }

  // The regions' basins, then the cavities' measures, each on
  // options.threads threads: every task fills its own slot, and the lists
  // are assembled in the order of a sequential run (regions by number,
  // basins in order), so the output does not depend on the threads.
  void run(Cavities& out) {
    out.sa_area = space_.union_of_balls().area();
    out.sa_volume = space_.union_of_balls().volume();
    std::vector<std::vector<Index>> region_cells(flow_.num_regions());
    for (Index c = 0; c < t_.num_cells(); ++c)
      if (flow_.region(c) != alpha::kNone) region_cells[flow_.region(c)].push_back(c);
    std::vector<std::size_t> sizes;
    for (const auto& cells : region_cells) sizes.push_back(cells.size());
    std::vector<std::optional<Region>> regions(region_cells.size());
    parallel_for(largest_first(sizes), options_.threads,
                 [&](std::size_t r) { regions[r].emplace(region_cells[r], *this); });

    std::vector<const std::vector<Index>*> basins;
    std::vector<const Region*> basin_region;
    sizes.clear();
    for (const std::optional<Region>& region : regions)
      for (const std::vector<Index>& basin : region->basins) {
        basins.push_back(&basin);
        basin_region.push_back(&*region);
        sizes.push_back(basin.size());
      }
    std::vector<std::optional<Cavity>> kept(basins.size());
    parallel_for(largest_first(sizes), options_.threads, [&](std::size_t k) {
      kept[k] = keep(*basins[k], basin_region[k]->space, basin_region[k]->nearest_mouth);
    });
    for (std::size_t k = 0; k < kept.size(); ++k)
      if (kept[k]) (basin_region[k]->mouths.empty() ? out.voids : out.pockets).push_back(std::move(*kept[k]));
  }

private:
  const alpha::AlphaComplex& ac_;
  const alpha::Triangulation& t_;
  const alpha::Simplices& s_;
  const std::vector<double>& radii_;
  const CavityOptions& options_;
  Index level_;
  // sealed_from() on a thread of its own while the union and the eroded
  // union are built (with more than one thread).
  std::future<std::vector<Index>> sealing_;
  alpha::DiscreteFlow flow_;
  std::unique_ptr<const alpha::UnionOfBalls> union_;  // the solvent-accessible body
  CavitySpace space_;
  std::unique_ptr<const alpha::ErodedUnion> excluded_;  // the solvent-excluded body: union_ eroded by the probe
  std::vector<Index> sealed_from_;   // cell -> see sealed_from()
  // All atoms, bucketed: the burial count and the clearance look only near
  // the cavity (a scan of all atoms per cavity is slow on large assemblies).
  alpha::PointGrid atoms_;
  alpha::NearestBall nearest_;

  bool empty(Index f) const { return ac_.triangle_interval(f).entry >= level_; }

  // Radius of the largest probe centred at x: its distance to the nearest
  // atom's van der Waals sphere (infinite for a point at infinity).
  double clearance(const Vec3& x) const { return nearest_.distance(x); }

  // The empty space of a region's cells (sorted), each computed once for
  // the size rule's masses and the measures of the region's cavities.
  struct RegionSpace {
    const std::vector<Index>& ids;
    std::vector<CellSpace> cells;
    RegionSpace(const std::vector<Index>& region, const CavitySpace& space) : ids(region) {
      cells.reserve(region.size());
      for (Index c : region) cells.push_back(space.cell(c));
    }
    const CellSpace& operator[](Index c) const {
      return cells[std::lower_bound(ids.begin(), ids.end(), c) - ids.begin()];
    }
  };

  // A region of the flow with its empty space, its triangles to the
  // outside (a pocket's mouths; none for a void) and its cavities: the
  // basins of a pocket region, the whole of a void.
  struct Region {
    std::vector<Index> mouths;
    RegionSpace space;
    NearestTriangle nearest_mouth;
    std::vector<std::vector<Index>> basins;
    Region(const std::vector<Index>& cells, const CavityBuilder& b)
        : mouths(b.region_mouths(cells)), space(cells, b.space_), nearest_mouth(b.t_, b.s_, mouths) {
      if (mouths.empty()) {
        basins.push_back(cells);
        return;
      }
      std::vector<double> free_volume;
      free_volume.reserve(cells.size());
      for (const CellSpace& m : space.cells) free_volume.push_back(std::max(0.0, m.sa_empty));
      const CavityOptions& o = b.options_;
      basins = alpha::persistent_basins(b.ac_, b.level_, cells,
                                        {o.split_persistence, free_volume, o.split_min_volume, o.split_volume});
    }
  };

  // The region's triangles to the outside.
  std::vector<Index> region_mouths(const std::vector<Index>& cells) const {
    std::vector<Index> mouths;
    for (Index c : cells)
      for (int k = 0; k < 4; ++k)
        if (flow_.outside(t_.cell(c).n[k]) && empty(s_.cell_triangle(c, k))) mouths.push_back(s_.cell_triangle(c, k));
    return mouths;
  }

  // The cavity of `cells` (sorted, a basin of the region of `space`, whose
  // triangles to the outside are `mouths`) if it holds at least
  // min_volume; the measures that look at atoms or mouths are taken only
  // then.
  std::optional<Cavity> keep(const std::vector<Index>& cells, const RegionSpace& space,
                             const NearestTriangle& mouths) const {
    double sa_volume = 0;
    for (Index c : cells) sa_volume += space[c].sa_empty;
    sa_volume = std::max(0.0, sa_volume);  // rounding
    if (sa_volume >= options_.min_volume) return build(cells, space, mouths, sa_volume);
    return std::nullopt;
  }

  Cavity build(const std::vector<Index>& cells, const RegionSpace& space, const NearestTriangle& mouths,
               double sa_volume) const {
    Cavity cav;
    cav.cells = cells;
    cav.sa_volume = sa_volume;
    // The probe layer between the SA and the molecular surface whose
    // nearest solvent-accessible point lies on the cavity's wall.
    const alpha::LayerShare layer = excluded_->cells_share(cells);
    std::vector<Opening> openings;
    Index last = cells.front();
    Vec3 weighted{};
    double total_weight = 0;
    for (Index c : cells) {
      const alpha::Cell& cell = t_.cell(c);
      if (flow_.is_sink(c)) cav.sinks.push_back(c);
      for (int k = 0; k < 4; ++k) {
        cav.lining_atoms.push_back(cell.v[k]);
        const Index f = s_.cell_triangle(c, k);
        if (!empty(f) || std::binary_search(cells.begin(), cells.end(), cell.n[k])) continue;
        openings.emplace_back(f, flow_.outside(cell.n[k]));
      }
      // The last cell to fill; ties as in the persistence pairs (the elder
      // of a complement component is its largest cell by rank, then id).
      if (ac_.cell_entry(c) >= ac_.cell_entry(last)) last = c;
      const CellSpace& m = space[c];
      cav.sa_area += m.sa_area;
      const double weight = std::max(0.0, m.sa_empty);
      weighted = weighted + weight * m.centroid;
      total_weight += weight;
    }
    cav.sa_area = std::max(0.0, cav.sa_area);  // rounding, as sa_volume
    cav.ms_volume = std::max(cav.sa_volume, cav.sa_volume + layer.volume);
    cav.ms_area = std::max(0.0, layer.area);
    cav.center = total_weight > 0
                     ? Vec3{weighted.x / total_weight, weighted.y / total_weight, weighted.z / total_weight}
                     : space[cells.front()].centroid;
    std::sort(cav.lining_atoms.begin(), cav.lining_atoms.end());
    cav.lining_atoms.erase(std::unique(cav.lining_atoms.begin(), cav.lining_atoms.end()), cav.lining_atoms.end());

    std::sort(openings.begin(), openings.end());
    cav.mouths = group_mouths(s_, openings, space_);
    for (const Mouth& m : cav.mouths) cav.mouth_area += m.area;
    cav.buriedness = cav.sa_area + cav.mouth_area > 0 ? cav.sa_area / (cav.sa_area + cav.mouth_area) : 1;

    cav.max_alpha_sq = ac_.spectrum_value(ac_.cell_entry(last));
    cav.fill_alpha_sq = cav.max_alpha_sq;
    cav.max_probe_radius = clearance(ac_.size_kernel().center(alpha::Simplex(t_.cell(last).v)));
    Index sealed = 0;
    for (Index c : cells) sealed = std::max(sealed, sealed_from_[c]);
    cav.close_alpha_sq = ac_.spectrum_value(sealed);

    // The largest distance from a cell to its nearest mouth; a cell with a
    // mouth within the depth so far cannot raise it.
    Index near_mouth = alpha::kNone;
    for (Index c : cells) {
      const Vec3& x = space[c].centroid;
      if (!mouths.empty() && !mouths.within(x, cav.depth, near_mouth))
        cav.depth = std::max(cav.depth, mouths.distance(x, near_mouth));
    }

    const double r2 = options_.burial_radius * options_.burial_radius;
    atoms_.visit(cav.center, options_.burial_radius, [&](Index i) {
      cav.burial_atoms += dot(t_.point(i) - cav.center, t_.point(i) - cav.center) <= r2;
    });
    return cav;
  }
};

// Cavities::sites, from the ranked pockets and voids.
std::vector<Site> rank_sites(const Cavities& cavities) {
  std::vector<Site> sites;
  for (std::size_t i = 0; i < cavities.pockets.size(); ++i) sites.push_back({false, i, cavities.pockets[i].center});
  for (std::size_t i = 0; i < cavities.voids.size(); ++i)
    if (holds_ligand(cavities.voids[i])) sites.push_back({true, i, cavities.voids[i].center});
  std::stable_sort(sites.begin(), sites.end(), [&](const Site& a, const Site& b) {
    return cavities.cavity(a).score > cavities.cavity(b).score;
  });
  return sites;
}

}  // namespace

bool holds_ligand(const Cavity& void_cavity) {
  return void_cavity.sa_volume >= kLigandSiteVolume || void_cavity.ms_volume >= kLigandVoidVolume;
}

std::vector<Site> site_candidates(const Cavities& cavities) {
  std::vector<Site> sites;
  for (std::size_t i = 0; i < cavities.pockets.size(); ++i) sites.push_back({false, i, cavities.pockets[i].center});
  for (std::size_t i = 0; i < cavities.voids.size(); ++i)
    if (cavities.voids[i].sa_volume >= kLigandSiteVolume) sites.push_back({true, i, cavities.voids[i].center});
  return sites;
}

std::string site_cavity_name(const Site& site) {
  return (site.is_void ? "void " : "pocket ") + std::to_string(site.index + 1);
}

Cavities find_cavities(const alpha::AlphaComplex& ac, const std::vector<double>& radii, const CavityOptions& options,
                       SolventBodies* bodies) {
  check_input(ac, radii, options);
  CavityBuilder builder(ac, radii, options);
  Cavities out;
  builder.run(out);
  rank_cavities(out.pockets);
  rank_cavities(out.voids);
  out.sites = rank_sites(out);
  const Index level = builder.level();
  if (options.tunnels)
    for (const alpha::PersistencePair& p : ac.persistence())
      if (p.dim == 1 && p.birth < level && p.death >= level && p.death != alpha::kNever)
        out.tunnels.push_back(make_tunnel(ac, p, radii, options.probe));
  std::stable_sort(out.tunnels.begin(), out.tunnels.end(),
                   [](const Tunnel& a, const Tunnel& b) { return a.death_alpha_sq > b.death_alpha_sq; });
  if (bodies) *bodies = std::move(builder).bodies();
  return out;
}

double cavity_score(const Cavity& cavity) {
  return std::min(cavity.sa_volume, kLigandSiteVolume) * std::pow(double(cavity.burial_atoms) / 600, 12);
}

void rank_cavities(std::vector<Cavity>& cavities) {
  for (Cavity& c : cavities) c.score = cavity_score(c);
  std::stable_sort(cavities.begin(), cavities.end(), [](const Cavity& a, const Cavity& b) { return a.score > b.score; });
}

}  // namespace molecule
