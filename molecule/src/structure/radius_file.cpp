// SPDX-License-Identifier: Apache-2.0
#include "molecule/radius_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "alpha/error.hpp"
#include "molecule/radii.hpp"

namespace molecule {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// '?' one character, '*' any run (greedy with backtracking).
bool matches(std::string_view pattern, std::string_view name) {
  if (pattern.empty()) return name.empty();
  if (pattern[0] == '*') {
    for (std::size_t k = 0; k <= name.size(); ++k)
      if (matches(pattern.substr(1), name.substr(k))) return true;
    return false;
  }
  return !name.empty() && (pattern[0] == '?' || pattern[0] == name[0]) && matches(pattern.substr(1), name.substr(1));
}

// HOLE compares blank-padded names ("CA" is "CA  " against "C???"), so
// the name and the pattern are padded alike ("CB" matches "CB"); a
// pattern with '*' is matched against the bare name.
bool matches_padded(std::string pattern, std::string name, std::size_t width) {
  if (pattern.find('*') != std::string::npos) return matches(pattern, name);
  width = std::max({width, pattern.size(), name.size()});
  pattern.resize(width, ' ');
  name.resize(width, ' ');
  return matches(pattern, name);
}

int specificity(const std::string& pattern) {
  return int(std::count_if(pattern.begin(), pattern.end(), [](char c) { return c != '?' && c != '*'; }));
}

}  // namespace

RadiusFile parse_radius_file(std::string_view text, const std::string& path) {
  RadiusFile out;
  out.path = path;
  std::istringstream in{std::string(text)};
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    if (f.empty() || f[0][0] == '#') continue;
    const std::string key = upper(f[0]);
    const bool hole = key == "VDWR";
    if (!hole && (key == "BOND" || key.rfind("REMARK", 0) == 0)) continue;
    const std::size_t expected = hole ? 4 : 3;
    const auto fail = [&](const std::string& problem, alpha::ErrorKind kind) {
      throw alpha::Error(path + ": line " + std::to_string(number) + ": " + problem, kind);
    };
    if (f.size() != expected)
      fail(hole ? "expected VDWR ATOM RESIDUE RADIUS" : "expected RESIDUE ATOM RADIUS or element SYMBOL RADIUS",
           alpha::ErrorKind::BadInput);
    const std::string& value = f.back();
    double r = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), r);
    if (ec != std::errc() || end != value.data() + value.size() || !std::isfinite(r) || r < 0)
      fail("radius '" + value + "' is not a number >= 0", alpha::ErrorKind::BadInput);
    if (!hole && key == "ELEMENT") {
      out.elements.emplace_back(upper(f[1]), r);
      continue;
    }
    RadiusRule rule;
    rule.residue = upper(hole ? f[2] : f[0]);
    rule.atom = upper(f[1]);
    rule.radius = r;
    rule.specificity = specificity(rule.residue) + specificity(rule.atom);
    out.rules.push_back(rule);
  }
  return out;
}

RadiusFile read_radius_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw alpha::Error(path + ": cannot read the radius file", alpha::ErrorKind::BadInput);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_radius_file(text.str(), path);
}

std::size_t apply_radius_file(const RadiusFile& file, std::vector<Atom>& atoms) {
  std::size_t fallback = 0;
  for (Atom& a : atoms) {
    const std::string residue = upper(a.residue_name), atom = upper(a.name);
    const RadiusRule* best = nullptr;
    for (const RadiusRule& r : file.rules)
      if ((!best || r.specificity > best->specificity) && matches_padded(r.residue, residue, 3) &&
          matches_padded(r.atom, atom, 4))
        best = &r;
    if (best) {
      a.radius = best->radius;
      continue;
    }
    const std::string element = upper(a.element);
    const auto e = std::find_if(file.elements.begin(), file.elements.end(),
                                [&](const auto& x) { return x.first == element; });
    if (e != file.elements.end()) {
      a.radius = e->second;
    } else {
      a.radius = atom_radius("", "", a.element).value;
      ++fallback;
    }
  }
  return fallback;
}

}  // namespace molecule
