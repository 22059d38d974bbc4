// SPDX-License-Identifier: Apache-2.0
// The structure reader on arbitrary bytes: PDB, mmCIF and gzip (the format
// is found from the content). Each input is read twice, with the default
// selection and with everything kept. Properties: an error is a
// StructureError with a one-line message naming the file; a result holds at
// least min_atoms atoms, each with a finite position and a positive radius.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "molecule/structure.hpp"

namespace {

void read(std::string_view bytes, const molecule::StructureOptions& options) {
  static const std::string name = "fuzz.pdb";
  try {
    const molecule::Structure s = molecule::parse_structure(bytes, name, options);
    fuzz::check(s.atoms.size() >= options.min_atoms, "fewer atoms than min_atoms");
    fuzz::check(s.report.kept == s.atoms.size(), "report.kept differs from the atoms");
    for (const molecule::Atom& a : s.atoms) {
      fuzz::check(std::isfinite(a.position.x) && std::isfinite(a.position.y) && std::isfinite(a.position.z),
                  "an atom position is not finite", a.name);
      fuzz::check(std::isfinite(a.radius) && a.radius > 0, "an atom radius is not positive", a.name);
    }
    for (const molecule::HeteroGroup& g : s.hetero_groups)
      fuzz::check(!g.atoms.empty(), "a hetero group without atoms", g.residue_name);
  } catch (const molecule::StructureError& e) {
    fuzz::check_message(e.what(), name);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  read(bytes, {});
  molecule::StructureOptions all;
  all.keep_hydrogens = all.keep_waters = all.keep_hetero = true;
  all.min_atoms = 1;
  read(bytes, all);
  return 0;
}
