// SPDX-License-Identifier: Apache-2.0
#include "util/temporary_paths.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace molecule {

void TemporaryPaths::erase(const std::string& path) {
  paths_.erase(std::remove(paths_.begin(), paths_.end(), path), paths_.end());
}

void TemporaryPaths::abandon() {
  mutex_.lock();  // never unlocked: writers stop here
  for (const std::string& p : paths_) {
    std::error_code ec;
    std::filesystem::remove_all(p, ec);
  }
  paths_.clear();
}

}  // namespace molecule
