// SPDX-License-Identifier: Apache-2.0
#include "molecule/site_features.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string_view>

#include "molecule/residues.hpp"

namespace molecule {
namespace {

using alpha::Index;
using alpha::Vec3;

constexpr std::array<double, 7> kBurialRadii{6, 8, 10, 12, 14, 16, 20};  // A

// Atom classes by residue and atom name (standard amino acids; "*": any residue).
struct AtomClass {
  std::string_view residue, atoms;  // atom names separated by spaces
};
constexpr AtomClass kAromatic[] = {{"PHE", "CG CD1 CD2 CE1 CE2 CZ"},
                                   {"TYR", "CG CD1 CD2 CE1 CE2 CZ"},
                                   {"TRP", "CG CD1 CD2 NE1 CE2 CE3 CZ2 CZ3 CH2"},
                                   {"HIS", "CG ND1 CD2 CE1 NE2"}};
constexpr AtomClass kDonor[] = {{"ARG", "NE NH1 NH2"}, {"ASN", "ND2"}, {"GLN", "NE2"}, {"HIS", "ND1 NE2"},
                                {"LYS", "NZ"},         {"SER", "OG"},  {"THR", "OG1"}, {"TYR", "OH"},
                                {"TRP", "NE1"},        {"CYS", "SG"}};
constexpr AtomClass kAcceptor[] = {{"*", "O OXT"},     {"ASP", "OD1 OD2"}, {"GLU", "OE1 OE2"}, {"ASN", "OD1"},
                                   {"GLN", "OE1"},     {"HIS", "ND1 NE2"}, {"SER", "OG"},     {"THR", "OG1"},
                                   {"TYR", "OH"},      {"MET", "SD"}};
constexpr AtomClass kPositive[] = {{"ARG", "NE NH1 NH2"}, {"LYS", "NZ"}, {"HIS", "ND1 NE2"}};
constexpr AtomClass kNegative[] = {{"ASP", "OD1 OD2"}, {"GLU", "OE1 OE2"}, {"*", "OXT"}};

template <std::size_t N>
bool in_class(const AtomClass (&table)[N], const Atom& a) {
  for (const AtomClass& c : table) {
    if (c.residue != "*" && c.residue != a.residue_name) continue;
    for (std::size_t from = 0; from < c.atoms.size();) {
      const std::size_t to = std::min(c.atoms.find(' ', from), c.atoms.size());
      if (c.atoms.substr(from, to - from) == a.name) return true;
      from = to + 1;
    }
  }
  return false;
}

bool is_backbone(const Atom& a) { return a.name == "N" || a.name == "CA" || a.name == "C" || a.name == "O"; }
// A backbone N is a donor too, but for proline's.
bool is_donor(const Atom& a) { return (a.name == "N" && a.residue_name != "PRO") || in_class(kDonor, a); }

// Kyte & Doolittle (1982) hydropathy; 0 for other residues.
double hydropathy(std::string_view residue) {
  static constexpr std::pair<std::string_view, double> kScale[] = {
      {"ALA", 1.8},  {"ARG", -4.5}, {"ASN", -3.5}, {"ASP", -3.5}, {"CYS", 2.5},  {"GLN", -3.5}, {"GLU", -3.5},
      {"GLY", -0.4}, {"HIS", -3.2}, {"ILE", 4.5},  {"LEU", 3.8},  {"LYS", -3.9}, {"MET", 1.9},  {"PHE", 2.8},
      {"PRO", -1.6}, {"SER", -0.8}, {"THR", -0.7}, {"TRP", -0.9}, {"TYR", -1.3}, {"VAL", 4.2}};
  for (const auto& [name, value] : kScale)
    if (name == residue) return value;
  return 0;
}

bool one_of(std::string_view residue, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), residue) != names.end();
}

double log_score(double score) { return std::log(std::max(score, 1e-300)); }

bool is_void(const Cavities& cavities, const Cavity& c) {
  return !(&c >= cavities.pockets.data() && &c < cavities.pockets.data() + cavities.pockets.size());
}

constexpr double kMetalRadius = 8;          // A from the centre: a metal ion next to the site
constexpr double kRepeatSimilarity = 0.5;   // Jaccard of residues: the same site in another chain

// A metal ion: a one-atom hetero group that is no halide or other non-metal.
bool is_metal_ion(const HeteroGroup& g) {
  if (g.atoms.size() != 1) return false;
  const std::string& e = g.atoms.front().element;
  return !one_of(e, {"C", "N", "O", "S", "P", "F", "Cl", "Br", "I", "Se", "B", "Si", "X"});
}

// The chain most of the lining atoms belong to ("" for none), and how many
// distinct chains line the cavity.
std::pair<std::string, std::size_t> chains_of(const std::vector<Atom>& atoms, const std::vector<Index>& lining,
                                              double* main_share) {
  std::map<std::string, std::size_t> count;
  for (Index i : lining) ++count[atoms[i].chain];
  std::pair<std::string, std::size_t> best{"", 0};
  for (const auto& [chain, n] : count)
    if (n > best.second) best = {chain, n};
  if (main_share) *main_share = lining.empty() ? 1.0 : double(best.second) / double(lining.size());
  return {best.first, count.size()};
}

}  // namespace

const std::vector<std::string>& site_feature_names() {
  static const std::vector<std::string> kNames = [] {
    std::vector<std::string> n = {"is_void",  "sa_volume", "ms_volume",         "sa_area",         "ms_area",
                                  "mouths",   "mouths_to_outside", "mouth_area", "max_mouth_area", "buriedness",
                                  "depth",    "max_probe_radius",  "max_alpha_sq", "persistence",  "tetrahedra",
                                  "sinks",    "lining_atoms",      "lining_residues"};
    for (double r : kBurialRadii) n.push_back("burial_" + std::to_string(int(r)));
    for (const char* s : {"clearance", "centroid_distance", "log_score", "score_rank", "log_score_vs_best",
                          "burial_14_vs_best", "structure_sites", "structure_atoms", "frac_c", "frac_n", "frac_o",
                          "frac_s", "frac_backbone", "frac_aromatic", "frac_donor", "frac_acceptor",
                          "frac_positive", "frac_negative", "res_hydrophobic", "res_aromatic", "res_polar",
                          "res_positive", "res_negative", "res_gly", "res_pro", "hydropathy", "b_zscore",
                          "lining_chains", "interchain_share", "repeat_chains", "metal_ions", "surface_share",
                          "structure_chains"})
      n.push_back(s);
    return n;
  }();
  return kNames;
}

SiteFeatures::SiteFeatures(const Structure& structure, const Cavities& cavities)
    : structure_(structure), cavities_(cavities), atoms_(4) {
  const std::vector<Atom>& atoms = structure.atoms;
  for (Index i = 0; i < atoms.size(); ++i) {
    atoms_.add(atoms[i].position, i);
    centroid_ = centroid_ + atoms[i].position;
  }
  atoms_.finish();
  const double n = std::max<double>(1, double(atoms.size()));
  centroid_ = (1 / n) * centroid_;
  for (const Atom& a : atoms) gyration_radius_ += dot(a.position - centroid_, a.position - centroid_);
  gyration_radius_ = std::sqrt(gyration_radius_ / n);

  // B-factors as z-scores within each chain.
  std::map<std::string, std::array<double, 3>> chain;  // count, sum, sum of squares
  for (const Atom& a : atoms) {
    auto& s = chain[a.chain];
    s[0] += 1, s[1] += a.b_factor, s[2] += double(a.b_factor) * a.b_factor;
  }
  b_zscore_.reserve(atoms.size());
  for (const Atom& a : atoms) {
    const auto& s = chain[a.chain];
    const double mean = s[1] / s[0], var = std::max(0.0, s[2] / s[0] - mean * mean);
    b_zscore_.push_back(var > 1e-12 * std::max(1.0, mean * mean) ? (a.b_factor - mean) / std::sqrt(var) : 0.0);
  }

  // The context: all candidate sites, whichever search_pockets leaves out
  // after the model has seen them.
  best_log_score_ = -std::numeric_limits<double>::infinity();
  for (const Site& s : site_candidates(cavities)) {
    candidate_scores_.push_back(cavities.cavity(s).score);
    best_log_score_ = std::max(best_log_score_, log_score(cavities.cavity(s).score));
    best_burial_ = std::max(best_burial_, double(cavities.cavity(s).burial_atoms));
  }
  if (candidate_scores_.empty()) best_log_score_ = 0;

  // Each candidate's residues by name and number (chain left out) and its
  // main chain: the same site in another chain of a homo-oligomer.
  for (const Site& s : site_candidates(cavities)) {
    const Cavity& c = cavities.cavity(s);
    candidate_chains_.push_back(chains_of(atoms, c.lining_atoms, nullptr).first);
    candidate_residues_.push_back(residue_keys(c));
  }
  std::set<std::string> chains;
  for (const Atom& a : atoms) chains.insert(a.chain);
  chains_ = chains.size();
  for (const HeteroGroup& g : structure.hetero_groups)
    if (is_metal_ion(g)) metals_.push_back(g.atoms.front().position);
}

std::vector<std::pair<std::string, int>> SiteFeatures::residue_keys(const Cavity& c) const {
  std::vector<std::pair<std::string, int>> keys;
  for (Index i : residues_of(structure_.atoms, c.lining_atoms))
    keys.emplace_back(structure_.atoms[i].residue_name, structure_.atoms[i].seq_num);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

std::vector<double> SiteFeatures::operator()(const Cavity& c) const {
  const std::vector<Atom>& atoms = structure_.atoms;
  std::vector<double> f;
  f.reserve(site_feature_names().size());
  double max_mouth = 0;
  std::size_t to_outside = 0;
  for (const Mouth& m : c.mouths) max_mouth = std::max(max_mouth, m.area), to_outside += m.to_outside;
  const std::vector<Index> residues = residues_of(atoms, c.lining_atoms);
  for (double x : {double(is_void(cavities_, c)), c.sa_volume, c.ms_volume, c.sa_area, c.ms_area,
                   double(c.mouths.size()), double(to_outside), c.mouth_area, max_mouth, c.buriedness, c.depth,
                   c.max_probe_radius, c.max_alpha_sq, c.fill_alpha_sq - c.close_alpha_sq, double(c.cells.size()),
                   double(c.sinks.size()), double(c.lining_atoms.size()), double(residues.size())})
    f.push_back(x);

  std::array<double, kBurialRadii.size()> burial{};
  double clearance = std::numeric_limits<double>::infinity();
  atoms_.visit(c.center, kBurialRadii.back(), [&](Index i) {
    const double d = norm(atoms[i].position - c.center);
    clearance = std::min(clearance, d - atoms[i].radius);
    for (std::size_t k = 0; k < kBurialRadii.size(); ++k) burial[k] += d <= kBurialRadii[k];
  });
  if (!std::isfinite(clearance)) clearance = kBurialRadii.back();  // no atom within 20 A
  for (double b : burial) f.push_back(b);
  f.push_back(clearance);
  f.push_back(gyration_radius_ > 0 ? norm(c.center - centroid_) / gyration_radius_ : 0);
  const double ls = log_score(c.score);
  std::size_t rank = 1;
  for (double score : candidate_scores_) rank += score > c.score;
  for (double x : {ls, double(rank), ls - best_log_score_, double(c.burial_atoms) - best_burial_,
                   double(candidate_scores_.size()), double(atoms.size())})
    f.push_back(x);

  // The lining's chemistry.
  std::array<double, 10> atom_counts{};  // C N O S backbone aromatic donor acceptor positive negative
  double b = 0;
  for (Index i : c.lining_atoms) {
    const Atom& a = atoms[i];
    const bool flags[] = {a.element == "C",     a.element == "N",          a.element == "O",
                          a.element == "S",     is_backbone(a),            in_class(kAromatic, a),
                          is_donor(a),          in_class(kAcceptor, a),    in_class(kPositive, a),
                          in_class(kNegative, a)};
    for (std::size_t k = 0; k < atom_counts.size(); ++k) atom_counts[k] += flags[k];
    b += b_zscore_[i];
  }
  const double na = std::max<double>(1, double(c.lining_atoms.size()));
  for (double x : atom_counts) f.push_back(x / na);
  std::array<double, 7> residue_counts{};  // hydrophobic aromatic polar positive negative gly pro
  double kd = 0;
  for (Index i : residues) {
    const std::string_view r = atoms[i].residue_name;
    const bool flags[] = {one_of(r, {"ALA", "VAL", "LEU", "ILE", "MET", "PHE", "TRP", "CYS"}),
                          one_of(r, {"PHE", "TRP", "TYR", "HIS"}),
                          one_of(r, {"SER", "THR", "ASN", "GLN"}),
                          one_of(r, {"LYS", "ARG", "HIS"}),
                          one_of(r, {"ASP", "GLU"}),
                          r == "GLY",
                          r == "PRO"};
    for (std::size_t k = 0; k < residue_counts.size(); ++k) residue_counts[k] += flags[k];
    kd += hydropathy(r);
  }
  const double nr = std::max<double>(1, double(residues.size()));
  for (double x : residue_counts) f.push_back(x / nr);
  f.push_back(kd / nr);
  f.push_back(b / na);

  // The whole entry: chains lining the site and the share of its lining
  // outside its main chain, the same site in other chains, metal ions next
  // to it, its share of the molecule's surface, the entry's chains.
  double main_share = 1;
  const auto [main_chain, chains] = chains_of(atoms, c.lining_atoms, &main_share);
  const std::vector<std::pair<std::string, int>> keys = residue_keys(c);
  std::set<std::string> repeats;
  for (std::size_t k = 0; k < candidate_residues_.size(); ++k) {
    if (candidate_chains_[k] == main_chain || repeats.count(candidate_chains_[k])) continue;
    const auto& other = candidate_residues_[k];
    std::vector<std::pair<std::string, int>> common;
    std::set_intersection(keys.begin(), keys.end(), other.begin(), other.end(), std::back_inserter(common));
    const double joint = double(keys.size() + other.size() - common.size());
    if (joint > 0 && double(common.size()) >= kRepeatSimilarity * joint) repeats.insert(candidate_chains_[k]);
  }
  std::size_t metals = 0;
  for (const Vec3& m : metals_) metals += norm(m - c.center) <= kMetalRadius;
  for (double x : {double(chains), 1 - main_share, double(repeats.size()), double(metals),
                   cavities_.sa_area > 0 ? c.sa_area / cavities_.sa_area : 0.0, double(chains_)})
    f.push_back(x);
  return f;
}

std::string site_features_csv(const Structure& structure, const Cavities& cavities) {
  std::string out = "kind,cavity_rank,site_rank,center_x,center_y,center_z";
  for (const std::string& n : site_feature_names()) out += ',' + n;
  out += ",ligandability,probability,rank_score\n";
  const SiteFeatures features(structure, cavities);
  char text[40];
  for (const bool voids : {false, true}) {
    const std::vector<Cavity>& list = voids ? cavities.voids : cavities.pockets;
    for (std::size_t i = 0; i < list.size(); ++i) {
      std::size_t site_rank = 0;
      for (std::size_t k = 0; k < cavities.sites.size(); ++k)
        if (cavities.sites[k].is_void == voids && cavities.sites[k].index == i) site_rank = k + 1;
      out += std::string(voids ? "void" : "pocket") + ',' + std::to_string(i + 1) + ',' + std::to_string(site_rank);
      for (double x : {list[i].center.x, list[i].center.y, list[i].center.z}) {
        std::snprintf(text, sizeof text, ",%.17g", x);
        out += text;
      }
      std::vector<double> row = features(list[i]);
      row.push_back(list[i].ligandability);
      row.push_back(list[i].probability);
      row.push_back(list[i].rank_score);
      for (double x : row) {
        std::snprintf(text, sizeof text, ",%.17g", x);
        out += text;
      }
      out += '\n';
    }
  }
  return out;
}

}  // namespace molecule
