// SPDX-License-Identifier: Apache-2.0
// A MeshLab project (.mlp) that opens several mesh files at once, as
// MeshLab 2020.09 writes them: file names relative to the project's
// directory, each mesh in place (identity matrix), all visible.
#pragma once
#include <string>
#include <vector>

namespace molecule {

// Its name in the meshes/ directory of `alphapocket pockets`.
inline constexpr const char* kMeshlabProject = "meshes/meshlab.mlp";

// files: names relative to the project's directory (no XML escaping
// needed: alphapocket's own names).
std::string meshlab_project(const std::vector<std::string>& files);

}  // namespace molecule
