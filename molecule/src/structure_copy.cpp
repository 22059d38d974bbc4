// SPDX-License-Identifier: Apache-2.0
#include "molecule/structure_copy.hpp"

#include <cctype>
#include <cstdio>
#include <set>
#include <string_view>
#include <tuple>

#include "molecule/safe_text.hpp"

namespace molecule {
namespace {

// A CIF value: a bare word of printable ASCII without whitespace (other
// bytes become '_'), '.' when empty, single-quoted where a bare word would
// be read as something else (a data name, a reserved word, a quote or
// comment); with no whitespace inside, the quotes end where meant.
std::string cif_value(std::string_view text) {
  std::string v = printable_ascii(text, " ", '_');
  if (v.empty()) return ".";
  std::string lower;
  for (const char c : v) lower += char(std::tolower(static_cast<unsigned char>(c)));
  const bool reserved = lower.rfind("data_", 0) == 0 || lower.rfind("loop_", 0) == 0 ||
                        lower.rfind("save_", 0) == 0 || lower.rfind("global_", 0) == 0 ||
                        lower.rfind("stop_", 0) == 0 || v == "." || v == "?";
  if (!reserved && std::string_view("_#$'\"[];").find(v[0]) == std::string_view::npos) return v;
  for (char& c : v)
    if (c == '\'') c = '_';
  return "'" + v + "'";
}

void atom_line(std::string& out, std::size_t id, const Atom& a, bool hetero) {
  char xyz[96];
  std::snprintf(xyz, sizeof xyz, "%.3f %.3f %.3f %.2f %.2f", a.position.x, a.position.y, a.position.z,
                double(a.occupancy), double(a.b_factor));
  const std::string number = std::to_string(a.seq_num);
  out += std::string(hetero ? "HETATM " : "ATOM ") + std::to_string(id) + ' ' + cif_value(a.element) + ' ' +
         cif_value(a.name) + " . " + cif_value(a.residue_name) + ' ' + cif_value(a.chain) + ' ' + number + ' ' +
         (a.icode ? cif_value(std::string(1, a.icode)) : std::string("?")) + ' ' + xyz + ' ' + number + ' ' +
         cif_value(a.chain) + " 1\n";
}

}  // namespace

StructureCopy structure_copy(const Structure& structure, const std::string& title) {
  StructureCopy copy;
  std::string& out = copy.cif;
  out += "# " + printable_ascii(title) + "\n";
  out += "data_structure\nloop_\n";
  for (const char* item : {"group_PDB", "id", "type_symbol", "label_atom_id", "label_alt_id", "label_comp_id", "label_asym_id",
                           "label_seq_id", "pdbx_PDB_ins_code", "Cartn_x", "Cartn_y", "Cartn_z", "occupancy",
                           "B_iso_or_equiv", "auth_seq_id", "auth_asym_id", "pdbx_PDB_model_num"})
    out += std::string("_atom_site.") + item + "\n";

  using Key = std::tuple<std::string, int, char, std::string>;
  const auto key = [](const auto& x) { return Key{x.chain, x.seq_num, x.icode, x.residue_name}; };
  std::set<Key> kept_groups;
  for (const HeteroGroup& g : structure.hetero_groups)
    if (g.kept) kept_groups.insert(key(g));
  std::size_t id = 0;
  for (const Atom& a : structure.atoms) {
    const bool ligand = kept_groups.count(key(a)) > 0;
    atom_line(out, ++id, a, a.hetero || ligand);
    if (ligand) copy.ligand_ids.push_back(id);
  }
  for (const HeteroGroup& g : structure.hetero_groups) {
    if (g.kept) continue;
    for (const Atom& a : g.atoms) {
      atom_line(out, ++id, a, true);
      copy.ligand_ids.push_back(id);
    }
  }
  return copy;
}

}  // namespace molecule
