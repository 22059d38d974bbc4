// SPDX-License-Identifier: Apache-2.0
#include "mesh_checks.hpp"

#include <cstring>
#include <sstream>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <map>
#include <system_error>
#include <utility>

#include <stdlib.h>

namespace testing {

namespace fs = std::filesystem;

TempDir::TempDir() {
  std::string tmpl = (fs::temp_directory_path() / "alphapocket_test_XXXXXX").string();
  REQUIRE(::mkdtemp(tmpl.data()) != nullptr);
  path_ = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(path_, ec))  // a test may lock a directory
    fs::permissions(e.path(), fs::perms::owner_all, fs::perm_options::add, ec);
  fs::remove_all(path_, ec);
}

std::vector<std::string> TempDir::files() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ReadMesh read_back(const fs::path& file, bool colors) {
  ReadMesh mesh;
  OpenMesh::IO::Options options;
  if (colors) {
    mesh.request_face_colors();
    options += OpenMesh::IO::Options::FaceColor;
  }
  REQUIRE(OpenMesh::IO::read_mesh(mesh, file.string(), options));
  if (colors) REQUIRE(options.check(OpenMesh::IO::Options::FaceColor));
  return mesh;
}

bool closed_and_consistent(const ReadMesh& mesh, bool manifold) {
  using Key = std::array<float, 3>;
  auto key = [&](ReadMesh::VertexHandle v) {
    const auto& p = mesh.point(v);
    return Key{p[0], p[1], p[2]};
  };
  std::map<std::pair<Key, Key>, int> directed;
  for (auto f : mesh.faces()) {
    std::vector<Key> k;
    for (auto v : f.vertices()) k.push_back(key(v));
    if (k.size() != 3) return false;
    for (int i = 0; i < 3; ++i) ++directed[{k[i], k[(i + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto it = directed.find({edge.second, edge.first});
    if (it == directed.end() || it->second != count || (manifold && count != 1)) return false;
  }
  return true;
}

double signed_volume(const ReadMesh& mesh) {
  double v = 0;
  for (auto f : mesh.faces()) {
    std::vector<OpenMesh::Vec3d> p;
    for (auto vh : f.vertices()) {
      const auto& q = mesh.point(vh);
      p.emplace_back(q[0], q[1], q[2]);
    }
    v += OpenMesh::dot(p[0], OpenMesh::cross(p[1], p[2])) / 6;
  }
  return v;
}

}  // namespace testing

namespace testing {

std::vector<int> vertex_sites(const std::filesystem::path& file) {
  const std::string bytes = read_text(file);
  const std::size_t end = bytes.find("end_header\n");
  REQUIRE(end != std::string::npos);
  std::istringstream header(bytes.substr(0, end));
  std::string line;
  std::size_t vertices = 0, offset = 0, stride = 0;
  bool in_vertex = false, found = false;
  const auto size_of = [](const std::string& type) -> std::size_t {
    if (type == "float" || type == "int" || type == "float32" || type == "int32" || type == "uint") return 4;
    if (type == "uchar" || type == "char" || type == "uint8") return 1;
    if (type == "double") return 8;
    return 2;
  };
  while (std::getline(header, line)) {
    std::istringstream w(line);
    std::string a, b, c;
    w >> a >> b >> c;
    if (a == "format") REQUIRE(b == "binary_little_endian");
    if (a == "element") {
      in_vertex = b == "vertex";
      if (in_vertex) vertices = std::stoul(c);
    }
    if (a == "property" && in_vertex) {
      if (c == "site") {
        REQUIRE(b == "int");
        found = true;
        offset = stride;
      }
      stride += size_of(b);
    }
  }
  REQUIRE(found);
  std::vector<int> out(vertices);
  const char* data = bytes.data() + end + 11;
  REQUIRE(bytes.size() >= end + 11 + vertices * stride);
  for (std::size_t v = 0; v < vertices; ++v) std::memcpy(&out[v], data + v * stride + offset, 4);
  return out;
}

}  // namespace testing
