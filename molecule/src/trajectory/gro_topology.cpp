// SPDX-License-Identifier: Apache-2.0
#include "trajectory/gro_topology.hpp"

#include <cctype>
#include <charconv>
#include <fmt/format.h>

#include "molecule/structure.hpp"

namespace molecule {
namespace {

std::string trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// "CA" of an ion residue CA is calcium; otherwise the name's first letter.
std::string element_of(const std::string& atom, const std::string& residue) {
  if (atom == residue && atom.size() <= 2) return atom;
  for (char c : atom)
    if (std::isalpha(static_cast<unsigned char>(c))) return std::string(1, c);
  return "X";
}

}  // namespace

bool is_gro_file(const std::string& path) { return path.size() > 4 && path.compare(path.size() - 4, 4, ".gro") == 0; }

std::string gro_as_pdb(std::string_view gro, const std::string& name) {
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start < gro.size();) {
    const std::size_t end = std::min(gro.find('\n', start), gro.size());
    lines.push_back(gro.substr(start, end - start));
    start = end + 1;
  }
  const auto fail = [&](std::size_t line, const std::string& what, alpha::ErrorKind kind) -> void {
    throw StructureError(name + ": line " + std::to_string(line) + ": " + what, kind);
  };
  if (lines.size() < 2)
    fail(lines.size() + 1, "a .gro file needs a title and an atom count", alpha::ErrorKind::BadInput);
  std::size_t atoms = 0;
  const std::string count = trimmed(lines[1]);
  if (std::from_chars(count.data(), count.data() + count.size(), atoms).ec != std::errc() || atoms == 0)
    fail(2, "not an atom count: '" + count + "'", alpha::ErrorKind::BadInput);
  if (lines.size() < atoms + 2)
    fail(lines.size() + 1,
         "truncated: " + std::to_string(atoms) + " atoms announced, " + std::to_string(lines.size() - 2) +
             " lines follow",
         alpha::ErrorKind::BadInput);
  std::string pdb;
  for (std::size_t i = 0; i < atoms; ++i) {
    const std::string_view l = lines[i + 2];
    if (l.size() < 44) fail(i + 3, "an atom line needs 44 columns", alpha::ErrorKind::BadInput);
    int residue = 0;
    double x[3];
    const std::string resnum = trimmed(l.substr(0, 5));
    if (std::from_chars(resnum.data(), resnum.data() + resnum.size(), residue).ec != std::errc())
      fail(i + 3, "residue number '" + resnum + "'", alpha::ErrorKind::BadInput);
    for (int d = 0; d < 3; ++d) {
      const std::string v = trimmed(l.substr(20 + 8 * d, 8));
      if (std::from_chars(v.data(), v.data() + v.size(), x[d]).ec != std::errc())
        fail(i + 3, "coordinate '" + v + "'", alpha::ErrorKind::BadInput);
    }
    const std::string res = trimmed(l.substr(5, 5)), atom = trimmed(l.substr(10, 5));
    pdb += fmt::format("ATOM  {:5d} {:<4.4} {:>3.3} A{:4d}    {:8.3f}{:8.3f}{:8.3f}  1.00  0.00          {:>2.2}\n",
                       (i + 1) % 100000, atom.size() < 4 ? " " + atom : atom, res, residue % 10000, 10 * x[0],
                       10 * x[1], 10 * x[2], element_of(atom, res));
  }
  return pdb + "END\n";
}

}  // namespace molecule
