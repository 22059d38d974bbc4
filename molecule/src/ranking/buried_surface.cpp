// SPDX-License-Identifier: Apache-2.0
#include "ranking/buried_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <tuple>

namespace molecule {
namespace {

using alpha::Index;
using alpha::Vec3;

// The unit sphere's Fibonacci lattice: n points of nearly equal spacing.
const std::vector<Vec3>& lattice() {
  static const std::vector<Vec3> kPoints = [] {
    std::vector<Vec3> p;
    const double pi = std::acos(-1.0), turn = pi * (1 + std::sqrt(5.0));
    for (int i = 0; i < kSurfacePointsPerAtom; ++i) {
      const double t = i + 0.5, z = 1 - 2 * t / kSurfacePointsPerAtom, s = std::sqrt(1 - z * z);
      p.push_back({std::cos(turn * t) * s, std::sin(turn * t) * s, z});
    }
    return p;
  }();
  return kPoints;
}

}  // namespace

BuriedSurface::BuriedSurface(const std::vector<Atom>& atoms)
    : atoms_(atoms), atom_grid_(4), grid_(kBuriedPointRadius / 2) {
  index_atoms();
  sample(std::vector<char>(atoms.size(), 1));
}

BuriedSurface::BuriedSurface(const std::vector<Atom>& atoms, std::span<const Vec3> centers, double radius)
    : atoms_(atoms), atom_grid_(4), grid_(kBuriedPointRadius / 2) {
  index_atoms();
  // The points within `radius` of a centre are the whole surface's: every
  // point of their cubes comes from an atom within radius + a cube's
  // diagonal + the largest sphere of it (1 A more: far above rounding).
  const double near = radius + std::sqrt(3.0) * kSurfacePointSpacing + reach_ + 1;
  std::vector<char> sampled(atoms.size(), 0);
  for (const Vec3& c : centers)
    atom_grid_.visit(c, near, [&](Index i) { sampled[i] |= norm(atoms[i].position - c) <= near; });
  sample(sampled);
}

void BuriedSurface::index_atoms() {
  for (Index i = 0; i < atoms_.size(); ++i) {
    atom_grid_.add(atoms_[i].position, i);
    reach_ = std::max(reach_, atoms_[i].radius + kSurfacePointProbe);
  }
  atom_grid_.finish();
}

void BuriedSurface::sample(const std::vector<char>& sampled) {
  const std::vector<Atom>& atoms = atoms_;
  // Lattice points outside every other atom's sphere, keyed by their cube.
  std::vector<std::tuple<std::array<std::int64_t, 3>, std::size_t, Vec3>> kept;
  std::vector<std::pair<Vec3, double>> overlapping;  // the spheres meeting atom i's: centre, squared radius
  for (Index i = 0; i < atoms.size(); ++i) {
    if (!sampled[i]) continue;
    const double r = atoms[i].radius + kSurfacePointProbe;
    overlapping.clear();
    atom_grid_.visit(atoms[i].position, r + reach_, [&](Index j) {
      const double rj = atoms[j].radius + kSurfacePointProbe;
      if (j != i && norm(atoms[j].position - atoms[i].position) < r + rj)
        overlapping.emplace_back(atoms[j].position, rj * rj);
    });
    for (const Vec3& u : lattice()) {
      const Vec3 p = atoms[i].position + r * u;
      const auto inside = [&](const std::pair<Vec3, double>& o) {
        const Vec3 d = p - o.first;
        return dot(d, d) < o.second;
      };
      // A sphere that held a point is tried first for the next ones (it
      // mostly holds them too; the answer does not depend on the order).
      if (const auto o = std::find_if(overlapping.begin(), overlapping.end(), inside); o != overlapping.end()) {
        std::iter_swap(overlapping.begin(), o);
        continue;
      }
      const auto cube = [&](double v) { return std::int64_t(std::floor(v / kSurfacePointSpacing)); };
      kept.emplace_back(std::array<std::int64_t, 3>{cube(p.x), cube(p.y), cube(p.z)}, kept.size(), p);
    }
  }
  // The first point of each cube, in their order.
  std::sort(kept.begin(), kept.end(), [](const auto& a, const auto& b) {
    return std::tie(std::get<0>(a), std::get<1>(a)) < std::tie(std::get<0>(b), std::get<1>(b));
  });
  std::vector<std::pair<std::size_t, Vec3>> first;
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (k == 0 || std::get<0>(kept[k]) != std::get<0>(kept[k - 1]))
      first.emplace_back(std::get<1>(kept[k]), std::get<2>(kept[k]));
  std::sort(first.begin(), first.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [order, p] : first) {
    grid_.add(p, Index(points_.size()));
    points_.push_back(p);
  }
  grid_.finish();
  atoms_near_.assign(points_.size(), -1);
}

int BuriedSurface::atoms_near(std::size_t k) const {
  if (atoms_near_[k] < 0) {
    int n = 0;
    atom_grid_.visit(points_[k], kBuriedPointRadius, [&](Index i) {
      const Vec3 d = atoms_[i].position - points_[k];
      n += dot(d, d) <= kBuriedPointRadius * kBuriedPointRadius;
    });
    atoms_near_[k] = n;
  }
  return atoms_near_[k];
}

std::string surface_points_csv(const std::vector<Atom>& atoms) {
  const BuriedSurface surface(atoms);
  std::string out = "x,y,z,atoms_near\n";
  char line[96];
  for (std::size_t k = 0; k < surface.points().size(); ++k) {
    const Vec3& p = surface.points()[k];
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%d\n", p.x, p.y, p.z, surface.atoms_near(k));
    out += line;
  }
  return out;
}

}  // namespace molecule
