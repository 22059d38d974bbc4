// SPDX-License-Identifier: Apache-2.0
// molecule::write_mesh_file: round trips through OpenMesh's readers (what a
// viewer such as MeshLab sees), for every format, on alpha shape boundaries.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>

#include <unistd.h>

// OpenMesh's colour property default-constructs VectorT<unsigned char, 3>
// without initializing it, which GCC reports where it is instantiated.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "molecule/mesh_export.hpp"
#include "mesh_checks.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/structure.hpp"
#include "point_sets.hpp"
#include "surface_mesh_checks.hpp"

namespace fs = std::filesystem;

namespace {

using testing::closed_and_consistent;
using testing::read_back;
using testing::read_text;
using testing::ReadMesh;
using testing::signed_volume;
using testing::TempDir;

molecule::TriangleMesh boundary_mesh(const alpha::AlphaComplex& a, alpha::Index level) {
  molecule::TriangleMesh m;
  const auto points = a.triangulation().points();
  m.points.assign(points.begin(), points.end());
  m.triangles = a.boundary(level).triangles;
  return m;
}

std::size_t used_vertices(const molecule::TriangleMesh& m) {
  std::vector<char> used(m.points.size(), 0);
  for (const auto& t : m.triangles)
    for (auto v : t) used[v] = 1;
  return std::size_t(std::count(used.begin(), used.end(), 1));
}

}  // namespace

TEST_CASE("mesh export: the 3x3x3 cube of a grid, every format", "[mesh_export]") {
  const alpha::Triangulation t(testing::grid_points(4));
  const alpha::AlphaComplex a(t);
  const alpha::Index level = a.level(0.75);  // all cells: the shape is the cube [0,3]^3
  REQUIRE(a.volume(level) == Approx(27.0));
  const molecule::TriangleMesh m = boundary_mesh(a, level);
  REQUIRE(m.triangles.size() == 108);  // 6 sides x 9 squares x 2 triangles
  REQUIRE(used_vertices(m) == 56);     // 64 grid points less the 8 inside

  TempDir dir;
  for (const std::string name : {"cube.ply", "cube.off", "cube.obj", "cube.stl", "CUBE.PLY"}) {
    CAPTURE(name);
    const fs::path file = dir / name;
    const molecule::MeshFileInfo info = molecule::write_mesh_file(file.string(), m);
    CHECK(info.vertices == 56);
    CHECK(info.faces == 108);
    CHECK(info.duplicated_vertices == 0);
    CHECK_FALSE(info.colors);
    const ReadMesh back = read_back(file);
    CHECK(back.n_vertices() == 56);
    CHECK(back.n_faces() == 108);
    CHECK(closed_and_consistent(back));
    CHECK(signed_volume(back) == Approx(a.volume(level)));
  }
  CHECK(dir.files() == std::vector<std::string>{"CUBE.PLY", "cube.obj", "cube.off", "cube.ply", "cube.stl"});
  CHECK(read_text(dir / "cube.ply").rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  CHECK(read_text(dir / "cube.off").rfind("OFF\n", 0) == 0);
}

TEST_CASE("mesh export: random shapes keep orientation and volume", "[mesh_export]") {
  const alpha::Triangulation t(testing::random_points(300, 7, 10.0));
  const alpha::AlphaComplex a(t);
  TempDir dir;
  std::size_t duplicated = 0;
  for (const double alpha_sq : {2.0, 4.0, 8.0, 1e6}) {
    CAPTURE(alpha_sq);
    const alpha::Index level = a.level(alpha_sq);
    const molecule::TriangleMesh m = boundary_mesh(a, level);
    REQUIRE(!m.triangles.empty());
    for (const std::string name : {"shape.ply", "shape.off", "shape.obj"}) {
      CAPTURE(name);
      const fs::path file = dir / name;
      const molecule::MeshFileInfo info = molecule::write_mesh_file(file.string(), m);
      CHECK(info.faces == m.triangles.size());
      duplicated += info.duplicated_vertices;
      CHECK(info.vertices == used_vertices(m) + info.duplicated_vertices);
      const ReadMesh back = read_back(file);
      CHECK(back.n_faces() == m.triangles.size());
      // The boundary of a union of tetrahedra is closed, whether or not it
      // is a manifold; the file holds it as a closed 2-manifold.
      CHECK(closed_and_consistent(back, false));
      if (name == "shape.off") {
        const testing::SurfaceReport r = testing::surface_report(testing::read_off(file.string()));
        CHECK(r.closed_manifold());
      }

      // Coordinates are stored as floats.
      CHECK(signed_volume(back) == Approx(a.volume(level)).epsilon(1e-6));
    }
  }
  CHECK(duplicated > 0);  // some shape was not a manifold: that path is covered too
}

TEST_CASE("mesh export: alpha shapes of proteins are closed 2-manifolds, as MeshLab sees them", "[mesh_export]") {
  // Where the shape is pinched along an edge whose solid wedges join again
  // around both of its ends, keeping the wedges apart left an edge of four
  // triangles between the same two vertices: OpenMesh wrote some triangles
  // apart, and at alpha_sq 0 MeshLab counted 70 boundary edges on 1a26A,
  // 54 on 1UYD. Checked on the vertex indices of the file, as MeshLab does
  // (OpenMesh's reader would mend it).
  TempDir dir;
  for (const std::string& file : {std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb", std::string(ALPHAPOCKET_TEST_DATA) + "/1UYD.pdb"}) {
    const molecule::AtomBalls balls = molecule::atom_balls(molecule::read_structure(file).atoms, 1.4);
    const alpha::Triangulation t(balls.points, balls.weights);
    const alpha::AlphaComplex a(t);
    for (const double alpha_sq : {-1.0, 0.0, 1.0, 4.0, 16.0}) {
      CAPTURE(file, alpha_sq);
      const alpha::Index level = a.level(alpha_sq);
      const molecule::TriangleMesh m = boundary_mesh(a, level);
      const fs::path off = dir / "shape.off";
      const molecule::MeshFileInfo info = molecule::write_mesh_file(off.string(), m);
      CHECK(info.faces == m.triangles.size());
      const testing::SurfaceReport r = testing::surface_report(testing::read_off(off.string()));
      CAPTURE(r.summary());
      CHECK(r.closed_manifold());
      CHECK(r.volume == Approx(a.volume(level)).epsilon(1e-6));
    }
  }
}

TEST_CASE("mesh export: non-manifold triangles are written with copied vertices", "[mesh_export]") {
  // Two tetrahedra that share only the vertex 0 (a bow tie).
  molecule::TriangleMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  auto tetra = [&](alpha::Index a, alpha::Index b, alpha::Index c, alpha::Index d) {
    // Oriented outward when orient3d(a, b, c, d) > 0.
    m.triangles.push_back({b, c, d});
    m.triangles.push_back({a, d, c});
    m.triangles.push_back({a, b, d});
    m.triangles.push_back({a, c, b});
  };
  tetra(0, 1, 2, 3);
  tetra(0, 4, 6, 5);
  TempDir dir;
  const fs::path file = dir / "bowtie.ply";
  const molecule::MeshFileInfo info = molecule::write_mesh_file(file.string(), m);
  CHECK(info.faces == 8);
  CHECK(info.vertices == 8);  // the shared vertex twice: once per tetrahedron
  CHECK(info.duplicated_vertices == 1);
  const ReadMesh back = read_back(file);
  CHECK(back.n_vertices() == 8);
  // Points in index order, the copy next to its original.
  std::vector<std::array<float, 3>> order;
  for (auto v : back.vertices()) order.push_back({back.point(v)[0], back.point(v)[1], back.point(v)[2]});
  CHECK(order == std::vector<std::array<float, 3>>{
                     {0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}});
  CHECK(back.n_faces() == 8);
  CHECK(closed_and_consistent(back));
  CHECK(signed_volume(back) == Approx(2.0 / 6));
}

TEST_CASE("mesh export: any triangle soup is written whole", "[mesh_export]") {
  // Random triangles on a few points: edges of many triangles, both
  // orientations, repeated triangles. Nothing may be lost.
  std::mt19937 rng(11);
  molecule::TriangleMesh m;
  for (int i = 0; i < 12; ++i) m.points.push_back({double(i % 3), double(i / 3 % 2), double(i * i % 5)});
  std::uniform_int_distribution<alpha::Index> pick(0, 11);
  while (m.triangles.size() < 300) {
    const alpha::Index a = pick(rng), b = pick(rng), c = pick(rng);
    if (a != b && b != c && a != c) m.triangles.push_back({a, b, c});
  }
  m.triangles.push_back(m.triangles.front());
  TempDir dir;
  const fs::path file = dir / "soup.off";
  const molecule::MeshFileInfo info = molecule::write_mesh_file(file.string(), m);
  CHECK(info.faces == m.triangles.size());
  CHECK(info.vertices == 12 + info.duplicated_vertices);
  const ReadMesh back = read_back(file);
  CHECK(back.n_faces() == m.triangles.size());
  CHECK(back.n_vertices() == info.vertices);
}

TEST_CASE("mesh export: face colours in PLY, OFF and OBJ (its .mtl)", "[mesh_export]") {
  molecule::TriangleMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};  // the last one unused
  m.triangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  m.face_colors = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}};
  TempDir dir;
  for (const std::string name : {"colored.ply", "colored.off"}) {
    CAPTURE(name);
    const fs::path file = dir / name;
    const molecule::MeshFileInfo info = molecule::write_mesh_file(file.string(), m);
    CHECK(info.colors);
    CHECK(info.vertices == 4);
    ReadMesh back = read_back(file, true);
    REQUIRE(back.n_faces() == 4);
    std::vector<std::array<int, 3>> colors;
    for (auto f : back.faces()) {
      const auto c = back.color(f);
      colors.push_back({int(c[0]), int(c[1]), int(c[2])});
    }
    CHECK(colors == std::vector<std::array<int, 3>>{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}});
  }
  // OBJ: a material per colour in the .mtl beside it, which OpenMesh reads back.
  CHECK(molecule::write_mesh_file((dir / "colored.obj").string(), m).colors);
  const std::string mtl = testing::read_text(dir / "colored.mtl");
  CHECK(std::count(mtl.begin(), mtl.end(), '\n') == 16);  // 4 materials of 4 lines
  CHECK(mtl.find("Kd 0.03922 0.07843 0.1176") != std::string::npos);
  CHECK(testing::read_text(dir / "colored.obj").find("mtllib colored.mtl\n") != std::string::npos);
  CHECK(read_back(dir / "colored.obj").n_faces() == 4);
  // STL has no colours: it still writes the mesh, and only that file.
  const molecule::MeshFileInfo info = molecule::write_mesh_file((dir / "plain.stl").string(), m);
  CHECK_FALSE(info.colors);
  CHECK(read_back(dir / "plain.stl").n_faces() == 4);
  CHECK(dir.files() == std::vector<std::string>{"colored.mtl", "colored.obj", "colored.off", "colored.ply", "plain.stl"});
}

TEST_CASE("mesh export: errors leave no file behind", "[mesh_export]") {
  molecule::TriangleMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  TempDir dir;
  using Catch::Matchers::Contains;

  CHECK_THROWS_WITH(molecule::check_mesh_file_name("shape.vrml"), "shape.vrml: unknown mesh format (expected .ply, .obj, .off or .stl)");
  CHECK_THROWS_WITH(molecule::check_mesh_file_name("dir.ply/shape"), Contains("unknown mesh format"));
  CHECK_NOTHROW(molecule::check_mesh_file_name((dir / "shape.Stl").string()));
  CHECK_NOTHROW(molecule::check_mesh_file_name("shape.obj"));  // in the working directory
  CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "shape.vrml").string(), m), Contains("unknown mesh format"));
  CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "shape").string(), m), Contains("unknown mesh format"));
  const std::string missing = (dir / "missing" / "shape.ply").string();
  CHECK_THROWS_WITH(molecule::write_mesh_file(missing, m),
                    missing + ": cannot create a file in " + (dir / "missing").string() + ": No such file or directory");
  CHECK_THROWS_WITH(molecule::check_mesh_file_name(missing), Contains("No such file or directory"));
  std::ofstream(dir / "file") << "not a directory\n";
  CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "file" / "shape.ply").string(), m), Contains("Not a directory"));
  CHECK_THROWS_WITH(molecule::check_mesh_file_name((dir / "file" / "shape.ply").string()), Contains("Not a directory"));
  fs::create_directory(dir / "dir.ply");
  CHECK_THROWS_WITH(molecule::check_mesh_file_name((dir / "dir.ply").string()), Contains("is a directory"));
  CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "dir.ply").string(), m), Contains("is a directory"));

  molecule::TriangleMesh bad = m;
  bad.triangles.push_back({0, 1, 4});
  CHECK_THROWS_AS(molecule::write_mesh_file((dir / "bad.ply").string(), bad), alpha::Error);
  bad = m;
  bad.triangles.push_back({0, 1, 1});
  CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "bad.ply").string(), bad), Contains("repeats a vertex"));
  bad = m;
  bad.face_colors.resize(3);
  CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "bad.ply").string(), bad), Contains("3 face colours for 4"));
  CHECK(dir.files() == std::vector<std::string>{"dir.ply", "file"});

  if (::geteuid() != 0) {  // root writes anywhere
    fs::create_directory(dir / "locked");
    fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    CHECK_THROWS_WITH(molecule::write_mesh_file((dir / "locked" / "shape.ply").string(), m),
                      Contains("Permission denied"));
    CHECK_THROWS_WITH(molecule::check_mesh_file_name((dir / "locked" / "shape.ply").string()),
                      Contains("Permission denied"));
    CHECK(fs::is_empty(dir / "locked"));
    fs::permissions(dir / "locked", fs::perms::owner_all);
  }
}

TEST_CASE("mesh export: an existing file is replaced whole", "[mesh_export]") {
  molecule::TriangleMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  TempDir dir;
  const fs::path file = dir / "shape.off";
  std::ofstream(file) << "old content that is much longer than the new mesh file will be, "
                         "so a file that is only overwritten would keep its tail .................\n";
  molecule::write_mesh_file(file.string(), m);
  const std::string text = read_text(file);
  CHECK(text.find("old content") == std::string::npos);
  CHECK(read_back(file).n_faces() == 4);
  // An empty mesh is a valid (empty) file.
  molecule::write_mesh_file(file.string(), molecule::TriangleMesh{});
  CHECK(read_text(file).rfind("OFF\n0 0 0\n", 0) == 0);
  CHECK(dir.files() == std::vector<std::string>{"shape.off"});
}

TEST_CASE("mesh export: PLY is written byte for byte as OpenMesh writes it", "[mesh_export]") {
  // A closed 2-manifold using every point (an octahedron split at random
  // heights: no vertex copies), with each optional property on or off.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-100, 100);
  std::uniform_int_distribution<int> byte(0, 255), site(-3, 70000);
  molecule::TriangleMesh m;
  for (int k = 0; k < 6; ++k) m.points.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  m.manifold = true;
  const auto rgb = [&] { return molecule::Rgb{std::uint8_t(byte(rng)), std::uint8_t(byte(rng)), std::uint8_t(byte(rng))}; };
  TempDir dir;
  for (int options = 0; options < 8; ++options) {
    CAPTURE(options);
    molecule::TriangleMesh x = m;
    if (options & 1) for (std::size_t v = 0; v < 6; ++v) x.vertex_colors.push_back(rgb());
    if (options & 2) for (std::size_t f = 0; f < 8; ++f) x.face_colors.push_back(rgb());
    if (options & 4) for (std::size_t v = 0; v < 6; ++v) x.vertex_sites.push_back(site(rng));
    const fs::path file = dir / ("mesh" + std::to_string(options) + ".ply");
    molecule::write_mesh_file(file.string(), x);

    OpenMesh::TriMesh_ArrayKernelT<> om;
    OpenMesh::IO::Options o = OpenMesh::IO::Options::Binary;
    o += OpenMesh::IO::Options::LSB;
    if (options & 1) om.request_vertex_colors(), o += OpenMesh::IO::Options::VertexColor;
    if (options & 2) om.request_face_colors(), o += OpenMesh::IO::Options::FaceColor;
    OpenMesh::VPropHandleT<int> sites;
    if (options & 4) {
      om.add_property(sites, "site");
      om.property(sites).set_persistent(true);
      o += OpenMesh::IO::Options::Custom;
    }
    std::vector<OpenMesh::VertexHandle> h;
    for (std::size_t v = 0; v < 6; ++v) {
      const alpha::Vec3& p = x.points[v];
      h.push_back(om.add_vertex({float(p.x), float(p.y), float(p.z)}));
      if (options & 1) om.set_color(h[v], {x.vertex_colors[v].r, x.vertex_colors[v].g, x.vertex_colors[v].b});
      if (options & 4) om.property(sites, h[v]) = x.vertex_sites[v];
    }
    for (std::size_t f = 0; f < 8; ++f) {
      const auto fh = om.add_face(h[x.triangles[f][0]], h[x.triangles[f][1]], h[x.triangles[f][2]]);
      if (options & 2) om.set_color(fh, {x.face_colors[f].r, x.face_colors[f].g, x.face_colors[f].b});
    }
    std::ostringstream expected(std::ios::binary);
    REQUIRE(OpenMesh::IO::write_mesh(om, expected, ".ply", o));
    CHECK(read_text(file) == expected.str());
  }
}
