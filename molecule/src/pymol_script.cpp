#include "molecule/pymol_script.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>

#include "molecule/pocket_colors.hpp"

namespace molecule {
namespace {

// Residues per "select" line: keeps lines short for PyMOL's parser.
constexpr std::size_t kResiduesPerLine = 8;

// A PyMOL object name from the file name: letters, digits and '_' only
// ("1a26A", as PyMOL names a fetched entry).
std::string object_name(const std::string& path) {
  std::string stem = std::filesystem::path(path).filename().string();
  stem = stem.substr(0, stem.find('.'));
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return stem.empty() ? std::string("structure") : stem;
}

// A Python string literal: the path may hold any character.
std::string python_string(const std::string& s) {
  std::string q = "\"";
  for (const unsigned char c : s) {
    if (c == '"' || c == '\\') {
      q += '\\';
      q += char(c);
    } else if (c < 0x20 || c == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02x", c);
      q += esc;
    } else {
      q += char(c);
    }
  }
  return q + '"';
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", x);
  return buf;
}

struct Named {
  std::string name;  // pocket_3
  const Cavity* cavity;
  Rgb color;
};

std::vector<Named> named_cavities(const Cavities& cavities) {
  const CavityColors colors = cavity_colors(cavities);
  std::vector<Named> out;
  for (std::size_t i = 0; i < cavities.pockets.size(); ++i)
    out.push_back({"pocket_" + std::to_string(i + 1), &cavities.pockets[i], colors.pockets[i]});
  for (std::size_t i = 0; i < cavities.voids.size(); ++i)
    out.push_back({"void_" + std::to_string(i + 1), &cavities.voids[i], colors.voids[i]});
  return out;
}

// A word of PyMOL's selection language: a leading '-' (a range otherwise)
// and the wildcard '*' escaped; '' for an empty one (a blank chain id).
std::string selection_word(const std::string& w) {
  std::string out;
  for (const char c : w) {
    if (c == '*' || (c == '-' && out.empty())) out += '\\';
    out += c;
  }
  return out.empty() ? std::string("''") : out;
}

// The atoms as one clause per residue, in order of their first atom:
// "(obj and chain A and resi 42 and name CA+CB)". By chain, residue and
// name, not by serial: PyMOL gives every state the first model's serials,
// and mmCIF numbers the atoms of each model apart.
std::vector<std::string> residue_clauses(const std::string& obj, const std::vector<Atom>& atoms,
                                         const std::vector<alpha::Index>& indices) {
  std::vector<std::string> clauses, names;
  std::map<std::tuple<std::string, int, char>, std::size_t> clause_of;
  for (const alpha::Index i : indices) {
    const Atom& a = atoms.at(i);
    const auto [it, added] = clause_of.try_emplace({a.chain, a.seq_num, a.icode}, clauses.size());
    if (added) {
      clauses.push_back("(" + obj + " and chain " + selection_word(a.chain) + " and resi " +
                        selection_word(std::to_string(a.seq_num) + icode_text(a.icode)) +
                        " and name ");
      names.emplace_back();
    }
    std::string& n = names[it->second];
    if (!n.empty()) n += '+';
    n += selection_word(a.name);
  }
  for (std::size_t k = 0; k < clauses.size(); ++k) clauses[k] += names[k] + ")";
  return clauses;
}

// "select NAME, ..." lines for the atoms, kResiduesPerLine residues a line.
std::string select_lines(const std::string& name, const std::vector<std::string>& clauses) {
  std::string s;
  for (std::size_t k = 0; k < clauses.size() || k == 0; k += kResiduesPerLine) {
    std::string part;
    for (std::size_t j = k; j < std::min(clauses.size(), k + kResiduesPerLine); ++j)
      part += (part.empty() ? "" : " or ") + clauses[j];
    if (part.empty()) part = "none";
    s += "select " + name + ", " + (k == 0 ? part : name + " or " + part) + "\n";
  }
  return s;
}

std::string position(const alpha::Vec3& p) {
  return "pos=[" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + "]";
}

}  // namespace

std::string pymol_script(const PocketRun& run, const std::string& structure_path) {
  const std::string obj = object_name(run.file);
  const std::vector<Atom>& atoms = run.structure->atoms;
  const std::vector<Named> cavities = named_cavities(run.search->cavities);

  std::string s;
  s += "# alphapocket " + run.version + ": pockets of " + run.file + "\n";
  s += "# Run with `pymol pockets.pml` or, inside PyMOL, `@pockets.pml`. Pockets and voids are\n";
  s += "# coloured by site rank (report.json sites); pocket_N selects the atoms lining pocket N and\n";
  s += "# pocket_N_center is its centre (void_N, void_N_center likewise); tunnel_N selects the three\n";
  s += "# atoms of tunnel N's bottleneck, tunnel_N_bottleneck is the largest probe passing it (cyan).\n";
  const StructureReport& report = run.structure->report;
  if (report.models > 1) {
    // PyMOL loads every model as a state: keep the one searched.
    s += "/cmd.load(" + python_string(structure_path) + ", \"" + obj + "_models\")\n";
    s += "/cmd.create(\"" + obj + "\", \"" + obj + "_models\", " + std::to_string(report.model_index + 1) +
         ", 1); cmd.delete(\"" + obj + "_models\")\n";
  } else {
    s += "/cmd.load(" + python_string(structure_path) + ", \"" + obj + "\")\n";
  }
  s += "hide everything, " + obj + "\n";
  s += "show cartoon, " + obj + "\n";
  s += "color grey80, " + obj + "\n";
  s += "set cartoon_color, grey80, " + obj + "\n";
  s += "show sticks, " + obj + " and organic\n";
  s += "show surface, " + obj + "\n";
  s += "set transparency, 0.2, " + obj + "\n";
  s += "set sphere_scale, 0.6\n";

  for (const Named& c : cavities) {
    s += "set_color ap_" + c.name + ", [" + std::to_string(c.color.r) + ", " + std::to_string(c.color.g) + ", " +
         std::to_string(c.color.b) + "]\n";
    s += select_lines(c.name, residue_clauses(obj, atoms, c.cavity->lining_atoms));
    s += "pseudoatom " + c.name + "_center, " + position(c.cavity->center) + "\n";
    s += "color ap_" + c.name + ", " + c.name + "_center\n";
  }
  // Worst rank first: the best one's colour is the one left on shared atoms.
  for (auto c = cavities.rbegin(); c != cavities.rend(); ++c) {
    s += "color ap_" + c->name + ", " + c->name + "\n";
    s += "show sticks, " + c->name + "\n";
  }
  if (!cavities.empty()) {
    s += "show spheres, *_center\n";
    s += "group centers, *_center\n";
  }
  // Tunnels: the bottleneck's atoms, and the largest probe passing it as a
  // sphere of its radius.
  const std::vector<Tunnel>& tunnels = run.search->cavities.tunnels;
  for (std::size_t i = 0; i < tunnels.size(); ++i) {
    const std::string name = "tunnel_" + std::to_string(i + 1);
    s += select_lines(name, residue_clauses(obj, atoms, tunnels[i].lining_atoms));
    s += "pseudoatom " + name + "_bottleneck, " + position(tunnels[i].bottleneck_center) +
         ", vdw=" + number(tunnels[i].bottleneck_radius) + "\n";
  }
  if (!tunnels.empty()) {
    s += "color cyan, tunnel_*_bottleneck\n";
    s += "show spheres, tunnel_*_bottleneck\n";
    s += "set sphere_scale, 1.0, tunnel_*_bottleneck\n";
    s += "set sphere_transparency, 0.5, tunnel_*_bottleneck\n";
    s += "group tunnels, tunnel_*_bottleneck\n";
  }
  s += "deselect\n";
  s += "orient " + obj + "\n";
  return s;
}

}  // namespace molecule
