// SPDX-License-Identifier: Apache-2.0
#include "molecule/mesh_export.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <numeric>
#include <sstream>
#include <system_error>
#include <tuple>

// OpenMesh's colour property default-constructs VectorT<unsigned char, 3>
// without initializing it, which GCC reports where it is instantiated.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "alpha/error.hpp"
#include "molecule/atomic_file.hpp"

namespace molecule {
namespace {

namespace fs = std::filesystem;

// OpenMesh's writers store single-precision coordinates whatever the mesh
// holds, so the mesh holds floats.
using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct Format {
  const char* name;
  bool binary;
  bool colors;
};
constexpr Format kFormats[] = {
    {"ply", true, true},
    {"off", false, true},
    {"obj", false, false},
    {"stl", true, false},
};
// Significant digits of ASCII coordinates: enough to read back every float exactly.
constexpr std::streamsize kAsciiPrecision = 9;

const Format* find_format(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  if (ext.empty()) return nullptr;
  ext.erase(0, 1);  // the dot
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const Format& f : kFormats)
    if (ext == f.name) return &f;
  return nullptr;
}

const Format* checked_format(const std::string& path) {
  const Format* format = find_format(path);
  if (!format) alpha::fail(path + ": unknown mesh format (expected .ply, .obj, .off or .stl)");
  std::error_code ec;
  if (fs::is_directory(path, ec)) alpha::fail(path + ": is a directory");
  return format;
}

// Silences OpenMesh's log streams (it reports to std::cerr / std::cout on
// its own) for its lifetime: stderr belongs to the caller.
class QuietOpenMesh {
public:
  QuietOpenMesh() {
    for (int i = 0; i < 3; ++i) {
      was_enabled_[i] = stream(i).is_enabled();
      stream(i).disable();
    }
  }
  ~QuietOpenMesh() {
    for (int i = 0; i < 3; ++i)
      if (was_enabled_[i]) stream(i).enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

private:
  bool was_enabled_[3] = {};
  static OpenMesh::mostream& stream(int i) {
    return i == 0 ? ::omerr() : i == 1 ? ::omlog() : ::omout();
  }
};

void check_input(const std::string& path, const TriangleMesh& in) {
  const std::size_t n = in.points.size();
  if (!in.face_colors.empty() && in.face_colors.size() != in.triangles.size())
    alpha::fail(path + ": " + std::to_string(in.face_colors.size()) + " face colours for " +
                std::to_string(in.triangles.size()) + " triangles");
  for (std::size_t f = 0; f < in.triangles.size(); ++f) {
    const auto& t = in.triangles[f];
    for (alpha::Index v : t)
      if (v >= n)
        alpha::fail(path + ": triangle " + std::to_string(f) + " uses point " + std::to_string(v) + " of " +
                    std::to_string(n));
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      alpha::fail(path + ": triangle " + std::to_string(f) + " repeats a vertex");
  }
}

// The vertex copy of each corner (corner 3f+k: vertex k of triangle f), and
// the number of copies. Corners of one point share a copy when their
// triangles are joined around it through manifold edges (edges of exactly
// two triangles, running through them in opposite directions): each copy
// is one fan, so non-manifold edges and vertices come apart into manifold
// pieces, as OpenMesh needs. Copies are numbered by point, then by the first
// triangle of their fan.
std::vector<std::size_t> corner_copies(const TriangleMesh& in, std::size_t& copies) {
  const std::size_t corners = 3 * in.triangles.size();
  std::vector<std::size_t> parent(corners);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  auto unite = [&](std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the first corner
  };
  auto vertex = [&](std::size_t c) { return in.triangles[c / 3][c % 3]; };
  auto next = [](std::size_t c) { return c - c % 3 + (c + 1) % 3; };  // the next corner of its triangle

  struct Edge {
    alpha::Index lo, hi;
    std::size_t corner;  // the corner the edge starts at, in its triangle's order
  };
  std::vector<Edge> edges;
  edges.reserve(corners);
  for (std::size_t c = 0; c < corners; ++c) {
    const alpha::Index a = vertex(c), b = vertex(next(c));
    edges.push_back({std::min(a, b), std::max(a, b), c});
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& x, const Edge& y) { return std::tie(x.lo, x.hi, x.corner) < std::tie(y.lo, y.hi, y.corner); });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    if (j - i == 2) {
      const std::size_t c = edges[i].corner, d = edges[i + 1].corner;
      if (vertex(c) == vertex(next(d))) {  // manifold: a->b in one triangle, b->a in the other
        unite(c, next(d));
        unite(next(c), d);
      }
    }
    i = j;
  }

  // Number the fans by point, then by first corner (a root is its class's first corner).
  std::vector<std::size_t> roots;
  for (std::size_t c = 0; c < corners; ++c)
    if (find(c) == c) roots.push_back(c);
  std::stable_sort(roots.begin(), roots.end(), [&](std::size_t a, std::size_t b) { return vertex(a) < vertex(b); });
  std::vector<std::size_t> copy_of_root(corners, 0), copy(corners);
  for (std::size_t k = 0; k < roots.size(); ++k) copy_of_root[roots[k]] = k;
  for (std::size_t c = 0; c < corners; ++c) copy[c] = copy_of_root[find(c)];
  copies = roots.size();
  return copy;
}

// The OpenMesh mesh of the triangles and the points they use.
Mesh build_mesh(const std::string& path, const TriangleMesh& in, bool colors, MeshFileInfo& info) {
  std::size_t copies = 0;
  const std::vector<std::size_t> copy = corner_copies(in, copies);
  Mesh mesh;
  auto add_vertex = [&](alpha::Index v) {
    const alpha::Vec3& p = in.points[v];
    return mesh.add_vertex(Mesh::Point(float(p.x), float(p.y), float(p.z)));
  };
  std::vector<alpha::Index> point_of(copies);
  for (std::size_t c = 0; c < copy.size(); ++c) point_of[copy[c]] = in.triangles[c / 3][c % 3];
  std::vector<Mesh::VertexHandle> handle(copies);
  for (std::size_t k = 0; k < copies; ++k) handle[k] = add_vertex(point_of[k]);
  std::vector<char> used(in.points.size(), 0);
  for (const auto& t : in.triangles)
    for (alpha::Index v : t) used[v] = 1;
  const std::size_t used_points = std::size_t(std::count(used.begin(), used.end(), 1));

  if (colors) mesh.request_face_colors();
  for (std::size_t f = 0; f < in.triangles.size(); ++f) {
    Mesh::FaceHandle fh = mesh.add_face(handle[copy[3 * f]], handle[copy[3 * f + 1]], handle[copy[3 * f + 2]]);
    if (!fh.is_valid()) {  // still refused (not seen so far): a separate triangle
      const auto& t = in.triangles[f];
      fh = mesh.add_face(add_vertex(t[0]), add_vertex(t[1]), add_vertex(t[2]));
      if (!fh.is_valid()) alpha::fail(path + ": OpenMesh refused triangle " + std::to_string(f));
    }
    if (colors) {
      const Rgb& c = in.face_colors[f];
      mesh.set_color(fh, Mesh::Color(c.r, c.g, c.b));
    }
  }
  info.vertices = mesh.n_vertices();
  info.faces = mesh.n_faces();
  info.duplicated_vertices = info.vertices - used_points;
  return mesh;
}

}  // namespace

void check_mesh_file_name(const std::string& path) {
  checked_format(path);
  check_can_create(path);
}

MeshFileContent mesh_file_content(const std::string& path, const TriangleMesh& mesh) {
  const Format* format = checked_format(path);
  MeshFileContent file;
  MeshFileInfo& info = file.info;
  info.format = format->name;
  info.binary = format->binary;
  info.colors = format->colors && !mesh.face_colors.empty();

  check_input(path, mesh);
  std::ostringstream out(std::ios::binary);
  {
    // OpenMesh's writers and log streams are process-wide: one thread at a time.
    static std::mutex openmesh;
    const std::scoped_lock lock(openmesh);
    const QuietOpenMesh quiet;
    const Mesh om = build_mesh(path, mesh, info.colors, info);
    OpenMesh::IO::Options options;
    if (format->binary) options += OpenMesh::IO::Options::Binary;
    if (format->binary) options += OpenMesh::IO::Options::LSB;
    if (info.colors) options += OpenMesh::IO::Options::FaceColor;
    if (!OpenMesh::IO::write_mesh(om, out, std::string(".") + format->name, options, kAsciiPrecision) || !out)
      alpha::fail(path + ": write error (" + format->name + ")");
  }
  file.bytes = std::move(out).str();
  return file;
}

MeshFileInfo write_mesh_file(const std::string& path, const TriangleMesh& mesh) {
  const MeshFileContent file = mesh_file_content(path, mesh);
  write_file_atomically(path, file.bytes);
  return file.info;
}

}  // namespace molecule
