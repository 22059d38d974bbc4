// SPDX-License-Identifier: Apache-2.0
// What tests of written files share: a scratch directory, reading a file
// back, and reading a mesh back through OpenMesh (what a viewer such as
// MeshLab sees) with the checks a surface must pass.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

// OpenMesh's colour property default-constructs VectorT<unsigned char, 3>
// without initializing it, which GCC reports where it is instantiated.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop

namespace testing {

// A fresh directory under the system temporary directory, removed (with
// everything in it) at the end.
class TempDir {
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }
  // Names of the files in the directory, sorted.
  std::vector<std::string> files() const;

private:
  std::filesystem::path path_;
};

std::string read_text(const std::filesystem::path& file);

using ReadMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// Reads a mesh file (REQUIREs success), with its face colours if asked.
ReadMesh read_back(const std::filesystem::path& file, bool colors = false);

// The faces are closed and consistently oriented: every edge (by vertex
// positions, so that copies of a vertex count as one) is run through as
// often in one direction as in the other; for a manifold, once each way.
bool closed_and_consistent(const ReadMesh& mesh, bool manifold = true);

// Volume enclosed by the mesh (divergence theorem): positive when the faces
// are oriented outward.
double signed_volume(const ReadMesh& mesh);

// The per-vertex integer property `site` of a binary PLY file (REQUIREs it).
std::vector<int> vertex_sites(const std::filesystem::path& file);

}  // namespace testing
