// SPDX-License-Identifier: Apache-2.0
// Time to mesh the molecular surface of protein structures: ours
// (alpha::eroded_union_mesh, the solvent-excluded surface, at the default
// --mesh-resolution) against CGAL's Skin_surface_3 meshing of the same
// atoms, on the same files in one run; and how close each mesh's area and
// enclosed volume come to our analytic molecular (SES) area and volume.
// bench/surface_mesh.sh runs it next to PyMOL (README there).
//
// Usage: bench_surface_mesh [--resolution H] [--no-cgal] FILE...
// (--no-cgal: ours alone, CGAL's columns 0: for the error against the
// resolution, where CGAL's minutes per file are not wanted.)
// One row per file: atoms, the analytic area and volume; ours: CPU
// seconds from the atoms to the mesh (triangulation, alpha complex, union,
// eroded union, mesh), the mesh part alone, its area and volume errors against the analytic ones; CGAL:
// seconds (make_skin_surface_mesh_3, shrink factor 1/2, one subdivision:
// its own regular triangulation included), its errors; the ratio CGAL /
// ours. Median of REPS runs (environment, default 3) of each.
//
// The skin of the van der Waals balls with shrink factor 1/2, the balls
// grown first (CGAL's grow_balls: radius sqrt(2) r_i) is Edelsbrunner's
// molecular skin: an isolated atom is its van der Waals sphere, and gaps
// narrower than about a probe are bridged by hyperboloid necks, as the SES bridges them by the rolling probe. It
// is a different surface, so its errors say how far it is from the SES.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/make_skin_surface_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <list>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/eroded_union.hpp"
#include "alpha/eroded_union_mesh.hpp"
#include "alpha/union_of_balls.hpp"
#include "median.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/pocket_meshes.hpp"
#include "molecule/structure.hpp"
#include "rss.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using WeightedPoint = K::Weighted_point_3;
using Polyhedron = CGAL::Polyhedron_3<K>;

constexpr double kProbe = 1.4;

struct Measures {
  double area = 0, volume = 0;
};

Measures measures(const alpha::SurfaceMesh& m) {
  Measures out;
  for (const auto& t : m.triangles) {
    const alpha::Vec3 a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    out.area += alpha::norm(alpha::cross(b - a, c - a)) / 2;
    out.volume += alpha::dot(a, alpha::cross(b, c)) / 6;
  }
  return out;
}

Measures measures(const Polyhedron& p) {
  Measures out;
  for (auto f = p.facets_begin(); f != p.facets_end(); ++f) {
    auto h = f->facet_begin();
    const K::Point_3 a = h->vertex()->point();
    ++h;
    for (; std::next(h) != f->facet_begin(); ++h) {  // a fan of triangles
      const K::Point_3 b = h->vertex()->point(), c = std::next(h)->vertex()->point();
      const alpha::Vec3 pa{a.x(), a.y(), a.z()}, pb{b.x(), b.y(), b.z()}, pc{c.x(), c.y(), c.z()};
      out.area += alpha::norm(alpha::cross(pb - pa, pc - pa)) / 2;
      out.volume += alpha::dot(pa, alpha::cross(pb, pc)) / 6;
    }
  }
  return out;
}

double percent(double value, double exact) { return 100 * (value - exact) / exact; }

}  // namespace

int main(int argc, char** argv) {
  double resolution = molecule::kDefaultMeshResolution;
  bool cgal_too = true;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--resolution" && i + 1 < argc)
      resolution = std::atof(argv[++i]);
    else if (a == "--no-cgal")
      cgal_too = false;
    else
      files.push_back(a);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: bench_surface_mesh [--resolution H] [--no-cgal] FILE...\n");
    return 2;
  }
  const int reps = std::getenv("REPS") ? std::max(1, std::atoi(std::getenv("REPS"))) : 3;
  std::printf("%-12s %6s %9s %9s %8s %8s %8s %8s %8s %8s %8s %8s\n", "file", "atoms", "ms_area", "ms_volume",
              "ours s", "mesh s", "area %", "vol %", "CGAL s", "area %", "vol %", "CGAL/us");
  std::vector<double> ratios;
  for (const std::string& file : files) {
    const std::vector<molecule::Atom> atoms = molecule::read_structure(file).atoms;
    const molecule::AtomBalls balls = molecule::atom_balls(atoms, kProbe);

    // Ours, from the atoms to the mesh.
    std::vector<double> total, mesh_only;
    Measures ours, exact;
    for (int k = 0; k < reps; ++k) {
      const double start = bench::cpu_seconds();
      const alpha::Triangulation t(balls.points, balls.weights);
      const alpha::AlphaComplex ac(t);
      const alpha::UnionOfBalls u(ac);
      const alpha::ErodedUnion eu(u, kProbe);
      const double mesh_start = bench::cpu_seconds();
      const alpha::ErodedUnionMesh m = alpha::eroded_union_mesh(eu, resolution);
      const double end = bench::cpu_seconds();
      total.push_back(end - start);
      mesh_only.push_back(end - mesh_start);
      if (k == 0) {
        ours = measures(m.mesh);
        const alpha::LayerShare layer = eu.layer();
        exact = {layer.area, u.volume() - layer.volume};
      }
    }

    // CGAL's molecular skin of the same atoms.
    std::list<WeightedPoint> points;
    for (std::size_t i = 0; i < balls.points.size(); ++i) {
      const double r = std::sqrt(balls.weights[i]) - kProbe;
      const alpha::Vec3& p = balls.points[i];
      points.emplace_back(K::Point_3(p.x, p.y, p.z), r * r);
    }
    std::vector<double> cgal{0};
    Measures skin = cgal_too ? Measures{} : exact;
    for (int k = 0; k < reps && cgal_too; ++k) {
      if (k == 0) cgal.clear();
      Polyhedron p;
      const double start = bench::cpu_seconds();
      CGAL::make_skin_surface_mesh_3(p, points.begin(), points.end(), 0.5, 1);
      cgal.push_back(bench::cpu_seconds() - start);
      if (k == 0) skin = measures(p);
    }

    const double ours_s = bench::median(total), cgal_s = bench::median(cgal);
    ratios.push_back(cgal_s / ours_s);
    std::string name = file.substr(file.find_last_of('/') + 1);
    std::printf("%-12s %6zu %9.1f %9.1f %8.3f %8.3f %+8.2f %+8.2f %8.3f %+8.2f %+8.2f %8.2f\n", name.c_str(),
                atoms.size(), exact.area, exact.volume, ours_s, bench::median(mesh_only), percent(ours.area, exact.area),
                percent(ours.volume, exact.volume), cgal_s, percent(skin.area, exact.area),
                percent(skin.volume, exact.volume), cgal_s / ours_s);
    std::fflush(stdout);
  }
  std::printf("median CGAL/ours time ratio over %zu files: %.2f\n", ratios.size(), bench::median(ratios));
  return 0;
}
