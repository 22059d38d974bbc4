// SPDX-License-Identifier: Apache-2.0
#include "molecule/pocket_meshes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "alpha/eroded_union.hpp"
#include "alpha/eroded_union_mesh.hpp"
#include "alpha/error.hpp"
#include "outputs/pocket_colors.hpp"

namespace molecule {
namespace {

TriangleMesh from(alpha::SurfaceMesh&& m) {
  TriangleMesh out;
  out.points = std::move(m.points);
  out.triangles = std::move(m.triangles);
  out.manifold = true;  // a contour (alpha/lattice_contour.hpp)
  return out;
}

// The colour rank (pocket_colors.hpp) of each cavity's cells.
std::map<alpha::Index, std::size_t> cell_ranks(const Cavities& cavities, const CavityRanks& ranks) {
  std::map<alpha::Index, std::size_t> out;
  for (std::size_t i = 0; i < cavities.pockets.size(); ++i)
    for (alpha::Index c : cavities.pockets[i].cells) out[c] = ranks.pockets[i];
  for (std::size_t i = 0; i < cavities.voids.size(); ++i)
    for (alpha::Index c : cavities.voids[i].cells) out[c] = ranks.voids[i];
  return out;
}

// The cast of one cavity, in the colour of its rank.
TriangleMesh cast(const alpha::ErodedUnion& eu, const Cavity& cavity, std::size_t rank, double resolution) {
  TriangleMesh m = from(cast_mesh(eu, cavity, resolution));
  m.vertex_colors.assign(m.points.size(), rank_color(rank));
  m.vertex_sites.assign(m.points.size(), int(rank));
  m.face_colors.assign(m.triangles.size(), rank_color(rank));
  return m;
}

}  // namespace

double cast_spacing(double resolution, double ms_volume) {
  return kCastResolution * (resolution / kDefaultMeshResolution) *
         std::clamp(std::cbrt(ms_volume / kFullResolutionCast), 0.25, 1.0);
}

alpha::SurfaceMesh cast_mesh(const alpha::ErodedUnion& eu, const Cavity& cavity, double resolution) {
  const double spacing = cast_spacing(resolution, cavity.ms_volume);
  alpha::SurfaceMesh m = alpha::cells_mesh(eu, cavity.cells, spacing);
  const double error = std::fabs(alpha::enclosed_volume(m) / cavity.ms_volume - 1);
  // The error goes as the spacing squared: aim at half the tolerance.
  if (error > kCastTolerance)
    m = alpha::cells_mesh(eu, cavity.cells, spacing * std::max(0.5, std::sqrt(kCastTolerance / 2 / error)));
  return m;
}

PocketMeshes pocket_meshes(const PocketSearch& search, double resolution) {
  const auto start = std::chrono::steady_clock::now();
  if (!search.bodies.excluded)
    alpha::fail("pocket_meshes: the search kept no solvent-excluded body", alpha::ErrorKind::Misuse);
  const alpha::ErodedUnion& eu = *search.bodies.excluded;
  const Cavities& cavities = search.cavities;
  const CavityRanks ranks = cavity_ranks(cavities);
  PocketMeshes out;

  alpha::ErodedUnionMesh surface = alpha::eroded_union_mesh(eu, resolution);
  const std::map<alpha::Index, std::size_t> rank_of = cell_ranks(cavities, ranks);
  out.surface = from(std::move(surface.mesh));
  TriangleMesh& s = out.surface;
  for (const alpha::Index c : surface.share_cells) {
    const auto it = rank_of.find(c);
    const std::size_t rank = it == rank_of.end() ? 0 : it->second;
    s.vertex_sites.push_back(int(rank));
    s.vertex_colors.push_back(rank ? rank_color(rank) : kMoleculeColor);
  }
  for (const auto& t : s.triangles) {
    // The site most of its vertices have; of two, the better (smaller rank).
    const int a = s.vertex_sites[t[0]], b = s.vertex_sites[t[1]], c = s.vertex_sites[t[2]];
    const int site = a == b || a == c ? a : b == c ? b : std::min({a ? a : b, b ? b : c, c ? c : a});
    s.face_colors.push_back(site ? rank_color(std::size_t(site)) : kMoleculeColor);
  }
  for (std::size_t i = 0; i < cavities.pockets.size(); ++i)
    out.pockets.push_back(cast(eu, cavities.pockets[i], ranks.pockets[i], resolution));
  for (std::size_t i = 0; i < cavities.voids.size(); ++i)
    out.voids.push_back(cast(eu, cavities.voids[i], ranks.voids[i], resolution));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace molecule
