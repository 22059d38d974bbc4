// SPDX-License-Identifier: Apache-2.0
#include "outputs/meshlab_project.hpp"

namespace molecule {

std::string meshlab_project(const std::vector<std::string>& files) {
  std::string out = "<!DOCTYPE MeshLabDocument>\n<MeshLabProject>\n <MeshGroup>\n";
  for (const std::string& f : files)
    out += "  <MLMesh label=\"" + f + "\" filename=\"" + f +
           "\" visible=\"1\">\n   <MLMatrix44>\n1 0 0 0 \n0 1 0 0 \n0 0 1 0 \n0 0 0 1 \n</MLMatrix44>\n  </MLMesh>\n";
  return out + " </MeshGroup>\n <RasterGroup/>\n</MeshLabProject>\n";
}

}  // namespace molecule
