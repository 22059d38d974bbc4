// SPDX-License-Identifier: Apache-2.0
#include "trajectory/frame_cavities.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "alpha/error.hpp"
#include "molecule/residues.hpp"

namespace molecule {
namespace {

// Grid index range [lo, hi] of a coordinate interval along one axis.
struct AxisRange {
  long lo, hi;
};
AxisRange axis_range(double low, double high, double origin, double spacing, std::size_t n) {
  return {std::max(0L, long(std::ceil((low - origin) / spacing))),
          std::min(long(n) - 1, long(std::floor((high - origin) / spacing)))};
}

// The atoms in cubic bins of a side at least the largest r_i + probe: the
// balls that may cover a point are in its bin and the 26 around it.
class AtomBins {
public:
  AtomBins(const std::vector<Atom>& atoms, double probe) : atoms_(atoms), probe_(probe) {
    double reach = 0;
    lo_ = hi_ = atoms.front().position;
    for (const Atom& a : atoms) {
      reach = std::max(reach, a.radius + probe);
      lo_ = {std::min(lo_.x, a.position.x), std::min(lo_.y, a.position.y), std::min(lo_.z, a.position.z)};
      hi_ = {std::max(hi_.x, a.position.x), std::max(hi_.y, a.position.y), std::max(hi_.z, a.position.z)};
    }
    side_ = std::max(reach, 1.0);
    for (int d = 0; d < 3; ++d) n_[d] = std::size_t((coord(hi_, d) - coord(lo_, d)) / side_) + 1;
    bins_.resize(n_[0] * n_[1] * n_[2]);
    for (std::size_t i = 0; i < atoms.size(); ++i) bins_[bin_of(atoms[i].position)].push_back(std::uint32_t(i));
  }

  // Whether p is inside some probe-inflated ball (no place for the probe's centre).
  bool covered(const alpha::Vec3& p) const {
    long b[3];
    for (int d = 0; d < 3; ++d) b[d] = long(std::floor((coord(p, d) - coord(lo_, d)) / side_));
    for (long i = b[0] - 1; i <= b[0] + 1; ++i)
      for (long j = b[1] - 1; j <= b[1] + 1; ++j)
        for (long k = b[2] - 1; k <= b[2] + 1; ++k) {
          if (i < 0 || j < 0 || k < 0 || i >= long(n_[0]) || j >= long(n_[1]) || k >= long(n_[2])) continue;
          for (std::uint32_t a : bins_[(std::size_t(i) * n_[1] + std::size_t(j)) * n_[2] + std::size_t(k)]) {
            const alpha::Vec3 d = p - atoms_[a].position;
            const double r = atoms_[a].radius + probe_;
            if (d.x * d.x + d.y * d.y + d.z * d.z < r * r) return true;
          }
        }
    return false;
  }

private:
  static double coord(const alpha::Vec3& v, int d) { return d == 0 ? v.x : d == 1 ? v.y : v.z; }
  std::size_t bin_of(const alpha::Vec3& p) const {
    std::size_t b[3];
    for (int d = 0; d < 3; ++d) b[d] = std::min(n_[d] - 1, std::size_t((coord(p, d) - coord(lo_, d)) / side_));
    return (b[0] * n_[1] + b[1]) * n_[2] + b[2];
  }
  const std::vector<Atom>& atoms_;
  double probe_;
  alpha::Vec3 lo_, hi_;
  double side_ = 1;
  std::size_t n_[3] = {1, 1, 1};
  std::vector<std::vector<std::uint32_t>> bins_;
};

double orient(const alpha::Vec3& a, const alpha::Vec3& b, const alpha::Vec3& c, const alpha::Vec3& d) {
  const alpha::Vec3 u = b - a, v = c - a, w = d - a;
  return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
}

// Grid points in the tetrahedron (on its boundary included) that the probe's centre can reach.
void cell_space(const std::array<alpha::Vec3, 4>& v, const SpaceGrid& grid, const AtomBins& bins,
                std::vector<std::uint32_t>& out) {
  const double volume = orient(v[0], v[1], v[2], v[3]);
  if (volume == 0) return;
  const double slack = -1e-12 * std::abs(volume);
  AxisRange r[3];
  const double* origin = &grid.origin.x;
  const std::size_t n[3] = {grid.nx, grid.ny, grid.nz};
  for (int d = 0; d < 3; ++d) {
    const auto c = [&](int k) { return (&v[k].x)[d]; };
    r[d] = axis_range(std::min({c(0), c(1), c(2), c(3)}), std::max({c(0), c(1), c(2), c(3)}), origin[d],
                      grid.spacing, n[d]);
  }
  for (long i = r[0].lo; i <= r[0].hi; ++i)
    for (long j = r[1].lo; j <= r[1].hi; ++j)
      for (long k = r[2].lo; k <= r[2].hi; ++k) {
        const std::size_t p = grid.index(std::size_t(i), std::size_t(j), std::size_t(k));
        const alpha::Vec3 x = grid.point(p);
        bool inside = true;
        for (int f = 0; f < 4 && inside; ++f) {
          std::array<alpha::Vec3, 4> w = v;
          w[f] = x;
          inside = orient(w[0], w[1], w[2], w[3]) * (volume > 0 ? 1 : -1) >= slack;
        }
        if (inside && !bins.covered(x)) out.push_back(std::uint32_t(p));
      }
}

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The nearest grid point, if the grid holds x.
std::optional<std::uint32_t> nearest_point(const SpaceGrid& grid, const alpha::Vec3& x) {
  const long i = std::lround((x.x - grid.origin.x) / grid.spacing);
  const long j = std::lround((x.y - grid.origin.y) / grid.spacing);
  const long k = std::lround((x.z - grid.origin.z) / grid.spacing);
  if (i < 0 || j < 0 || k < 0 || i >= long(grid.nx) || j >= long(grid.ny) || k >= long(grid.nz)) return std::nullopt;
  return std::uint32_t(grid.index(std::size_t(i), std::size_t(j), std::size_t(k)));
}

void add_lining(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& lining, FrameCavity& c) {
  for (alpha::Index a : lining) {
    c.residues.push_back(residue_id(atoms[a]));
    c.lining_atoms.push_back(c.residues.back() + ":" + atoms[a].name);
  }
  sort_unique(c.residues);
  sort_unique(c.lining_atoms);
}

}  // namespace

SpaceGrid grid_around(const std::vector<Atom>& atoms, double spacing, double margin) {
  alpha::Vec3 lo = atoms.front().position, hi = lo;
  for (const Atom& a : atoms) {
    lo = {std::min(lo.x, a.position.x), std::min(lo.y, a.position.y), std::min(lo.z, a.position.z)};
    hi = {std::max(hi.x, a.position.x), std::max(hi.y, a.position.y), std::max(hi.z, a.position.z)};
  }
  SpaceGrid g;
  g.spacing = spacing;
  // On multiples of the spacing: grids of runs on the same molecule line up.
  g.origin = {spacing * std::floor((lo.x - margin) / spacing), spacing * std::floor((lo.y - margin) / spacing),
              spacing * std::floor((lo.z - margin) / spacing)};
  g.nx = std::size_t(std::ceil((hi.x + margin - g.origin.x) / spacing)) + 1;
  g.ny = std::size_t(std::ceil((hi.y + margin - g.origin.y) / spacing)) + 1;
  g.nz = std::size_t(std::ceil((hi.z + margin - g.origin.z) / spacing)) + 1;
  if (double(g.nx) * double(g.ny) * double(g.nz) > double(std::numeric_limits<std::int32_t>::max()))
    throw alpha::Error("the grid over the first frame would have more than 2^31 points: raise --grid-spacing",
                       alpha::ErrorKind::LimitExceeded);
  return g;
}

FrameCavities frame_cavities(const Analysis& analysis, const SpaceGrid& grid) {
  FrameCavities out;
  const std::vector<Atom>& atoms = analysis.structure.atoms;
  const alpha::Triangulation& t = analysis.search.shape->triangulation();
  const AtomBins bins(atoms, analysis.options.cavities.probe);
  const alpha::SizeKernel sizes = analysis.search.shape->complex().size_kernel();
  const long half_cube = std::max(0L, long(std::floor(1.0 / grid.spacing + 1e-9)));  // mdpocket's 2 A cube
  const auto add = [&](CavityKind kind, const std::vector<Cavity>& list) {
    for (std::size_t r = 0; r < list.size(); ++r) {
      const Cavity& c = list[r];
      FrameCavity f;
      f.kind = kind;
      f.measures.rank = r + 1;
      f.measures.sa_volume = c.sa_volume;
      f.measures.ms_volume = c.ms_volume;
      f.measures.probability = c.probability;
      f.measures.mouths = c.mouths.size();
      f.measures.bottleneck_radius = std::numeric_limits<double>::quiet_NaN();
      f.measures.center = c.center;
      add_lining(atoms, c.lining_atoms, f);
      for (alpha::Index cell : c.cells) {
        const auto& v = t.cell(cell).v;
        cell_space({t.point(v[0]), t.point(v[1]), t.point(v[2]), t.point(v[3])}, grid, bins, f.space);
        const std::optional<std::uint32_t> p = nearest_point(grid, sizes.center(alpha::Simplex(v[0], v[1], v[2], v[3])));
        if (!p) continue;
        const long i = long(*p / grid.nz / grid.ny), j = long(*p / grid.nz % grid.ny), k = long(*p % grid.nz);
        for (long a = i - half_cube; a <= i + half_cube; ++a)
          for (long b = j - half_cube; b <= j + half_cube; ++b)
            for (long d = k - half_cube; d <= k + half_cube; ++d)
              if (a >= 0 && b >= 0 && d >= 0 && a < long(grid.nx) && b < long(grid.ny) && d < long(grid.nz))
                out.density_hits.push_back(std::uint32_t(grid.index(std::size_t(a), std::size_t(b), std::size_t(d))));
      }
      sort_unique(f.space);
      out.cavities.push_back(std::move(f));
    }
  };
  add(CavityKind::pocket, analysis.search.cavities.pockets);
  add(CavityKind::void_, analysis.search.cavities.voids);
  std::size_t rank = 0;
  for (const TunnelPath& path : analysis.paths) {
    FrameCavity f;
    f.kind = CavityKind::tunnel;
    f.measures.rank = ++rank;
    f.measures.probability = std::numeric_limits<double>::quiet_NaN();
    f.measures.bottleneck_radius = path.bottleneck_radius;
    f.measures.length = path.length;
    f.measures.mouths = path.pore ? 2 : 1;
    f.measures.center = path.bottleneck;
    add_lining(atoms, path.lining_atoms, f);
    for (const alpha::Vec3& x : path.centreline)
      if (const std::optional<std::uint32_t> p = nearest_point(grid, x)) f.space.push_back(*p);
    sort_unique(f.space);
    out.cavities.push_back(std::move(f));
  }
  return out;
}

}  // namespace molecule
