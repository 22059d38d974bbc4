// SPDX-License-Identifier: Apache-2.0
// Writing triangle meshes (alpha shape boundaries, later pockets) to the
// files that mesh viewers such as MeshLab open, through OpenMesh.
//
// The format follows the file extension (case-insensitive):
//
//   .ply  binary little-endian PLY; vertex and face colours, and the
//         per-vertex integer property `site` when given (written here,
//         the bytes OpenMesh's writer gives, in a twentieth of its time)
//   .off  ASCII OFF; vertex colours, else face colours
//   .obj  ASCII Wavefront OBJ; face colours as materials of a companion
//         .mtl file of the same name (written here, not by OpenMesh,
//         whose OBJ writer makes the .mtl only when it writes to a named
//         file itself, which would break all-or-nothing writes)
//   .stl  binary STL (with per-face normals); no colours
//
// Coordinates are single precision in every format (OpenMesh's writers
// store floats; ASCII files print 9 significant digits, enough to read the
// float back exactly): about 1e-7 relative, plenty for viewing.
//
// The file appears whole or not at all: the mesh is written to a temporary
// file in the same directory, which is renamed to the requested name only
// once it is complete (and removed on any failure). An existing file of that
// name is replaced.
//
// Errors (unknown extension, a directory that does not exist or is not
// writable, a failed write) throw alpha::Error with a one-line message that
// names the file.
//
// OpenMesh holds only manifold meshes. Where the triangles do not form one
// (two alpha-shape tetrahedra meeting at an edge or a vertex only), a point
// is written once per fan of triangles around it (triangles joined through
// pairs of triangles of opposite directions around each edge), so the file
// holds every triangle and some points more than once (same coordinates).
// The boundary of a union of tetrahedra comes out a closed 2-manifold
// (mesh_export.cpp, corner_copies, says how pinched edges are resolved).
//
// While writing, OpenMesh's own log streams (omerr, omlog, omout) are
// silenced. OpenMesh's writers and streams are process-wide, so the
// OpenMesh part of these calls is serialised by a lock: threads may write
// meshes at the same time (one at a time through OpenMesh).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "alpha/geometry.hpp"

namespace molecule {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct TriangleMesh {
  std::vector<alpha::Vec3> points;  // may include points no triangle uses
  // Indices into points, counter-clockwise seen from outside: the normal
  // (b-a)x(c-a) points out.
  std::vector<std::array<alpha::Index, 3>> triangles;
  // Empty, or one colour per triangle (PLY, OFF, OBJ).
  std::vector<Rgb> face_colors;
  // Empty, or one per point: a colour (PLY, OFF) and an integer written as
  // the PLY vertex property `site`.
  std::vector<Rgb> vertex_colors;
  std::vector<int> vertex_sites;
  // Whether the triangles are known to form a 2-manifold (every vertex one
  // fan): then no point needs copies, and the search for them is skipped.
  bool manifold = false;
};

struct MeshFileInfo {
  std::string format;  // "ply", "off", "obj" or "stl"
  bool binary = false;
  std::size_t vertices = 0;             // vertices in the file
  std::size_t faces = 0;                // triangles in the file
  std::size_t duplicated_vertices = 0;  // vertices - points used: copies at non-manifold places
  bool colors = false;                  // whether colours were written
};

// Throws alpha::Error, as write_mesh_file would, when the extension of
// path is not a supported format, path is a directory, or its directory is
// missing or not writable: lets a caller fail before it computes the mesh.
void check_mesh_file_name(const std::string& path);

// Writes mesh to path, in the format of its extension. Only the points that
// some triangle uses are written, in increasing index order (copies of a
// point next to each other), so a caller can pass all points of a
// triangulation. Throws alpha::Error for an unknown extension, an index out
// of range, a triangle with a repeated vertex, a colour count that does not
// match, or a failed write.
MeshFileInfo write_mesh_file(const std::string& path, const TriangleMesh& mesh);

// What write_mesh_file would write to path, in memory (path only chooses
// the format and names the file in errors), and what it would return. For
// callers that write several files as one (a StagedDirectory).
struct MeshFileContent {
  std::string bytes;
  MeshFileInfo info;
  // A companion file to write with it (an OBJ's .mtl): its path (path's
  // with another extension) and content; empty if none.
  std::string companion_path, companion;
};
MeshFileContent mesh_file_content(const std::string& path, const TriangleMesh& mesh);

}  // namespace molecule
