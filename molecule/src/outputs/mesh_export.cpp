// SPDX-License-Identifier: Apache-2.0
#include "molecule/mesh_export.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <numeric>
#include <sstream>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

// OpenMesh's colour property default-constructs VectorT<unsigned char, 3>
// without initializing it, which GCC reports where it is instantiated.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "alpha/error.hpp"
#include "util/atomic_file.hpp"

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
    {"obj", false, true},  // by obj_with_materials
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
  if (!format)
    alpha::fail(path + ": unknown mesh format (expected .ply, .obj, .off or .stl)", alpha::ErrorKind::BadInput);
  std::error_code ec;
  if (fs::is_directory(path, ec)) alpha::fail(path + ": is a directory", alpha::ErrorKind::BadInput);
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
                    std::to_string(in.triangles.size()) + " triangles",
                alpha::ErrorKind::BadInput);
  if ((!in.vertex_colors.empty() && in.vertex_colors.size() != n) || (!in.vertex_sites.empty() && in.vertex_sites.size() != n))
    alpha::fail(path + ": vertex colours or sites do not match the " + std::to_string(n) + " points",
                alpha::ErrorKind::BadInput);
  for (std::size_t f = 0; f < in.triangles.size(); ++f) {
    const auto& t = in.triangles[f];
    for (alpha::Index v : t)
      if (v >= n)
        alpha::fail(
            path + ": triangle " + std::to_string(f) + " uses point " + std::to_string(v) + " of " + std::to_string(n),
            alpha::ErrorKind::BadInput);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      alpha::fail(path + ": triangle " + std::to_string(f) + " repeats a vertex", alpha::ErrorKind::BadInput);
  }
}

// The triangles around each edge of the mesh, as the corners the edge
// starts at (in its triangle's order), in the order they pair up: joined two
// by two, first with second, third with fourth, ... (or, for a ring with
// `shifted` set, second with third, ..., last with first). An edge of two
// triangles is one pair; around an edge of more (solids meeting at an edge
// only) the triangles alternate in direction by angle, and the ring starts
// so that each pair bounds a solid wedge: the sheets of the solids stay
// apart.
struct EdgeRing {
  std::vector<std::size_t> corners;
  bool shifted = false;  // pair across the empty wedges instead
};

inline std::size_t next_corner(std::size_t c) { return c - c % 3 + (c + 1) % 3; }

std::vector<EdgeRing> edge_rings(const TriangleMesh& in) {
  const std::size_t corners = 3 * in.triangles.size();
  auto vertex = [&](std::size_t c) { return in.triangles[c / 3][c % 3]; };
  struct Edge {
    alpha::Index lo, hi;
    std::size_t corner;
  };
  std::vector<Edge> edges;
  edges.reserve(corners);
  for (std::size_t c = 0; c < corners; ++c) {
    const alpha::Index a = vertex(c), b = vertex(next_corner(c));
    edges.push_back({std::min(a, b), std::max(a, b), c});
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& x, const Edge& y) { return std::tie(x.lo, x.hi, x.corner) < std::tie(y.lo, y.hi, y.corner); });
  std::vector<EdgeRing> rings;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    EdgeRing ring;
    for (std::size_t k = i; k < j; ++k) ring.corners.push_back(edges[k].corner);
    auto& around = ring.corners;
    if (around.size() > 2) {
      const alpha::Vec3 a = in.points[edges[i].lo], axis = in.points[edges[i].hi] - a;
      alpha::Vec3 e1 = alpha::cross(axis, std::fabs(axis.x) <= std::fabs(axis.y) ? alpha::Vec3{1, 0, 0} : alpha::Vec3{0, 1, 0});
      const alpha::Vec3 e2 = alpha::cross(axis, e1);
      const auto angle = [&](std::size_t c) {
        const alpha::Vec3 d = in.points[vertex(next_corner(next_corner(c)))] - a;
        return std::atan2(alpha::dot(d, e2), alpha::dot(d, e1));
      };
      std::stable_sort(around.begin(), around.end(), [&](std::size_t x, std::size_t y) { return angle(x) < angle(y); });
      // Start where the first triangle's outward normal points back from
      // the turn, i.e. the wedge ahead of it is inside.
      const std::size_t first = around[0];
      const alpha::Vec3 p0 = in.points[vertex(first)], p1 = in.points[vertex(next_corner(first))],
                        p2 = in.points[vertex(next_corner(next_corner(first)))];
      const alpha::Vec3 normal = alpha::cross(p1 - p0, p2 - p0);
      const alpha::Vec3 d = p2 - a, ahead = alpha::cross(axis, d - (alpha::dot(d, axis) / alpha::dot(axis, axis)) * axis);
      if (alpha::dot(normal, ahead) > 0) std::rotate(around.begin(), around.begin() + 1, around.end());
    }
    rings.push_back(std::move(ring));
    i = j;
  }
  return rings;
}

// The vertex copy of each corner (corner 3f+k: vertex k of triangle f), and
// the number of copies. Corners of one point share a copy when their
// triangles are joined around it through edges paired as edge_rings says
// (two triangles running through the edge in opposite directions): each
// copy is one fan, so non-manifold edges and vertices come apart into
// manifold pieces, as OpenMesh needs.
//
// Keeping solid wedges apart at an edge ab is not enough where the shape is
// pinched along ab but its wedges join again around both a and b (a ring of
// tetrahedra closing on itself at one edge): then each of a and b is one
// fan, and both copies of the edge would join the same two vertices. There
// the ring is paired across its empty wedges instead (the surface runs
// through the pinch as through a thin neck), which splits the fans of a and
// b apart, so that every edge copy joins its own pair of vertex copies: the
// file is a closed 2-manifold, with the same triangles (area, volume and
// orientation unchanged). Copies are numbered by point, then by the first
// triangle of their fan.
std::vector<std::size_t> corner_copies(const TriangleMesh& in, std::size_t& copies) {
  const std::size_t corners = 3 * in.triangles.size();
  if (in.manifold) {  // one fan per point: a copy per point used, in point order
    std::vector<std::size_t> number(in.points.size(), 0);
    for (const auto& t : in.triangles)
      for (alpha::Index v : t) number[v] = 1;
    copies = 0;
    for (std::size_t& n : number) n = n ? copies++ : 0;
    std::vector<std::size_t> copy(corners);
    for (std::size_t c = 0; c < corners; ++c) copy[c] = number[in.triangles[c / 3][c % 3]];
    return copy;
  }
  auto vertex = [&](std::size_t c) { return in.triangles[c / 3][c % 3]; };
  std::vector<EdgeRing> rings = edge_rings(in);
  std::vector<std::size_t> parent(corners);
  auto find = [&](std::size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  auto unite = [&](std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the first corner
  };
  auto join = [&]() {
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    for (const EdgeRing& ring : rings) {
      const std::size_t n = ring.corners.size(), s = ring.shifted ? 1 : 0;
      for (std::size_t k = 0; k + 1 < n; k += 2) {
        const std::size_t c = ring.corners[(k + s) % n], d = ring.corners[(k + 1 + s) % n];
        if (vertex(c) == vertex(next_corner(d))) {  // a->b in one triangle, b->a in the other
          unite(c, next_corner(d));
          unite(next_corner(c), d);
        }
      }
    }
  };
  // Shifting a ring splits the fans at its ends, never joins any, so rings
  // are shifted until no two copies of an edge share their ends; within one
  // round, only rings with no point in common (two shifts at one point
  // could join again what each splits).
  join();
  for (bool shifted_some = true; shifted_some;) {
    shifted_some = false;
    std::vector<char> touched(in.points.size(), 0);
    for (EdgeRing& ring : rings) {
      const std::size_t n = ring.corners.size();
      if (n <= 2 || ring.shifted) continue;
      std::vector<std::pair<std::size_t, std::size_t>> ends;  // the vertex copies of each edge copy
      for (std::size_t k = 0; k + 1 < n; k += 2) {
        const std::size_t c = ring.corners[k], a = find(c), b = find(next_corner(c));
        ends.emplace_back(std::min(a, b), std::max(a, b));
      }
      std::sort(ends.begin(), ends.end());
      const alpha::Index a = vertex(ring.corners[0]), b = vertex(next_corner(ring.corners[0]));
      if (std::adjacent_find(ends.begin(), ends.end()) == ends.end() || touched[a] || touched[b]) continue;
      ring.shifted = true;
      touched[a] = touched[b] = 1;
      shifted_some = true;
    }
    if (shifted_some) join();
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

// The OpenMesh mesh of the triangles and the points they use, with the
// colours and sites asked for.
Mesh build_mesh(const std::string& path, const TriangleMesh& in, const OpenMesh::IO::Options& options,
                MeshFileInfo& info) {
  std::size_t copies = 0;
  const std::vector<std::size_t> copy = corner_copies(in, copies);
  Mesh mesh;
  const bool face_colors = options.check(OpenMesh::IO::Options::FaceColor);
  const bool vertex_colors = options.check(OpenMesh::IO::Options::VertexColor);
  const bool sites = options.check(OpenMesh::IO::Options::Custom);
  if (face_colors) mesh.request_face_colors();
  if (vertex_colors) mesh.request_vertex_colors();
  OpenMesh::VPropHandleT<int> site;
  if (sites) {
    mesh.add_property(site, "site");
    mesh.property(site).set_persistent(true);
  }
  auto add_vertex = [&](alpha::Index v) {
    const alpha::Vec3& p = in.points[v];
    const Mesh::VertexHandle h = mesh.add_vertex(Mesh::Point(float(p.x), float(p.y), float(p.z)));
    if (vertex_colors) mesh.set_color(h, Mesh::Color(in.vertex_colors[v].r, in.vertex_colors[v].g, in.vertex_colors[v].b));
    if (sites) mesh.property(site, h) = in.vertex_sites[v];
    return h;
  };
  std::vector<alpha::Index> point_of(copies);
  for (std::size_t c = 0; c < copy.size(); ++c) point_of[copy[c]] = in.triangles[c / 3][c % 3];
  std::vector<Mesh::VertexHandle> handle(copies);
  for (std::size_t k = 0; k < copies; ++k) handle[k] = add_vertex(point_of[k]);
  std::vector<char> used(in.points.size(), 0);
  for (const auto& t : in.triangles)
    for (alpha::Index v : t) used[v] = 1;
  const std::size_t used_points = std::size_t(std::count(used.begin(), used.end(), 1));

  for (std::size_t f = 0; f < in.triangles.size(); ++f) {
    Mesh::FaceHandle fh = mesh.add_face(handle[copy[3 * f]], handle[copy[3 * f + 1]], handle[copy[3 * f + 2]]);
    if (!fh.is_valid()) {  // still refused (not seen so far): a separate triangle
      const auto& t = in.triangles[f];
      fh = mesh.add_face(add_vertex(t[0]), add_vertex(t[1]), add_vertex(t[2]));
      if (!fh.is_valid())
        alpha::fail(path + ": OpenMesh refused triangle " + std::to_string(f), alpha::ErrorKind::BadInput);
    }
    if (face_colors) {
      const Rgb& c = in.face_colors[f];
      mesh.set_color(fh, Mesh::Color(c.r, c.g, c.b));
    }
  }
  info.vertices = mesh.n_vertices();
  info.faces = mesh.n_faces();
  info.duplicated_vertices = info.vertices - used_points;
  return mesh;
}

// Wavefront OBJ with its faces grouped by colour, each colour a material
// of the .mtl file `mtl_name` (none when there are no colours).
std::string obj_with_materials(const TriangleMesh& in, const std::string& mtl_name, std::string& mtl,
                               MeshFileInfo& info) {
  std::ostringstream out;
  out.precision(kAsciiPrecision);
  out << "# alphapocket\n";
  // One vertex per fan, as in the other formats (build_mesh).
  std::size_t copies = 0;
  const std::vector<std::size_t> copy = corner_copies(in, copies);
  std::vector<alpha::Index> point_of(copies);
  for (std::size_t c = 0; c < copy.size(); ++c) point_of[copy[c]] = in.triangles[c / 3][c % 3];
  for (const alpha::Index v : point_of) {
    const alpha::Vec3& p = in.points[v];
    out << "v " << float(p.x) << ' ' << float(p.y) << ' ' << float(p.z) << '\n';
  }
  const auto face = [&](std::size_t f) {
    out << "f " << copy[3 * f] + 1 << ' ' << copy[3 * f + 1] + 1 << ' ' << copy[3 * f + 2] + 1 << '\n';
  };
  std::vector<Rgb> materials;  // in order of first use
  std::vector<std::size_t> material_of(in.triangles.size(), 0);
  for (std::size_t f = 0; f < in.face_colors.size(); ++f) {
    auto it = std::find(materials.begin(), materials.end(), in.face_colors[f]);
    if (it == materials.end()) it = materials.insert(materials.end(), in.face_colors[f]);
    material_of[f] = std::size_t(it - materials.begin());
  }
  if (!materials.empty()) out << "mtllib " << mtl_name << '\n';
  std::ostringstream m;
  m.precision(4);
  for (std::size_t k = 0; k < materials.size(); ++k) {
    m << "newmtl color_" << k << "\nKd " << materials[k].r / 255.0 << ' ' << materials[k].g / 255.0 << ' '
      << materials[k].b / 255.0 << "\nKa 0 0 0\nillum 1\n";
    out << "usemtl color_" << k << '\n';
    for (std::size_t f = 0; f < in.triangles.size(); ++f)
      if (material_of[f] == k) face(f);
  }
  if (materials.empty())
    for (std::size_t f = 0; f < in.triangles.size(); ++f) face(f);
  mtl = std::move(m).str();
  std::vector<char> used(in.points.size(), 0);
  for (const alpha::Index v : point_of) used[v] = 1;
  info.vertices = copies;
  info.duplicated_vertices = copies - std::size_t(std::count(used.begin(), used.end(), 1));
  info.faces = in.triangles.size();
  return std::move(out).str();
}

// Binary little-endian PLY, written here: the same bytes as OpenMesh's
// writer (tested), which builds a halfedge mesh and writes value by value
// through a stream, about 20 times the time (a fifth of a `pockets` run's).
// One vertex per fan, as build_mesh has them.
std::string binary_ply(const TriangleMesh& in, bool vertex_colors, bool face_colors, bool sites, MeshFileInfo& info) {
  std::size_t copies = 0;
  const std::vector<std::size_t> copy = corner_copies(in, copies);
  std::vector<alpha::Index> point_of(copies);
  for (std::size_t c = 0; c < copy.size(); ++c) point_of[copy[c]] = in.triangles[c / 3][c % 3];
  std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(copies) +
                       "\nproperty float x\nproperty float y\nproperty float z\n";
  const char* rgb = "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (vertex_colors) header += rgb;
  if (sites) header += "property int site\n";
  header += "element face " + std::to_string(in.triangles.size()) + "\nproperty list uchar int vertex_indices\n";
  if (face_colors) header += rgb;
  header += "end_header\n";
  const std::size_t vertex_bytes = 12 + (vertex_colors ? 3 : 0) + (sites ? 4 : 0), face_bytes = 13 + (face_colors ? 3 : 0);
  std::string out(header.size() + copies * vertex_bytes + in.triangles.size() * face_bytes, '\0');
  std::copy(header.begin(), header.end(), out.begin());
  char* at = out.data() + header.size();
  const auto u32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) *at++ = char(v >> (8 * k) & 0xff);
  };
  const auto color = [&](const Rgb& c) {
    *at++ = char(c.r);
    *at++ = char(c.g);
    *at++ = char(c.b);
  };
  for (const alpha::Index v : point_of) {
    const alpha::Vec3& p = in.points[v];
    for (const double x : {p.x, p.y, p.z}) u32(std::bit_cast<std::uint32_t>(float(x)));
    if (vertex_colors) color(in.vertex_colors[v]);
    if (sites) u32(std::uint32_t(in.vertex_sites[v]));
  }
  for (std::size_t f = 0; f < in.triangles.size(); ++f) {
    *at++ = 3;
    for (int k = 0; k < 3; ++k) u32(std::uint32_t(copy[3 * f + k]));
    if (face_colors) color(in.face_colors[f]);
  }
  std::vector<char> used(in.points.size(), 0);
  for (const alpha::Index v : point_of) used[v] = 1;
  info.vertices = copies;
  info.duplicated_vertices = copies - std::size_t(std::count(used.begin(), used.end(), 1));
  info.faces = in.triangles.size();
  info.colors = vertex_colors || face_colors;
  return out;
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
  check_input(path, mesh);
  const bool ply = info.format == "ply";
  if (info.format == "obj") {
    info.colors = !mesh.face_colors.empty();
    if (info.colors) file.companion_path = fs::path(path).replace_extension(".mtl").string();
    file.bytes = obj_with_materials(mesh, fs::path(file.companion_path).filename().string(), file.companion, info);
    return file;
  }
  if (ply) {
    file.bytes = binary_ply(mesh, !mesh.vertex_colors.empty(), !mesh.face_colors.empty(), !mesh.vertex_sites.empty(), info);
    return file;
  }
  OpenMesh::IO::Options options;
  if (format->binary) options += OpenMesh::IO::Options::Binary;
  if (format->binary) options += OpenMesh::IO::Options::LSB;
  if (format->colors && !mesh.vertex_colors.empty()) options += OpenMesh::IO::Options::VertexColor;
  // OFF holds one kind of colour: the vertices' when given.
  if (format->colors && !mesh.face_colors.empty() && (ply || mesh.vertex_colors.empty()))
    options += OpenMesh::IO::Options::FaceColor;
  if (ply && !mesh.vertex_sites.empty()) options += OpenMesh::IO::Options::Custom;
  info.colors = options.check(OpenMesh::IO::Options::VertexColor) || options.check(OpenMesh::IO::Options::FaceColor);
  std::ostringstream out(std::ios::binary);
  {
    // OpenMesh's writers and log streams are process-wide: one thread at a time.
    static std::mutex openmesh;
    const std::scoped_lock lock(openmesh);
    const QuietOpenMesh quiet;
    const Mesh om = build_mesh(path, mesh, options, info);
    if (!OpenMesh::IO::write_mesh(om, out, std::string(".") + format->name, options, kAsciiPrecision) || !out)
      alpha::fail(path + ": write error (" + format->name + ")", alpha::ErrorKind::BadInput);
  }
  file.bytes = std::move(out).str();
  return file;
}

MeshFileInfo write_mesh_file(const std::string& path, const TriangleMesh& mesh) {
  const MeshFileContent file = mesh_file_content(path, mesh);
  // The .mtl first: the mesh never names a material file that is not there.
  if (!file.companion_path.empty()) write_file_atomically(file.companion_path, file.companion);
  write_file_atomically(path, file.bytes);
  return file.info;
}

}  // namespace molecule
