// SPDX-License-Identifier: Apache-2.0
#include "outputs/structure_copy.hpp"

#include <charconv>
#include <set>
#include <string_view>
#include <tuple>

#include "util/case_insensitive.hpp"
#include "util/safe_text.hpp"

namespace molecule {
namespace {

// A CIF value: a bare word of printable ASCII without whitespace (other
// bytes become '_'), '.' when empty, single-quoted where a bare word would
// be read as something else (a data name, a reserved word, a quote or
// comment); with no whitespace inside, the quotes end where meant.
void append_cif_value(std::string& out, std::string_view text) {
  std::string v = printable_ascii(text, " ", '_');
  if (v.empty()) {
    out += '.';
    return;
  }
  bool reserved = v == "." || v == "?";
  for (const std::string_view word : {"data_", "loop_", "save_", "global_", "stop_"})
    reserved = reserved || starts_with_ci(v, word);
  if (!reserved && std::string_view("_#$'\"[];").find(v[0]) == std::string_view::npos) {
    out += v;
    return;
  }
  for (char& c : v)
    if (c == '\'') c = '_';
  out += '\'';
  out += v;
  out += '\'';
}

// The value as printf's "%.{precision}f" writes it (to_chars is that, in
// a tenth of the time).
void append_fixed(std::string& out, double value, int precision) {
  char text[400];  // the longest double in fixed notation, with 3 decimals
  out.append(text, std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, precision).ptr);
}

void atom_line(std::string& out, std::size_t id, const Atom& a, bool hetero) {
  const std::string number = std::to_string(a.seq_num);
  out += hetero ? "HETATM " : "ATOM ";
  out += std::to_string(id);
  for (const std::string_view field : {std::string_view(a.element), std::string_view(a.name)}) {
    out += ' ';
    append_cif_value(out, field);
  }
  out += " . ";
  append_cif_value(out, a.residue_name);
  out += ' ';
  append_cif_value(out, a.chain);
  out += ' ';
  out += number;
  out += ' ';
  if (a.icode)
    append_cif_value(out, std::string_view(&a.icode, 1));
  else
    out += '?';
  out += ' ';
  for (const double x : {a.position.x, a.position.y, a.position.z}) {
    append_fixed(out, x, 3);
    out += ' ';
  }
  for (const float x : {a.occupancy, a.b_factor}) {
    append_fixed(out, double(x), 2);
    out += ' ';
  }
  out += number;
  out += ' ';
  append_cif_value(out, a.chain);
  out += " 1\n";
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
