// SPDX-License-Identifier: Apache-2.0
// The files the HTML pages need beyond their own data.
//
// The pages' own scripts and styles (report.js, report.css, index.js,
// index.css in the source tree's report_assets/) are compiled in, so that
// index.html, which needs nothing else, is written by every build.
//
// report.html needs Mol* too: its prebuilt viewer from npm (molstar,
// build/viewer/molstar.js and molstar.css), read at run time and copied
// into viewer/ beside the page with report.js and report.css, so that the
// output directory can be zipped and opened anywhere. Where Mol* is looked
// for, first found wins:
//   $ALPHAPOCKET_MOLSTAR (a directory), and only there when it is set
//   <executable's directory>/../share/alphapocket/viewer   (installed)
//   the source tree's report_assets/node_modules/molstar/build/viewer
//   (`npm ci` in report_assets/ installs it)
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace molecule {

inline constexpr const char* kViewerDir = "viewer";

// The text of a page's own file: "report.js", "report.css", "index.js" or
// "index.css" (throws alpha::Error, Misuse, for another name).
const std::string& page_asset(std::string_view name);

// (name in viewer/, where it is) of Mol*'s files. Throws alpha::Error
// (BadInput) with missing_viewer_assets()'s line when Mol* is not found.
std::vector<std::pair<std::string, std::filesystem::path>> molstar_files();

// (name in viewer/, its bytes), every file report.html loads: Mol*'s and
// report.js, report.css. Throws alpha::Error (BadInput) as molstar_files()
// does, or when a file cannot be read.
std::vector<std::pair<std::string, std::string>> viewer_files();

// Empty when Mol* is found, else one line naming where it was looked for
// and how to install it.
std::string missing_viewer_assets();

}  // namespace molecule
