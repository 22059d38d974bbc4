// SPDX-License-Identifier: Apache-2.0
#include "molecule/structure.hpp"

// Compiled as C++17 by clang (molecule/CMakeLists.txt): no std::span or
// starts_with here.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <sstream>

#include <gemmi/cif.hpp>
#include <gemmi/mmcif.hpp>
#include <gemmi/pdb.hpp>
#include <gemmi/polyheur.hpp>
#include <gemmi/resinfo.hpp>

#include "alpha/input_file.hpp"
#include "util/case_insensitive.hpp"
#include "util/gunzip.hpp"
#include "molecule/radii.hpp"
#include "structure/format_checks.hpp"
#include "util/safe_text.hpp"

namespace molecule {
namespace {

using namespace format_checks;

// The problem may quote the file's own bytes (a record, a token): any
// control or non-ASCII byte among them becomes '?', so the message stays
// one line and prints nothing but text.
[[noreturn]] void fail(const std::string& name, const std::string& what, alpha::ErrorKind kind) {
  throw StructureError(name + ": " + printable_ascii(what), kind);
}

// A check of format_checks.hpp, whose alpha::Error becomes the reader's
// StructureError (same text and kind).
template <class Check> auto checked(Check&& check) {
  try {
    return check();
  } catch (const alpha::Error& e) {
    throw StructureError(e.what(), e.kind());
  }
}

std::string join(const std::vector<std::string>& items, std::size_t max_items) {
  std::string s;
  for (std::size_t i = 0; i < items.size() && i < max_items; ++i) s += (i ? ", " : "") + items[i];
  if (items.size() > max_items) s += ", ...";
  return s;
}

// gemmi's messages may span lines and may name the file already.
std::string one_line(std::string s, const std::string& name) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  s = printable_ascii(s);  // gemmi quotes the record, bytes and all
  while (!s.empty() && s.back() == ' ') s.pop_back();
  // Some end with ": NAME" ("Incorrect file format (perhaps it is cif not
  // pdb?): NAME"); ours start with it.
  const std::string suffix = ": " + name;
  if (s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0)
    s.erase(s.size() - suffix.size());
  return s.compare(0, name.size(), name) == 0 ? s : name + ": " + s;
}

int seq_num(const gemmi::Residue& r) { return r.seqid.num.has_value() ? *r.seqid.num : 0; }

// Whether a residue has atoms in two parts of a chain of one model: gemmi
// starts a new part at each change of chain id among the records.
bool has_split_residues(const gemmi::Structure& st) {
  for (const gemmi::Model& m : st.models) {
    std::unordered_map<std::string, std::unordered_set<gemmi::ResidueId>> residues;  // by chain
    for (const gemmi::Chain& part : m.chains) {
      std::unordered_set<gemmi::ResidueId>& seen = residues[part.name];
      for (const gemmi::Residue& r : part.residues)  // gemmi joins those within a part
        if (!seen.insert(r).second) return true;
    }
  }
  return false;
}

// Types the residues of a chain that the file left untyped (no TER record
// after them, no mmCIF entity): water by name, polymer if gemmi counts it
// as a residue of the polymer type of the chain's residues from ATOM
// records (of all but waters if none), else neither. Unlike gemmi's
// add_entity_types, which counts every residue (so that a dozen waters hide
// a peptide) and ends the polymer at the first residue that does not fit
// it, this depends on no order.
void type_residues(gemmi::Chain& chain) {
  std::vector<gemmi::Residue>& residues = chain.residues;
  const auto untyped = [](const gemmi::Residue& r) { return r.entity_type == gemmi::EntityType::Unknown; };
  if (std::none_of(residues.begin(), residues.end(), untyped)) return;
  const auto counted = [&](bool atom_records) {
    std::vector<gemmi::Residue> some;  // moved out and back: gemmi counts a contiguous span
    std::vector<std::size_t> from;
    for (std::size_t i = 0; i < residues.size(); ++i)
      if (!residues[i].is_water() && (!atom_records || residues[i].het_flag == 'A')) {
        from.push_back(i);
        some.push_back(std::move(residues[i]));
      }
    const gemmi::PolymerType type = gemmi::check_polymer_type(gemmi::ConstResidueSpan(some.data(), some.size()));
    for (std::size_t k = 0; k < some.size(); ++k) residues[from[k]] = std::move(some[k]);
    return std::make_pair(type, !some.empty());
  };
  auto [type, any] = counted(true);
  if (!any) type = counted(false).first;
  for (gemmi::Residue& r : residues)
    if (untyped(r))
      r.entity_type = r.is_water() ? gemmi::EntityType::Water
                      : gemmi::is_polymer_residue(r, type) ? gemmi::EntityType::Polymer
                                                           : gemmi::EntityType::NonPolymer;
}

// For a file whose residues' records are not together (as written from a
// selection or a merge): in each model, the parts of a chain joined into
// one and the pieces of a residue into one, by identity (name, number,
// insertion code, segment), polymer residues first, then others, then
// waters, each by number. `retype`: the types gemmi took from TER records
// are dropped (their places mean nothing then) and all residues typed by
// type_residues; otherwise only those the file left untyped (mmCIF
// entities are kept).
void regroup_residues(gemmi::Structure& st, bool retype) {
  const auto rank = [](const gemmi::Residue& r) {
    return r.entity_type == gemmi::EntityType::Polymer ? 0 : r.entity_type == gemmi::EntityType::Water ? 2 : 1;
  };
  for (gemmi::Model& m : st.models) {
    std::vector<gemmi::Chain> chains;  // in order of first appearance
    std::vector<std::unordered_map<gemmi::ResidueId, std::size_t>> index;
    for (gemmi::Chain& part : m.chains) {
      auto c = std::find_if(chains.begin(), chains.end(), [&](const gemmi::Chain& x) { return x.name == part.name; });
      if (c == chains.end()) {
        c = chains.insert(chains.end(), gemmi::Chain(part.name));
        index.emplace_back();
      }
      gemmi::Chain& chain = *c;
      for (gemmi::Residue& r : part.residues) {
        const auto [at, added] = index[std::size_t(c - chains.begin())].emplace(r, chain.residues.size());
        if (added) {
          chain.residues.push_back(std::move(r));
          continue;
        }
        gemmi::Residue& same = chain.residues[at->second];
        same.atoms.insert(same.atoms.end(), r.atoms.begin(), r.atoms.end());
        if (r.het_flag == 'A') same.het_flag = 'A';  // from ATOM records if any piece is
      }
    }
    for (gemmi::Chain& chain : chains) {
      if (retype)
        for (gemmi::Residue& r : chain.residues) r.entity_type = gemmi::EntityType::Unknown;
      type_residues(chain);
      std::stable_sort(chain.residues.begin(), chain.residues.end(), [&](const gemmi::Residue& a, const gemmi::Residue& b) {
        return std::make_tuple(rank(a), seq_num(a), a.seqid.icode) < std::make_tuple(rank(b), seq_num(b), b.seqid.icode);
      });
    }
    m.chains = std::move(chains);
  }
}

bool has_atoms(const gemmi::Model& m) {
  return std::any_of(m.chains.begin(), m.chains.end(), [](const gemmi::Chain& c) {
    return std::any_of(c.residues.begin(), c.residues.end(), [](const gemmi::Residue& r) { return !r.atoms.empty(); });
  });
}

bool has_atoms(const gemmi::Structure& st) {
  return std::any_of(st.models.begin(), st.models.end(), [](const gemmi::Model& m) { return has_atoms(m); });
}

// `old_columns`: a PDB file whose columns 73-80 are not read.
// *local_plddt: whether an mmCIF file has per-residue model quality
// (ModelCIF's _ma_qa_metric_local, as AlphaFold DB's files).
gemmi::Structure parse_with_gemmi(std::string_view text, Format format, const std::string& name, bool old_columns,
                                  bool* local_plddt, UnknownElements& unknown) {
  if (format == Format::Pdb) checked([&] { check_pdb_records(text, name, old_columns, unknown); });
  gemmi::Structure st;
  std::vector<std::string> missing;
  try {
    if (format == Format::Pdb) {
      gemmi::PdbReadOptions pdb_options;
      if (old_columns) pdb_options.max_line_length = 72;
      st = gemmi::read_pdb_from_memory(text.data(), text.size(), name, pdb_options);
      if (has_scattered_residues(text, old_columns)) regroup_residues(st, /*retype=*/true);
    } else {
      gemmi::cif::Document doc = gemmi::cif::read_memory(text.data(), text.size(), name.c_str());
      check_atom_site(doc.blocks.at(0), text, name, unknown);
      st = gemmi::make_structure(doc);
      if (has_split_residues(st)) regroup_residues(st, /*retype=*/false);
      *local_plddt = doc.blocks.at(0).find_mmcif_category("_ma_qa_metric_local.").ok();
      if (!has_atoms(st)) missing = missing_atom_site_columns(doc.blocks.at(0));
    }
    // Polymer, water or neither, where the file does not say (PDB files
    // without TER records).
    for (gemmi::Model& m : st.models)
      for (gemmi::Chain& c : m.chains) type_residues(c);
  } catch (const std::exception& e) {
    throw StructureError(one_line(e.what(), name), alpha::ErrorKind::BadInput);
  }
  if (!missing.empty())
    fail(name, "mmCIF _atom_site lacks column(s) " + join(missing, missing.size()), alpha::ErrorKind::BadInput);
  if (!has_atoms(st)) fail(name, "no atoms in the file", alpha::ErrorKind::BadInput);
  return st;
}

// ---------------------------------------------------------------- selection

bool is_hydrogen(const gemmi::Atom& a) { return a.element == gemmi::El::H || a.element == gemmi::El::D; }

bool is_water(const gemmi::Residue& r) { return r.entity_type == gemmi::EntityType::Water || r.is_water(); }

bool is_polymer(const gemmi::Residue& r) { return r.entity_type == gemmi::EntityType::Polymer; }

// Whether any residue of the chain comes from ATOM records.
bool has_atom_records(const gemmi::Chain& chain) {
  return std::any_of(chain.residues.begin(), chain.residues.end(),
                     [](const gemmi::Residue& r) { return r.het_flag == 'A'; });
}

// A ligand bound to the receptor, as the ligand-site datasets (PDBbind,
// COACH420/P2Rank) count it: not water and not part of the receptor's
// polymer. gemmi calls every residue of a polymer chain "polymer", so HETATM
// residues need a closer look: a chain of HETATM records only is a peptide
// or an inhibitor given its own chain, and a HETATM residue that gemmi's
// tables do not know as a modified amino acid or nucleotide is a ligand
// covalently bound to the chain. Modified residues (MSE, SEP, ...) stay.
bool is_ligand(const gemmi::Residue& r, bool chain_has_atom_records) {
  if (!is_polymer(r)) return true;
  if (r.het_flag != 'H') return false;
  if (!chain_has_atom_records) return true;
  const gemmi::ResidueInfo info = gemmi::find_tabulated_residue(r.name);
  return !(info.is_amino_acid() || info.is_nucleic_acid());
}

char no_blank(char c) { return c == ' ' ? '\0' : c; }

// The altloc kept for a group of residues with one sequence number: the
// highest mean occupancy, ties to the smallest letter (not the first in the
// file: the choice must not depend on the order of the records); '\0' if
// none.
char chosen_altloc(gemmi::Span<const gemmi::Residue> group) {
  struct Conformer {
    char altloc;
    double occupancy = 0;
    std::size_t atoms = 0;
  };
  std::vector<Conformer> seen;  // in order of first appearance
  for (const gemmi::Residue& r : group)
    for (const gemmi::Atom& a : r.atoms) {
      if (!a.altloc) continue;
      auto it = std::find_if(seen.begin(), seen.end(), [&](const Conformer& c) { return c.altloc == a.altloc; });
      if (it == seen.end()) it = seen.insert(seen.end(), Conformer{a.altloc});
      it->occupancy += a.occ;
      ++it->atoms;
    }
  const Conformer* best = nullptr;
  for (const Conformer& c : seen)  // means compared without dividing: a/n > b/m as a*m > b*n
    if (!best || c.occupancy * double(best->atoms) > best->occupancy * double(c.atoms) ||
        (c.occupancy * double(best->atoms) == best->occupancy * double(c.atoms) && c.altloc < best->altloc))
      best = &c;
  return best ? best->altloc : '\0';
}

// Which atoms of a residue the altloc selection keeps: those without an
// altloc, those of the chosen one, and for each atom name without an atom in
// the chosen one, that name's best other atom: the highest occupancy, ties
// to the smallest altloc, then position and serial (not the first in the
// file). One pass with a table by name: linear in the atoms (a residue may
// hold tens of thousands).
std::vector<bool> altloc_keep(const gemmi::Residue& r, char chosen) {
  const auto& atoms = r.atoms;
  constexpr std::size_t kNone = std::size_t(-1);
  struct Name {
    bool in_chosen = false;
    std::size_t best = kNone;  // the best atom in another altloc
  };
  const auto rank = [](const gemmi::Atom& a) {
    return std::make_tuple(-a.occ, a.altloc, a.pos.x, a.pos.y, a.pos.z, a.serial);
  };
  std::unordered_map<std::string_view, Name> names;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    if (!atoms[i].altloc) continue;
    Name& n = names[atoms[i].name];
    if (atoms[i].altloc == chosen)
      n.in_chosen = true;
    else if (n.best == kNone || rank(atoms[i]) < rank(atoms[n.best]))
      n.best = i;
  }
  std::vector<bool> keep(atoms.size(), true);
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    if (!atoms[i].altloc || atoms[i].altloc == chosen) continue;
    const Name& n = names.at(atoms[i].name);
    keep[i] = !n.in_chosen && n.best == i;
  }
  return keep;
}

// A residue of a microheterogeneity group made only of other conformers.
bool only_other_conformers(const gemmi::Residue& r, char chosen) {
  return std::all_of(r.atoms.begin(), r.atoms.end(),
                     [&](const gemmi::Atom& a) { return a.altloc && a.altloc != chosen; });
}

// "CA of GLY A16", for messages.
std::string describe(const Atom& a) {
  return a.name + " of " + a.residue_name + " " + a.chain + std::to_string(a.seq_num);
}

// The canonical order of atoms: by chain, residue number, insertion code,
// residue name, atom name, altloc, then position, serial and the remaining
// fields, so that atoms alike in identity (duplicate names) are ordered too
// and only atoms equal in every field tie. Structure::atoms are kept in it
// (per kind, see select), so that every result computed from them is a
// function of the set of atoms, not of the order of the records.
auto canonical_key(const Atom& a) {
  return std::tie(a.chain, a.seq_num, a.icode, a.residue_name, a.name, a.altloc, a.position.x, a.position.y,
                  a.position.z, a.serial, a.element, a.occupancy, a.b_factor, a.hetero);
}

bool canonical_less(const Atom& a, const Atom& b) { return canonical_key(a) < canonical_key(b); }

// Sorts atoms into the canonical order. A file lists a residue's atoms
// together, residues mostly in order: std::sort on the atoms themselves
// moved four strings per swap and, on that nearly sorted input, fell back
// to heapsort (0.8 G instructions on 150,000 atoms). Instead the indices are
// sorted by the residue (chain's rank among the distinct chains, number,
// insertion code), each residue's by canonical_less, and the atoms moved
// once. Only atoms equal in every field tie, so the order is the same.
void canonical_sort(std::vector<Atom>& atoms) {
  struct Residue {
    std::uint32_t chain;
    int seq_num;
    char icode;
    std::uint32_t atom;
  };
  std::map<std::string, std::uint32_t> chains;
  for (const Atom& a : atoms) chains.emplace(a.chain, 0);
  std::uint32_t rank = 0;
  for (auto& [chain, r] : chains) r = rank++;
  std::vector<Residue> order;
  order.reserve(atoms.size());
  const std::uint32_t* chain = nullptr;
  for (std::uint32_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    if (i == 0 || a.chain != atoms[i - 1].chain) chain = &chains.find(a.chain)->second;
    order.push_back({*chain, a.seq_num, a.icode, i});
  }
  auto residue = [](const Residue& r) { return std::tie(r.chain, r.seq_num, r.icode); };
  std::sort(order.begin(), order.end(), [&](const Residue& a, const Residue& b) {
    return std::tie(a.chain, a.seq_num, a.icode, a.atom) < std::tie(b.chain, b.seq_num, b.icode, b.atom);
  });
  for (auto begin = order.begin(); begin != order.end();) {
    const auto end = std::find_if(begin, order.end(), [&](const Residue& r) { return residue(r) != residue(*begin); });
    std::sort(begin, end, [&](const Residue& a, const Residue& b) { return canonical_less(atoms[a.atom], atoms[b.atom]); });
    begin = end;
  }
  std::vector<Atom> sorted;
  sorted.reserve(atoms.size());
  for (const Residue& r : order) sorted.push_back(std::move(atoms[r.atom]));
  atoms = std::move(sorted);
}

// Radii per atom, with one warning per element that gets the default;
// warnings count only the atoms kept (`kept`), the ones a caller uses.
class RadiusAssigner {
public:
  double operator()(const Atom& a, bool kept) {
    const AtomRadius r = atom_radius(a.residue_name, a.name, a.element);
    kept_x_ += kept && a.element == "X";
    if (kept && r.source == RadiusSource::Default) {
      Unknown& u = unknown_[a.element];
      if (u.atoms++ == 0 || canonical_less(a, u.first)) u.first = a;
    }
    return r.value;
  }
  // `symbols`: what the file wrote where gemmi read X, with lines.
  void add_warnings(std::vector<std::string>& warnings, const UnknownElements& symbols) const {
    // "'QQ', 'ZZ'" and "on line 5, 9; ": the symbols gemmi read as X.
    std::string written, lines;
    for (const auto& [symbol, line] : symbols) {
      written += (written.empty() ? "'" : ", '") + symbol + "'";
      lines += (lines.empty() ? "on line " : ", ") + std::to_string(line);
    }
    if (!symbols.empty() && kept_x_ > 0 && !unknown_.count("X"))  // each got a radius from its name
      warnings.push_back("unknown element " + written + " (" + lines + ") read as X; radii from the atom names");
    for (const auto& [element, u] : unknown_) {
      std::string what = "'" + element + "'", where;
      if (element == "X" && !symbols.empty()) {
        what = written;
        where = lines + "; ";
      }
      std::ostringstream s;
      s << u.atoms << " atom" << (u.atoms == 1 ? "" : "s") << " of unknown element " << what << " (" << where
        << "first: atom " << describe(u.first) << ") given radius " << kDefaultRadius << " A";
      warnings.push_back(s.str());
    }
  }

private:
  struct Unknown {
    std::size_t atoms = 0;
    Atom first;  // in the canonical order
  };
  std::map<std::string, Unknown> unknown_;  // ordered: deterministic warnings
  std::size_t kept_x_ = 0;                  // kept atoms of element X, whatever their radius
};

Atom make_atom(const gemmi::Atom& a, const gemmi::Residue& r, const gemmi::Chain& c) {
  Atom atom;
  atom.serial = a.serial;
  atom.name = a.name;
  atom.element = a.element.name();
  atom.altloc = a.altloc;
  atom.occupancy = a.occ;
  atom.b_factor = a.b_iso;
  atom.residue_name = r.name;
  atom.seq_num = seq_num(r);
  atom.icode = no_blank(r.seqid.icode);
  atom.chain = c.name;
  atom.hetero = r.het_flag == 'H';
  atom.position = {a.pos.x, a.pos.y, a.pos.z};
  return atom;
}

int model_number(const gemmi::Model& m) {
  int n = 0;
  std::from_chars(m.name.data(), m.name.data() + m.name.size(), n);
  return n;
}

// Model 0 is the first model with atoms (a PDB file may have empty ones).
const gemmi::Model& select_model(const gemmi::Structure& st, int model, const std::string& name) {
  if (model < 0) fail(name, "invalid model number " + std::to_string(model), alpha::ErrorKind::Misuse);
  if (model == 0)
    return *std::find_if(st.models.begin(), st.models.end(), [](const gemmi::Model& m) { return has_atoms(m); });
  std::vector<std::string> names, with_atoms;
  for (const gemmi::Model& m : st.models) {
    if (model_number(m) == model && has_atoms(m)) return m;
    names.push_back(m.name);
    if (has_atoms(m)) with_atoms.push_back(m.name);
  }
  if (std::find(names.begin(), names.end(), std::to_string(model)) != names.end())
    fail(name, "model " + std::to_string(model) + " has no atoms (models with atoms: " + join(with_atoms, 10) + ")",
         alpha::ErrorKind::BadInput);
  fail(name, "no model " + std::to_string(model) + " (models: " + join(names, 10) + ")", alpha::ErrorKind::BadInput);
}

void check_chains(const gemmi::Model& model, const std::vector<std::string>& chains, const std::string& name) {
  for (const std::string& wanted : chains)
    if (!model.find_chain(wanted)) {
      std::vector<std::string> names;
      for (const gemmi::Chain& c : model.chains)
        if (std::find(names.begin(), names.end(), c.name) == names.end()) names.push_back(c.name);
      fail(name, "no chain '" + wanted + "' in model " + model.name + " (chains: " + join(names, 30) + ")",
           alpha::ErrorKind::BadInput);
    }
}

std::string dropped_list(const StructureReport& r) {
  std::vector<std::string> parts;
  const auto add = [&](std::size_t n, const char* what) {
    if (n) parts.push_back(std::to_string(n) + " " + what);
  };
  add(r.dropped_chain, "other-chain");
  add(r.dropped_altloc, "altloc");
  add(r.dropped_water, "water");
  add(r.dropped_hetero, "hetero");
  add(r.dropped_hydrogen, "hydrogen");
  add(r.dropped_plddt, "low-pLDDT");
  return parts.empty() ? "none" : join(parts, parts.size());
}

double mean_b_factor(const gemmi::Residue& r) {
  double sum = 0;
  for (const gemmi::Atom& a : r.atoms) sum += a.b_iso;
  return r.atoms.empty() ? 0 : sum / double(r.atoms.size());
}

Structure select(const gemmi::Structure& st, const StructureOptions& options, const std::string& name,
                 bool predicted, const UnknownElements& unknown) {
  const gemmi::Model& model = select_model(st, options.model, name);
  check_chains(model, options.chains, name);
  Structure out;
  StructureReport& report = out.report;
  report.models = st.models.size();
  report.model = model_number(model);
  report.model_index = std::size_t(&model - st.models.data());
  report.predicted = predicted;
  const bool by_plddt = predicted && options.min_plddt > 0;
  if (options.min_plddt > 0 && !predicted)
    report.warnings.push_back("not a predicted model (no pLDDT): --min-plddt ignored");
  RadiusAssigner radius;
  const auto wanted_chain = [&](const std::string& chain) {
    return options.chains.empty() ||
           std::find(options.chains.begin(), options.chains.end(), chain) != options.chains.end();
  };
  std::vector<Atom> kept_atoms[3];  // polymer, hetero, water
  for (const gemmi::Chain& chain : model.chains) {
    const auto& residues = chain.residues;
    const bool chain_has_atom_records = has_atom_records(chain);
    for (std::size_t g = 0; g < residues.size();) {
      // A group: consecutive residues with one sequence number.
      std::size_t end = g + 1;
      while (end < residues.size() && residues[end].seqid == residues[g].seqid) ++end;
      const gemmi::Span<const gemmi::Residue> group(residues.data() + g, end - g);
      g = end;
      const char chosen = chosen_altloc(group);
      for (const gemmi::Residue& res : group) {
        report.atoms_in_model += res.atoms.size();
        if (!wanted_chain(chain.name)) {
          report.dropped_chain += res.atoms.size();
          continue;
        }
        if (group.size() > 1 && only_other_conformers(res, chosen)) {
          report.dropped_altloc += res.atoms.size();
          continue;
        }
        const std::vector<bool> keep = altloc_keep(res, chosen);
        const bool water = is_water(res);
        const bool hetero = !water && is_ligand(res, chain_has_atom_records);
        const bool keep_group = hetero && keeps_hetero(options, res.name);
        const bool low_plddt = by_plddt && mean_b_factor(res) < options.min_plddt;
        HeteroGroup ligand{res.name, chain.name, seq_num(res), no_blank(res.seqid.icode), {}};
        for (std::size_t i = 0; i < res.atoms.size(); ++i) {
          const gemmi::Atom& a = res.atoms[i];
          if (!keep[i]) {
            ++report.dropped_altloc;
            continue;
          }
          const bool in_ligand = hetero && !is_hydrogen(a);
          bool kept = false;
          if (water && !options.keep_waters)
            ++report.dropped_water;
          else if (hetero && !keep_group)
            ++report.dropped_hetero;
          else if (is_hydrogen(a) && !options.keep_hydrogens)
            ++report.dropped_hydrogen;
          else if (low_plddt)
            ++report.dropped_plddt;
          else
            kept = true;
          if (!kept && !in_ligand) continue;
          Atom atom = make_atom(a, res, chain);
          atom.file_index = report.atoms_in_model - res.atoms.size() + i;
          atom.radius = radius(atom, kept);
          if (in_ligand) ligand.atoms.push_back(atom);
          ligand.kept = ligand.kept || (kept && in_ligand);
          if (kept) kept_atoms[water ? 2 : hetero ? 1 : 0].push_back(std::move(atom));
        }
        if (!ligand.atoms.empty()) out.hetero_groups.push_back(std::move(ligand));
      }
    }
  }
  // The polymer first, then the kept hetero groups, then waters: a copy of
  // the atoms searched followed by the ligands (structure_copy) reads back
  // in the same order.
  for (std::vector<Atom>& atoms : kept_atoms) {
    canonical_sort(atoms);
    out.atoms.insert(out.atoms.end(), std::make_move_iterator(atoms.begin()), std::make_move_iterator(atoms.end()));
  }
  for (HeteroGroup& g : out.hetero_groups) std::sort(g.atoms.begin(), g.atoms.end(), canonical_less);
  std::sort(out.hetero_groups.begin(), out.hetero_groups.end(), [](const HeteroGroup& a, const HeteroGroup& b) {
    return canonical_less(a.atoms.front(), b.atoms.front());
  });
  report.kept = out.atoms.size();
  report.hetero_groups = out.hetero_groups.size();
  radius.add_warnings(report.warnings, unknown);
  if (out.atoms.empty())
    fail(name,
         "no atoms left after the selection (model " + model.name + " has " + std::to_string(report.atoms_in_model) +
             " atoms; dropped: " + dropped_list(report) + ")",
         alpha::ErrorKind::BadInput);
  if (out.atoms.size() < options.min_atoms)
    fail(name,
         "only " + std::to_string(out.atoms.size()) + " atom" + (out.atoms.size() == 1 ? "" : "s") +
             " after the selection, at least " + std::to_string(options.min_atoms) + " are needed",
         alpha::ErrorKind::BadInput);
  return out;
}

[[noreturn]] void too_large(const std::string& name, std::uintmax_t bytes, std::size_t max_mib) {
  fail(name, "is " + std::to_string(bytes >> 20) + " MiB, more than the limit for a structure file of " +
                 std::to_string(max_mib) + " MiB (--max-input-mb raises it)",
       alpha::ErrorKind::LimitExceeded);
}

}  // namespace

namespace {

// The file parsed by gemmi, and how each model is selected from it.
template <class Select>
auto parsed(std::string_view data, const std::string& name, const StructureOptions& options, Select&& select_models) {
  if (data.empty()) fail(name, "file is empty", alpha::ErrorKind::BadInput);
  std::string unzipped;
  const bool gzipped = is_gzip(data);
  if (gzipped) {
    try {
      unzipped = gunzip(data, name, options.max_input_mib << 20);
    } catch (const alpha::Error& e) {
      throw StructureError(e.what(), e.kind());
    }
    data = unzipped;
  } else if (ends_with_ci(name, ".gz")) {
    fail(name, "not gzip data (no gzip header)", alpha::ErrorKind::BadInput);
  }
  if (data.size() > options.max_input_mib << 20) too_large(name, data.size(), options.max_input_mib);
  if (is_blank(data))
    fail(name, gzipped ? "file is empty (after decompression)" : "file is empty", alpha::ErrorKind::BadInput);
  if (const std::optional<std::size_t> line = cif_without_data_block(data))
    fail(name, "line " + std::to_string(*line) + ": mmCIF without a data_ block (its first line must be data_NAME)",
         alpha::ErrorKind::BadInput);
  const Format format = checked([&] { return detect_format(data, name); });
  const std::optional<OldColumns> old = format == Format::Pdb ? old_format_columns(data) : std::nullopt;
  bool local_plddt = false;
  UnknownElements unknown;
  const gemmi::Structure st = parse_with_gemmi(data, format, name, old.has_value(), &local_plddt, unknown);
  const bool af_name = std::filesystem::path(name).filename().string().rfind("AF-", 0) == 0;
  const auto one = [&](const StructureOptions& model_options) {
    Structure out = select(st, model_options, name, local_plddt || af_name, unknown);
    if (old)
      out.report.warnings.insert(out.report.warnings.begin(),
                                 "columns 73-80 hold an old-format id code and line number (line " +
                                     std::to_string(old->line_number) + ": '" + old->text +
                                     "'): ignored, elements taken from the atom names");
    out.report.format = format == Format::Pdb ? "PDB" : "mmCIF";
    out.report.gzipped = gzipped;
    return out;
  };
  return select_models(st, one);
}

}  // namespace

Structure parse_structure(std::string_view data, const std::string& name, const StructureOptions& options) {
  return parsed(data, name, options, [&](const gemmi::Structure&, const auto& one) { return one(options); });
}

std::vector<Structure> parse_models(std::string_view data, const std::string& name, const StructureOptions& options) {
  return parsed(data, name, options, [&](const gemmi::Structure& st, const auto& one) {
    std::vector<Structure> models;
    for (const gemmi::Model& m : st.models) {
      StructureOptions model_options = options;
      model_options.model = model_number(m);
      models.push_back(one(model_options));
    }
    return models;
  });
}

Structure read_structure(const std::string& path, const StructureOptions& options) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
  if (!ec && size > options.max_input_mib << 20) too_large(path, size, options.max_input_mib);  // not even read
  std::string text;
  try {
    text = alpha::read_input_file(path);
  } catch (const alpha::Error& e) {
    throw StructureError(e.what(), e.kind());
  }
  return parse_structure(text, path, options);
}

bool keeps_hetero(const StructureOptions& options, const std::string& residue_name) {
  const auto named = [&](const auto& codes) {
    return std::find(std::begin(codes), std::end(codes), residue_name) != std::end(codes);
  };
  return options.keep_hetero || named(options.keep_hetero_codes) || (options.keep_cofactors && named(kCofactors));
}

bool is_structure_file(std::string_view path) {
  if (ends_with_ci(path, ".gz")) path.remove_suffix(3);
  for (const char* ext : {".pdb", ".ent", ".cif", ".mmcif"})
    if (ends_with_ci(path, ext)) return true;
  return false;
}

std::string summary(const StructureReport& r) {
  std::ostringstream s;
  s << r.format << (r.gzipped ? " (gzip)" : "") << ", model " << r.model;
  if (r.models > 1) s << " of " << r.models;
  s << ": kept " << r.kept << " of " << r.atoms_in_model << " atoms; dropped: " << dropped_list(r) << "; "
    << r.hetero_groups << " hetero group" << (r.hetero_groups == 1 ? "" : "s");
  return s.str();
}

}  // namespace molecule
