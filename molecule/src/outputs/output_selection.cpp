// SPDX-License-Identifier: Apache-2.0
#include "molecule/output_selection.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "alpha/error.hpp"

namespace molecule {
namespace {

using Item = std::pair<const char*, bool OutputSelection::*>;
constexpr std::array<Item, 7> kItems{{{"report", &OutputSelection::report},
                                      {"csv", &OutputSelection::csv},
                                      {"pml", &OutputSelection::pml},
                                      {"pdb", &OutputSelection::pdb},
                                      {"meshes", &OutputSelection::meshes},
                                      {"tunnels", &OutputSelection::tunnels},
                                      {"html", &OutputSelection::html}}};

}  // namespace

OutputSelection parse_output_selection(const std::string& list) {
  OutputSelection s{false, false, false, false, false, false, false};
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string item = list.substr(begin, end - begin);
    const auto it = std::find_if(kItems.begin(), kItems.end(), [&](const Item& k) { return item == k.first; });
    if (item == "all")
      for (const Item& k : kItems) s.*k.second = true;
    else if (it != kItems.end())
      s.*it->second = true;
    else
      alpha::fail("unknown output '" + item + "' (report, csv, pml, pdb, meshes, tunnels, html or all)",
                  alpha::ErrorKind::BadInput);
    begin = end + 1;
  }
  return s;
}

std::string output_list(const OutputSelection& selection) {
  std::string list;
  for (const Item& k : kItems) {
    if (!(selection.*k.second)) continue;
    if (!list.empty()) list += ',';
    list += k.first;
  }
  return list;
}

}  // namespace molecule
