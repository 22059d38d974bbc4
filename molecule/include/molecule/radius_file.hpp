// SPDX-License-Identifier: Apache-2.0
// Atomic radii from a file (`alphapocket pockets --radii FILE`), because
// tunnel radii are compared across tools with their radius sets.
//
// One rule per line; blank lines and lines starting with '#' are skipped.
//   RESIDUE ATOM RADIUS     e.g. "ALA CB 1.88", "* C* 1.70", "HOH O 1.40"
//   element SYMBOL RADIUS   e.g. "element C 1.70" (the fallback by element)
//   VDWR ATOM RESIDUE RADIUS  HOLE's .rad format, e.g. "VDWR C??? ??? 1.85";
//                             HOLE's other records (BOND, remark, ...) are skipped
// Patterns: '?' matches any one character (HOLE pads atom names to 4 and
// residue names to 3 characters with blanks, so "C???" matches "CA" and
// "CB"), '*' any run of characters; names are compared in upper case. An
// atom gets the radius of the most specific rule matching its residue and
// atom name (the fewest wildcard characters; ties: the first in the file),
// else that of its element's `element` rule, else the built-in van der
// Waals radius of its element (molecule/radii.hpp), which is counted.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "molecule/structure.hpp"

namespace molecule {

struct RadiusRule {
  std::string residue, atom;  // patterns, upper case
  double radius = 0;
  int specificity = 0;  // characters that are no wildcard
};

struct RadiusFile {
  std::string path;
  std::vector<RadiusRule> rules;
  std::vector<std::pair<std::string, double>> elements;  // upper-case symbol, radius
};

// Throws alpha::Error "<path>: line N: <problem>" for a missing file or a
// malformed line (not three fields, a radius that is not a finite number >= 0).
RadiusFile read_radius_file(const std::string& path);
RadiusFile parse_radius_file(std::string_view text, const std::string& path);

// Sets every atom's radius from the file; returns how many atoms fell back
// to the built-in element radius.
std::size_t apply_radius_file(const RadiusFile& file, std::vector<Atom>& atoms);

}  // namespace molecule
