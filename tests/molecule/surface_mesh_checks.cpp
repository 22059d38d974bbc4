// SPDX-License-Identifier: Apache-2.0
#include "surface_mesh_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <vector>

#include <catch2/catch.hpp>

#include "alpha/predicates.hpp"

namespace testing {

using alpha::Index;
using alpha::Vec3;

std::string SurfaceReport::summary() const {
  std::ostringstream s;
  s << "boundary edges " << boundary_edges << ", non-manifold edges " << nonmanifold_edges << ", misoriented edges "
    << misoriented_edges << ", non-manifold vertices " << nonmanifold_vertices << ", degenerate " << degenerate_triangles
    << ", components " << components << ", area " << area << ", volume " << volume;
  return s.str();
}

alpha::SurfaceMesh read_off(const std::string& path) {
  std::ifstream in(path);
  std::string magic;
  std::size_t vertices = 0, faces = 0, edges = 0;
  in >> magic >> vertices >> faces >> edges;
  REQUIRE(magic == "OFF");
  alpha::SurfaceMesh mesh;
  mesh.points.resize(vertices);
  for (Vec3& p : mesh.points) in >> p.x >> p.y >> p.z;
  mesh.triangles.resize(faces);
  for (auto& t : mesh.triangles) {
    int corners = 0;
    in >> corners >> t[0] >> t[1] >> t[2];
    REQUIRE(corners == 3);
  }
  REQUIRE(in);
  return mesh;
}

SurfaceReport surface_report(const alpha::SurfaceMesh& mesh) {
  SurfaceReport out;
  const auto& tris = mesh.triangles;
  std::map<std::pair<Index, Index>, std::vector<std::size_t>> edges;  // undirected -> directed uses (corner ids)
  for (std::size_t f = 0; f < tris.size(); ++f) {
    const auto& t = tris[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) ++out.degenerate_triangles;
    for (int k = 0; k < 3; ++k) edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}].push_back(3 * f + k);
    const Vec3 a = mesh.points[t[0]], b = mesh.points[t[1]], c = mesh.points[t[2]];
    out.area += alpha::triangle_area(a, b, c);
    out.volume += alpha::dot(a, alpha::cross(b, c)) / 6;
  }
  // Fans: corners of one vertex joined through manifold edges.
  std::vector<std::size_t> parent(3 * tris.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&](std::size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  std::vector<std::size_t> face_parent(tris.size());
  std::iota(face_parent.begin(), face_parent.end(), std::size_t(0));
  const auto find_face = [&](std::size_t f) {
    while (face_parent[f] != f) f = face_parent[f] = face_parent[face_parent[f]];
    return f;
  };
  const auto next = [](std::size_t c) { return c - c % 3 + (c + 1) % 3; };
  const auto vertex = [&](std::size_t c) { return tris[c / 3][c % 3]; };
  for (const auto& [e, uses] : edges) {
    if (uses.size() == 1) ++out.boundary_edges;
    if (uses.size() > 2) ++out.nonmanifold_edges;
    if (uses.size() != 2) continue;
    const std::size_t c = uses[0], d = uses[1];
    if (vertex(c) != vertex(next(d))) {
      ++out.misoriented_edges;
      continue;
    }
    parent[find(c)] = find(next(d));
    parent[find(next(c))] = find(d);
    face_parent[find_face(c / 3)] = find_face(d / 3);
  }
  std::unordered_map<Index, std::size_t> fans;
  for (std::size_t c = 0; c < parent.size(); ++c)
    if (find(c) == c) ++fans[vertex(c)];
  for (const auto& [v, n] : fans) out.nonmanifold_vertices += n > 1;
  for (std::size_t f = 0; f < tris.size(); ++f) out.components += find_face(f) == f;
  return out;
}

namespace {

// Exact predicates on the points as floats (what a file holds).
struct Exact {
  alpha::Kernel k{nullptr, nullptr};
  int orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return k.orient3d(a, b, c, d); }
  // orient2d in the coordinate plane normal to `axis`, as orient3d with a
  // point lifted by exactly 1 along it.
  int orient2(const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
    Vec3 d = a;
    (axis == 0 ? d.x : axis == 1 ? d.y : d.z) += 1;
    return orient(a, b, c, d);
  }
  bool segments_2d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, int axis) {
    const int s1 = orient2(a, b, c, axis), s2 = orient2(a, b, d, axis), s3 = orient2(c, d, a, axis),
              s4 = orient2(c, d, b, axis);
    if (s1 * s2 > 0 || s3 * s4 > 0) return false;
    if (s1 == 0 && s2 == 0) {  // collinear: overlap along the coordinate they spread most in
      const Vec3 e = b - a, f = d - c;
      const double spread[3] = {std::fabs(e.x) + std::fabs(f.x), std::fabs(e.y) + std::fabs(f.y),
                                std::fabs(e.z) + std::fabs(f.z)};
      int u = axis == 0 ? 1 : 0;
      for (int w = 0; w < 3; ++w)
        if (w != axis && spread[w] > spread[u]) u = w;
      const auto co = [u](const Vec3& p) { return u == 0 ? p.x : u == 1 ? p.y : p.z; };
      return std::min(co(a), co(b)) <= std::max(co(c), co(d)) && std::min(co(c), co(d)) <= std::max(co(a), co(b));
    }
    return true;
  }
  bool point_in_triangle_2d(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
    const int s1 = orient2(a, b, p, axis), s2 = orient2(b, c, p, axis), s3 = orient2(c, a, p, axis);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  }
  // Whether the closed segment ab meets the closed triangle pqr.
  bool segment_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r) {
    const int sa = orient(p, q, r, a), sb = orient(p, q, r, b);
    if (sa * sb > 0) return false;
    if (sa == 0 && sb == 0) {
      const Vec3 n = alpha::cross(q - p, r - p);
      const double m[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
      const int axis = m[0] >= m[1] && m[0] >= m[2] ? 0 : m[1] >= m[2] ? 1 : 2;
      return point_in_triangle_2d(a, p, q, r, axis) || segments_2d(a, b, p, q, axis) ||
             segments_2d(a, b, q, r, axis) || segments_2d(a, b, r, p, axis);
    }
    const int s1 = orient(a, b, p, q), s2 = orient(a, b, q, r), s3 = orient(a, b, r, p);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  }
};

bool bad_pair(Exact& ex, const alpha::SurfaceMesh& m, const std::array<Index, 3>& s, const std::array<Index, 3>& t) {
  const auto P = [&](Index i) { return m.points[i]; };
  int shared = 0;
  for (Index a : s) shared += a == t[0] || a == t[1] || a == t[2];
  if (shared == 0) {
    for (int k = 0; k < 3; ++k) {
      if (ex.segment_triangle(P(s[k]), P(s[(k + 1) % 3]), P(t[0]), P(t[1]), P(t[2]))) return true;
      if (ex.segment_triangle(P(t[k]), P(t[(k + 1) % 3]), P(s[0]), P(s[1]), P(s[2]))) return true;
    }
    return false;
  }
  // The vertices of each triangle not in the other.
  const auto rest = [](const std::array<Index, 3>& x, const std::array<Index, 3>& y) {
    std::vector<Index> out;
    for (Index a : x)
      if (a != y[0] && a != y[1] && a != y[2]) out.push_back(a);
    return out;
  };
  const std::vector<Index> rs = rest(s, t), rt = rest(t, s);
  if (shared == 3) return true;  // the same triangle twice
  if (shared == 2) {  // folded onto each other: coplanar, on the same side of the shared edge
    std::vector<Index> e;
    for (Index a : s)
      if (a == t[0] || a == t[1] || a == t[2]) e.push_back(a);
    const Vec3 a = P(e[0]), b = P(e[1]), c = P(rs[0]), d = P(rt[0]);
    if (ex.orient(a, b, c, d) != 0) return false;
    const Vec3 n = alpha::cross(b - a, c - a);
    const double m[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
    const int axis = m[0] >= m[1] && m[0] >= m[2] ? 0 : m[1] >= m[2] ? 1 : 2;
    return ex.orient2(a, b, c, axis) * ex.orient2(a, b, d, axis) > 0;
  }
  // One shared vertex: the opposite edge of each must miss the other.
  return ex.segment_triangle(P(rs[0]), P(rs[1]), P(t[0]), P(t[1]), P(t[2])) ||
         ex.segment_triangle(P(rt[0]), P(rt[1]), P(s[0]), P(s[1]), P(s[2]));
}

}  // namespace

std::size_t intersecting_pairs(const alpha::SurfaceMesh& in) {
  alpha::SurfaceMesh mesh = in;  // as a file holds it: single precision
  for (Vec3& p : mesh.points) p = {double(float(p.x)), double(float(p.y)), double(float(p.z))};
  const auto& tris = mesh.triangles;
  if (tris.empty()) return 0;
  double mean = 0;
  for (const auto& t : tris) mean += alpha::norm(mesh.points[t[1]] - mesh.points[t[0]]);
  const double cell = std::max(2 * mean / double(tris.size()), 1e-9);
  using Key = std::array<long long, 3>;
  const auto key = [&](double x, double y, double z) {
    return Key{(long long)std::floor(x / cell), (long long)std::floor(y / cell), (long long)std::floor(z / cell)};
  };
  std::map<Key, std::vector<std::size_t>> grid;
  std::vector<std::pair<Key, Key>> box(tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f) {
    Vec3 lo = mesh.points[tris[f][0]], hi = lo;
    for (Index v : tris[f]) {
      const Vec3 p = mesh.points[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    box[f] = {key(lo.x, lo.y, lo.z), key(hi.x, hi.y, hi.z)};
    for (long long x = box[f].first[0]; x <= box[f].second[0]; ++x)
      for (long long y = box[f].first[1]; y <= box[f].second[1]; ++y)
        for (long long z = box[f].first[2]; z <= box[f].second[2]; ++z) grid[{x, y, z}].push_back(f);
  }
  Exact ex;
  std::size_t bad = 0;
  for (const auto& [k, list] : grid)
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const std::size_t f = list[i], g = list[j];
        // Test each pair once: in the first cell both boxes share.
        Key first;
        for (int a = 0; a < 3; ++a) first[a] = std::max(box[f].first[a], box[g].first[a]);
        if (first != k) continue;
        bool overlap = true;
        for (int a = 0; a < 3; ++a) overlap = overlap && box[f].first[a] <= box[g].second[a] && box[g].first[a] <= box[f].second[a];
        if (overlap && bad_pair(ex, mesh, tris[f], tris[g])) ++bad;
      }
  return bad;
}

}  // namespace testing
