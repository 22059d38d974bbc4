// SPDX-License-Identifier: Apache-2.0
// libalpha on a plain point cloud: points sampled on a torus, their alpha
// complex, its spectrum and persistence, and the alpha shape that recovers
// the torus written as a mesh file for MeshLab.
//
//   point_cloud_shape [OUT.ply]      (default: torus.ply)
//
// The persistence diagram tells at which alpha_sq the sample "is" a torus:
// the longest-lived 2-dimensional class is the torus's enclosed void; in the
// middle of its life (geometric mean of birth and death) the shape has the
// Betti numbers of a torus surface, b0 = 1, b1 = 2, b2 = 1. The program
// checks that, so it exits 1 if the shape is not a torus.
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/triangulation.hpp"
#include "molecule/mesh_export.hpp"

namespace {

// n points on the torus of radii R (around the z axis) and r (the tube),
// uniform in area: the angle around the tube is drawn with density
// proportional to the circle it sweeps (rejection sampling).
std::vector<alpha::Vec3> torus_sample(std::size_t n, double R, double r, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), unit(0, 1);
  std::vector<alpha::Vec3> points;
  while (points.size() < n) {
    const double u = angle(rng), v = angle(rng);
    if (unit(rng) * (R + r) > R + r * std::cos(v)) continue;
    const double d = R + r * std::cos(v);
    points.push_back({d * std::cos(u), d * std::sin(u), r * std::sin(v)});
  }
  return points;
}

int run(const std::string& output) {
  alpha::Triangulation triangulation(torus_sample(3000, 3.0, 1.0, 2024));
  const alpha::AlphaComplex complex(triangulation);
  std::printf("%zu points, %zu finite tetrahedra, %zu critical values (alpha spectrum)\n",
              triangulation.num_points(), triangulation.num_finite_cells(), complex.spectrum_size());
  std::printf("connected at alpha_sq = %.4g\n", complex.spectrum_value(complex.optimal_level() - 1));

  // The most persistent class of each dimension, in alpha_sq.
  const alpha::PersistencePair* longest[3] = {};
  auto life = [&](const alpha::PersistencePair& p) {
    return p.death == alpha::kNever ? INFINITY : complex.spectrum_value(p.death) - complex.spectrum_value(p.birth);
  };
  for (const alpha::PersistencePair& p : complex.persistence())
    if (!longest[p.dim] || life(p) > life(*longest[p.dim])) longest[p.dim] = &p;
  for (int dim = 1; dim < 3; ++dim)
    if (longest[dim])
      std::printf("longest %s: born at alpha_sq %.4g, dies at %.4g\n", dim == 1 ? "loop" : "void",
                  complex.spectrum_value(longest[dim]->birth), complex.spectrum_value(longest[dim]->death));
  if (!longest[2]) {
    std::fprintf(stderr, "no void: the sample is not a closed surface\n");
    return 1;
  }

  const double alpha_sq =
      std::sqrt(complex.spectrum_value(longest[2]->birth) * complex.spectrum_value(longest[2]->death));
  const alpha::Index level = complex.level(alpha_sq);
  const auto betti = complex.betti(level);
  std::printf("at alpha_sq %.4g: Betti numbers %zu %zu %zu, volume %.3f, area %.3f\n", alpha_sq, betti[0], betti[1],
              betti[2], complex.volume(level), complex.area(level));

  molecule::TriangleMesh mesh;
  const auto points = triangulation.points();
  mesh.points.assign(points.begin(), points.end());
  mesh.triangles = complex.boundary(level).triangles;
  const molecule::MeshFileInfo info = molecule::write_mesh_file(output, mesh);
  std::printf("wrote %zu triangles, %zu vertices to %s\n", info.faces, info.vertices, output.c_str());

  if (betti != std::array<std::size_t, 3>{1, 2, 1}) {
    std::fprintf(stderr, "the shape is not a torus (expected Betti numbers 1 2 1)\n");
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? argv[1] : "torus.ply");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
}
