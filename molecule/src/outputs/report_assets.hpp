// SPDX-License-Identifier: Apache-2.0
// The viewer files report.html loads (report_page.hpp), copied into
// viewer/ beside it so that the output directory can be zipped and opened
// anywhere: Mol*'s prebuilt viewer (npm molstar, build/viewer/molstar.js
// and molstar.css) and the page's own script and style (report.js,
// report.css, from the source tree's report_assets/).
//
// Where they are looked for, first found wins:
//   <executable's directory>/../share/alphapocket/viewer   (installed)
//   the source tree's report_assets/, Mol* in its node_modules/ (`npm ci`
//   in report_assets/ installs it)
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace molecule {

inline constexpr const char* kViewerDir = "viewer";

// (name in viewer/, its bytes), every file the pages load. Throws
// alpha::Error with one line naming where they were looked for and how to
// install them when one is missing.
std::vector<std::pair<std::string, std::string>> viewer_files();

// The same check without throwing: empty when every file is there, else
// the error's message.
std::string missing_viewer_assets();

}  // namespace molecule
