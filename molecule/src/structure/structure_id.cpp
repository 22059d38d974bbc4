// SPDX-License-Identifier: Apache-2.0
#include "structure/structure_id.hpp"

#include <filesystem>
#include <regex>

namespace molecule {

std::string structure_id(const std::string& path) {
  static const std::regex kExtension(R"((\.(pdb|ent|cif|mmcif))?(\.gz)?$)", std::regex::icase);
  const std::string id = std::regex_replace(std::filesystem::path(path).filename().string(), kExtension, "");
  return id.empty() ? std::string("structure") : id;
}

}  // namespace molecule
