// SPDX-License-Identifier: Apache-2.0
// User-controlled text (file names; chain, residue and atom names; hetero
// codes) on its way into a script a viewer executes or a fixed-format
// file: made harmless there, so that it can never start a line, a command
// or a record of its own.
#pragma once
#include <string>
#include <string_view>

namespace molecule {

// Every byte outside printable ASCII (control characters such as a
// newline, DEL, any non-ASCII byte) and every byte of `also` becomes
// `replacement`: fit for a comment line of a script or a PDB REMARK.
inline std::string printable_ascii(std::string_view text, std::string_view also = {}, char replacement = '?') {
  std::string out(text);
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7f || also.find(c) != std::string_view::npos) c = replacement;
  }
  return out;
}

}  // namespace molecule
