#include "molecule/cavity_mesh.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "alpha/error.hpp"
#include "molecule/pocket_colors.hpp"

namespace molecule {
namespace {

// Every point of the triangulation: write_mesh_file keeps the used ones.
TriangleMesh with_points(const alpha::AlphaComplex& ac) {
  TriangleMesh mesh;
  const auto points = ac.triangulation().points();
  mesh.points.assign(points.begin(), points.end());
  return mesh;
}

}  // namespace

TriangleMesh cavity_mesh(const alpha::AlphaComplex& ac, const Cavity& cavity, Rgb color) {
  const alpha::Triangulation& t = ac.triangulation();
  const alpha::Simplices& s = ac.simplices();
  std::vector<alpha::Index> mouth;
  for (const Mouth& m : cavity.mouths) mouth.insert(mouth.end(), m.triangles.begin(), m.triangles.end());
  std::sort(mouth.begin(), mouth.end());
  const auto in_cavity = [&](alpha::Index c) {
    return std::binary_search(cavity.cells.begin(), cavity.cells.end(), c);
  };
  const Rgb tint = mouth_tint(color);

  TriangleMesh mesh = with_points(ac);
  for (const alpha::Index c : cavity.cells) {
    if (c >= t.num_cells() || t.is_infinite(c))
      alpha::fail("cavity cell " + std::to_string(c) + " is not a finite cell of the triangulation");
    const alpha::Cell& cell = t.cell(c);
    for (int i = 0; i < 4; ++i) {
      if (in_cavity(cell.n[i])) continue;  // inside the cavity: not on its surface
      // kFacet[i] sees vertex i, inside c, on its positive side: swapping
      // two vertices turns the normal away from the cavity.
      const auto& f = alpha::kFacet[i];
      mesh.triangles.push_back({cell.v[f[0]], cell.v[f[2]], cell.v[f[1]]});
      const bool is_mouth = std::binary_search(mouth.begin(), mouth.end(), s.cell_triangle(c, i));
      mesh.face_colors.push_back(is_mouth ? tint : color);
    }
  }
  return mesh;
}

TriangleMesh molecule_mesh(const alpha::AlphaComplex& ac) {
  TriangleMesh mesh = with_points(ac);
  mesh.triangles = ac.boundary(ac.level(0)).triangles;
  mesh.face_colors.assign(mesh.triangles.size(), kMoleculeColor);
  return mesh;
}

}  // namespace molecule
