// SPDX-License-Identifier: Apache-2.0
#include "outputs/report_assets.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "alpha/error.hpp"

namespace molecule {
namespace {

namespace fs = std::filesystem;

using Files = std::vector<std::pair<std::string, fs::path>>;

constexpr const char* kFiles[] = {"molstar.js", "molstar.css", "report.js", "report.css", "index.js", "index.css"};

struct Search {
  Files files;         // empty: not found
  std::string looked;  // the directories looked in
};

Search search() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path installed = ec ? fs::path() : exe.parent_path().parent_path() / "share/alphapocket" / kViewerDir;
  const fs::path source = ALPHAPOCKET_REPORT_ASSETS;
  Search out;
  for (const bool in_source : {false, true}) {
    const fs::path& dir = in_source ? source : installed;
    if (dir.empty()) continue;
    out.looked += (out.looked.empty() ? "" : " or ") + dir.string();
    Files files;
    for (const std::string name : kFiles) {
      const bool from_npm = in_source && name.rfind("molstar.", 0) == 0;
      const fs::path file = from_npm ? dir / "node_modules/molstar/build/viewer" / name : dir / name;
      if (fs::is_regular_file(file, ec)) files.emplace_back(name, file);
    }
    if (files.size() == std::size(kFiles)) {
      out.files = std::move(files);
      return out;
    }
  }
  return out;
}

}  // namespace

std::string missing_viewer_assets() {
  const Search found = search();
  if (!found.files.empty()) return "";
  return "the HTML pages need Mol* and their scripts (molstar.js, molstar.css, report.js, index.js and their .css), not found in " +
         found.looked + ": run `npm ci` in report_assets/ (README.md) or leave html out of --outputs";
}

std::vector<std::pair<std::string, std::string>> viewer_files() {
  const Search found = search();
  if (found.files.empty()) alpha::fail(missing_viewer_assets());
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [name, path] : found.files) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in || !bytes) alpha::fail("cannot read " + path.string() + ": " + std::strerror(errno));
    out.emplace_back(name, bytes.str());
  }
  return out;
}

}  // namespace molecule
