// SPDX-License-Identifier: Apache-2.0
#include "molecule/pocket_run.hpp"

#include "molecule/radii.hpp"

namespace molecule {

std::string PocketRun::mesh_format() const { return meshes ? options.mesh_format : std::string(); }

std::string PocketRun::radii() const {
  return options.radii_file.empty() ? std::string(kRadiusTable) : options.radii_file;
}

}  // namespace molecule
