// SPDX-License-Identifier: Apache-2.0
#include "molecule/residues.hpp"

#include <algorithm>
#include <tuple>

#include "alpha/error.hpp"

namespace molecule {
namespace {

// Residue identity: chain, number, insertion code and name.
auto residue_key(const Atom& a) { return std::tie(a.chain, a.seq_num, a.icode, a.residue_name); }

}  // namespace

std::string residue_id(const Atom& a) {
  return a.chain + ':' + a.residue_name + ':' + std::to_string(a.seq_num) + icode_text(a.icode);
}

std::vector<alpha::Index> residues_of(const std::vector<Atom>& atoms, const std::vector<alpha::Index>& indices) {
  for (const alpha::Index i : indices)
    if (i >= atoms.size()) alpha::fail("atom index " + std::to_string(i) + " out of range", alpha::ErrorKind::Misuse);
  // By residue, then file order: the first of each run is its residue's first atom.
  std::vector<alpha::Index> by_residue = indices;
  std::sort(by_residue.begin(), by_residue.end(), [&](alpha::Index a, alpha::Index b) {
    return std::tuple_cat(residue_key(atoms[a]), std::tie(a)) < std::tuple_cat(residue_key(atoms[b]), std::tie(b));
  });
  std::vector<alpha::Index> first;
  for (std::size_t k = 0; k < by_residue.size(); ++k)
    if (k == 0 || residue_key(atoms[by_residue[k - 1]]) != residue_key(atoms[by_residue[k]]))
      first.push_back(by_residue[k]);
  std::sort(first.begin(), first.end());
  return first;
}

}  // namespace molecule
