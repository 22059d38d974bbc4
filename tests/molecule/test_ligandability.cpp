// SPDX-License-Identifier: Apache-2.0
// The ligandability model (molecule/ligandability_model.hpp) and its
// features (molecule/site_features.hpp): the compiled-in model gives the
// margins and probabilities scikit-learn gave on every pockets-dev site
// (fixture written by training/train.py), every feature of a hand-made
// cavity equals its value computed by hand (the fixture is alphapocket's
// own output: it cannot catch a wrong feature), the evaluator follows a
// hand-made model exactly, bad models are refused, and search_pockets
// ranks the sites by the model.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "alpha/error.hpp"
#include "molecule/ligandability_model.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/site_features.hpp"
#include "molecule/structure.hpp"

namespace {

using molecule::LigandabilityModel;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) out.push_back(field);
  return out;
}

struct FixtureRow {
  std::string structure, kind;
  std::size_t cavity_rank = 0;
  std::vector<double> features;
  double margin = 0, probability = 0, rank_score = 0;
};

std::vector<FixtureRow> read_fixture(std::vector<std::string>& header) {
  std::ifstream in(std::string(ALPHAPOCKET_TEST_DATA) + "/ligandability/pockets-dev.csv");
  REQUIRE(in);
  std::string line;
  std::getline(in, line);
  header = split(line);
  std::vector<FixtureRow> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = split(line);
    REQUIRE(f.size() == header.size());
    FixtureRow r{f[0], f[1], std::stoul(f[2]), {}, std::stod(f[f.size() - 3]), std::stod(f[f.size() - 2]),
                 std::stod(f.back())};
    for (std::size_t k = 3; k + 3 < f.size(); ++k) r.features.push_back(std::stod(f[k]));
    rows.push_back(std::move(r));
  }
  return rows;
}

// One tree: x0 <= 1.5 ? (x1 <= -2 ? 0.25 : -1) : 3; init 0.5, scale 2; the
// calibration 0 -> 0.1, 4 -> 0.9 (linear between, clipped beyond).
std::string toy_model(const std::string& tree, const std::string& knots = R"("x":[0,4],"y":[0.1,0.9])") {
  std::string features;
  for (const std::string& n : molecule::site_feature_names()) features += (features.empty() ? "\"" : ",\"") + n + '"';
  return R"({"features":[)" + features + R"(],"init":0.5,"scale":2,"trees":[)" + tree +
         R"(],"calibration":{)" + knots + "}}";
}
const std::string kToyTree =
    R"({"feature":[0,1,-1,-1,-1],"threshold":[1.5,-2,0,0,0],"left":[1,3,-1,-1,-1],"right":[2,4,-1,-1,-1],)"
    R"("value":[0,0,3,0.25,-1]})";

}  // namespace

TEST_CASE("ligandability: the compiled-in model gives scikit-learn's margin, probability and rank score on every "
          "pockets-dev site",
          "[ligandability]") {
  std::vector<std::string> header;
  const std::vector<FixtureRow> rows = read_fixture(header);
  const std::vector<std::string> names(header.begin() + 3, header.end() - 3);
  CHECK(names == molecule::site_feature_names());
  std::map<std::string, int> structures;
  for (const FixtureRow& r : rows) ++structures[r.structure];
  CHECK(structures.size() == 40);  // every pockets-dev structure has sites
  const LigandabilityModel& model = molecule::default_ligandability_model();
  double worst_margin = 0, worst_probability = 0, worst_rank = 0;
  for (const FixtureRow& r : rows) {
    const double m = model.margin(r.features);
    worst_margin = std::max(worst_margin, std::fabs(m - r.margin));
    worst_probability = std::max(worst_probability, std::fabs(model.probability(m) - r.probability));
    worst_rank = std::max(worst_rank, std::fabs(model.rank_score(r.features) - r.rank_score));
  }
  INFO(rows.size() << " sites");
  CHECK(worst_margin <= 1e-6);
  CHECK(worst_probability <= 1e-6);
  CHECK(worst_rank <= 1e-6);
}

TEST_CASE("ligandability: alphapocket's features of a pockets-dev structure are the fixture's", "[ligandability]") {
  std::vector<std::string> header;
  const std::vector<FixtureRow> rows = read_fixture(header);
  for (const char* name : {"1fkgA", "3stdA"}) {
    INFO(name);
    const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/" + name + ".pdb");
    const molecule::PocketSearch search = molecule::search_pockets(s, {});
    const molecule::SiteFeatures features(s, search.cavities);
    std::size_t seen = 0;
    for (const FixtureRow& r : rows) {
      if (r.structure != name) continue;
      ++seen;
      const auto& list = r.kind == "void" ? search.cavities.voids : search.cavities.pockets;
      REQUIRE(r.cavity_rank >= 1);
      REQUIRE(r.cavity_rank <= list.size());
      const molecule::Cavity& c = list[r.cavity_rank - 1];
      const std::vector<double> f = features(c);
      REQUIRE(f.size() == r.features.size());
      for (std::size_t k = 0; k < f.size(); ++k) {
        INFO(molecule::site_feature_names()[k]);
        CHECK(f[k] == Approx(r.features[k]).epsilon(1e-12).margin(1e-12));
      }
      CHECK(std::fabs(c.ligandability - r.margin) <= 1e-6);
      CHECK(std::fabs(c.probability - r.probability) <= 1e-6);
      CHECK(std::fabs(c.rank_score - r.rank_score) <= 1e-6);
    }
    CHECK(seen == molecule::site_candidates(search.cavities).size());
  }
}

TEST_CASE("ligandability: every feature of a hand-made cavity, computed by hand", "[ligandability]") {
  // Seven atoms of chain A (B-factors 10..70: mean 40, standard deviation
  // 20); a pocket centred at the origin lined by the first six, at 3 A
  // (five) and 9 A (MET SD); GLY CA 15 A away. A void as a second site
  // candidate, with a better score and burial.
  const auto atom = [](const char* residue, int number, const char* name, const char* element, alpha::Vec3 p,
                       double radius, float b) {
    molecule::Atom a;
    a.residue_name = residue, a.seq_num = number, a.name = name, a.element = element, a.chain = "A";
    a.position = p, a.radius = radius, a.b_factor = b;
    return a;
  };
  molecule::Structure s;
  s.atoms = {atom("ALA", 1, "N", "N", {3, 0, 0}, 1.5, 10),    atom("ALA", 1, "CA", "C", {0, 3, 0}, 1.7, 20),
             atom("PHE", 2, "CZ", "C", {0, 0, 3}, 1.7, 30),   atom("ASP", 3, "OD1", "O", {-3, 0, 0}, 1.5, 40),
             atom("LYS", 4, "NZ", "N", {0, -3, 0}, 1.5, 50),  atom("MET", 5, "SD", "S", {0, 0, -9}, 1.8, 60),
             atom("GLY", 6, "CA", "C", {15, 0, 0}, 1.7, 70)};
  molecule::Cavities cavities;
  molecule::Cavity pocket;
  pocket.cells = {1, 2, 3};
  pocket.mouths.resize(2);
  pocket.mouths[0].area = 2, pocket.mouths[0].to_outside = true;
  pocket.mouths[1].area = 3, pocket.mouths[1].to_outside = false;
  pocket.sa_volume = 200, pocket.ms_volume = 120, pocket.sa_area = 90, pocket.ms_area = 70;
  pocket.depth = 4, pocket.center = {0, 0, 0}, pocket.lining_atoms = {0, 1, 2, 3, 4, 5}, pocket.sinks = {7};
  pocket.max_alpha_sq = 3, pocket.max_probe_radius = 1.2, pocket.close_alpha_sq = 0.5, pocket.fill_alpha_sq = 2.5;
  pocket.mouth_area = 5, pocket.buriedness = 0.75, pocket.burial_atoms = 5, pocket.score = 2;
  molecule::Cavity void_site;
  void_site.sa_volume = 160, void_site.center = {15, 0, 0}, void_site.lining_atoms = {6};
  void_site.burial_atoms = 9, void_site.score = 4;
  cavities.pockets = {pocket};
  cavities.voids = {void_site};
  cavities.sa_area = 900;
  const molecule::SiteFeatures features(s, cavities);
  const std::vector<double> f = features(cavities.pockets[0]);
  const std::vector<std::string>& names = molecule::site_feature_names();
  REQUIRE(f.size() == names.size());
  const std::map<std::string, double> expected{
      {"is_void", 0}, {"sa_volume", 200}, {"ms_volume", 120}, {"sa_area", 90}, {"ms_area", 70}, {"mouths", 2},
      {"mouths_to_outside", 1}, {"mouth_area", 5}, {"max_mouth_area", 3}, {"buriedness", 0.75}, {"depth", 4},
      {"max_probe_radius", 1.2}, {"max_alpha_sq", 3}, {"persistence", 2}, {"tetrahedra", 3}, {"sinks", 1},
      {"lining_atoms", 6}, {"lining_residues", 5},
      // atoms within 6..20 A of the centre: five at 3 A, MET SD at 9, GLY CA at 15
      {"burial_6", 5}, {"burial_8", 5}, {"burial_10", 6}, {"burial_12", 6}, {"burial_14", 6}, {"burial_16", 7},
      {"burial_20", 7},
      {"clearance", 3 - 1.7},
      // centroid (15/7, 0, -6/7): |centroid|^2 = 261/49, Rg^2 = 351/7 - 261/49 = 2196/49
      {"centroid_distance", std::sqrt(261.0 / 2196.0)},
      {"log_score", std::log(2.0)}, {"score_rank", 2}, {"log_score_vs_best", std::log(2.0) - std::log(4.0)},
      {"burial_14_vs_best", 5 - 9}, {"structure_sites", 2}, {"structure_atoms", 7},
      // lining atoms N CA CZ OD1 NZ SD
      {"frac_c", 2 / 6.0}, {"frac_n", 2 / 6.0}, {"frac_o", 1 / 6.0}, {"frac_s", 1 / 6.0},
      {"frac_backbone", 2 / 6.0}, {"frac_aromatic", 1 / 6.0}, {"frac_donor", 2 / 6.0}, {"frac_acceptor", 2 / 6.0},
      {"frac_positive", 1 / 6.0}, {"frac_negative", 1 / 6.0},
      // residues ALA PHE ASP LYS MET; Kyte-Doolittle 1.8 + 2.8 - 3.5 - 3.9 + 1.9 = -0.9
      {"res_hydrophobic", 3 / 5.0}, {"res_aromatic", 1 / 5.0}, {"res_polar", 0}, {"res_positive", 1 / 5.0},
      {"res_negative", 1 / 5.0}, {"res_gly", 0}, {"res_pro", 0}, {"hydropathy", -0.9 / 5},
      // B z-scores -1.5 -1 -0.5 0 0.5 1
      {"b_zscore", -1.5 / 6},
      // one chain, no other copy of the site, no ion; 90 of the molecule's 900 A^2
      {"lining_chains", 1}, {"interchain_share", 0}, {"repeat_chains", 0}, {"metal_ions", 0},
      {"surface_share", 0.1}, {"structure_chains", 1}};
  REQUIRE(expected.size() == names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    INFO(names[k]);
    REQUIRE(expected.count(names[k]) == 1);
    CHECK(f[k] == Approx(expected.at(names[k])).margin(1e-12));
  }
  const std::vector<double> v = features(cavities.voids[0]);
  CHECK(v[0] == 1);  // is_void
  CHECK(v[std::find(names.begin(), names.end(), "score_rank") - names.begin()] == 1);
}

TEST_CASE("ligandability: whole-entry features of a hand-made entry of five chains", "[ligandability]") {
  // Pocket 1 at the origin: four atoms of chain A and two of chain B line
  // it. Its residues by name and number (ALA 1, PHE 2, ASP 3, LYS 4) come
  // back in chain B's pocket 2 (the same), chain D's pocket 4 (3 of 5:
  // Jaccard 0.6) but not chain E's pocket 5 (1 of 6); chain C's pocket 3 has
  // others. Ions: ZN 5 A from pocket 1's centre, MG 9 A away, and a
  // chloride at 2 A (no metal).
  const auto atom = [](const char* chain, const char* residue, int number, alpha::Vec3 p) {
    molecule::Atom a;
    a.chain = chain, a.residue_name = residue, a.seq_num = number, a.name = "CA", a.element = "C";
    a.position = p, a.radius = 1.7;
    return a;
  };
  molecule::Structure s;
  s.atoms = {atom("A", "ALA", 1, {3, 0, 0}),    atom("A", "PHE", 2, {0, 3, 0}),    atom("A", "ASP", 3, {-3, 0, 0}),
             atom("A", "LYS", 4, {0, -3, 0}),   atom("B", "ALA", 1, {0, 0, 3}),    atom("B", "PHE", 2, {0, 0, -3}),
             atom("B", "ASP", 3, {40, 0, 0}),   atom("B", "LYS", 4, {40, 3, 0}),   atom("C", "GLY", 7, {80, 0, 0}),
             atom("C", "PRO", 8, {80, 3, 0}),   atom("D", "ALA", 1, {0, 40, 0}),   atom("D", "PHE", 2, {3, 40, 0}),
             atom("D", "ASP", 3, {0, 43, 0}),   atom("D", "GLY", 9, {0, 40, 3}),   atom("E", "ALA", 1, {0, 80, 0}),
             atom("E", "GLY", 9, {3, 80, 0}),   atom("E", "GLY", 10, {0, 83, 0})};
  const auto ion = [](const char* name, const char* element, alpha::Vec3 p) {
    molecule::HeteroGroup g;
    g.residue_name = name, g.chain = "A", g.atoms = {molecule::Atom{}};
    g.atoms[0].element = element, g.atoms[0].position = p;
    return g;
  };
  s.hetero_groups = {ion("ZN", "Zn", {0, 0, 5}), ion("MG", "Mg", {0, 9, 0}), ion("CL", "Cl", {0, 0, 2})};
  const auto pocket = [](std::vector<alpha::Index> lining, alpha::Vec3 center) {
    molecule::Cavity c;
    c.lining_atoms = std::move(lining), c.center = center, c.sa_area = 50;
    return c;
  };
  molecule::Cavities cavities;
  cavities.pockets = {pocket({0, 1, 2, 3, 4, 5}, {0, 0, 0}), pocket({4, 5, 6, 7}, {40, 0, 0}),
                      pocket({8, 9}, {80, 0, 0}), pocket({10, 11, 12, 13}, {0, 40, 0}),
                      pocket({14, 15, 16}, {0, 80, 0})};
  cavities.sa_area = 1000;
  const molecule::SiteFeatures features(s, cavities);
  const std::vector<std::string>& names = molecule::site_feature_names();
  const auto value = [&](std::size_t pocket_index, const char* name) {
    return features(cavities.pockets[pocket_index])[std::find(names.begin(), names.end(), name) - names.begin()];
  };
  CHECK(value(0, "lining_chains") == 2);
  CHECK(value(0, "interchain_share") == Approx(2 / 6.0).margin(1e-12));
  CHECK(value(0, "repeat_chains") == 2);  // B and D
  CHECK(value(0, "metal_ions") == 1);
  CHECK(value(0, "surface_share") == Approx(0.05).margin(1e-12));
  CHECK(value(0, "structure_chains") == 5);
  CHECK(value(1, "lining_chains") == 1);  // B's copy, lined by B alone
  CHECK(value(1, "interchain_share") == 0);
  CHECK(value(1, "repeat_chains") == 2);  // A and D
  CHECK(value(2, "lining_chains") == 1);
  CHECK(value(2, "repeat_chains") == 0);
  CHECK(value(2, "metal_ions") == 0);
  CHECK(value(4, "repeat_chains") == 0);
}

TEST_CASE("ligandability: a homo-dimer built from 1fkgA repeats its sites; an added zinc ion is seen",
          "[ligandability]") {
  const molecule::Structure monomer = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb");
  alpha::Vec3 centroid{};
  for (const molecule::Atom& a : monomer.atoms) centroid = centroid + (1.0 / double(monomer.atoms.size())) * a.position;
  molecule::Structure dimer = monomer;
  for (const molecule::Atom& a : monomer.atoms) {
    molecule::Atom b = a;
    b.chain = "B";  // turned half a turn about z, its centroid 128 A from the first's: no site touches both
    b.position = {2 * centroid.x + 128 - a.position.x, 2 * centroid.y - a.position.y, a.position.z};
    dimer.atoms.push_back(b);
  }
  const std::vector<std::string>& names = molecule::site_feature_names();
  const auto column = [&](const char* name) { return std::find(names.begin(), names.end(), name) - names.begin(); };
  const molecule::PocketSearch one = molecule::search_pockets(monomer, {});
  const molecule::SiteFeatures one_features(monomer, one.cavities);
  for (const molecule::Site& site : molecule::site_candidates(one.cavities)) {
    const std::vector<double> f = one_features(one.cavities.cavity(site));
    CHECK(f[column("repeat_chains")] == 0);
    CHECK(f[column("structure_chains")] == 1);
  }
  const molecule::PocketSearch two = molecule::search_pockets(dimer, {});
  const molecule::SiteFeatures two_features(dimer, two.cavities);
  const std::vector<molecule::Site> candidates = molecule::site_candidates(two.cavities);
  CHECK(candidates.size() == 2 * molecule::site_candidates(one.cavities).size());  // each copy's own
  REQUIRE(candidates.size() >= 4);
  std::size_t repeated = 0;
  for (const molecule::Site& site : candidates) {
    const std::vector<double> f = two_features(two.cavities.cavity(site));
    CHECK(f[column("lining_chains")] == 1);
    CHECK(f[column("interchain_share")] == 0);
    CHECK(f[column("structure_chains")] == 2);
    CHECK(f[column("repeat_chains")] <= 1);
    repeated += f[column("repeat_chains")] == 1;
  }
  INFO(candidates.size() << " candidate sites in the dimer");
  CHECK(repeated >= candidates.size() * 9 / 10);  // a copy's site is the other's, up to rounding
  // A zinc ion (not kept: hetero groups alone) 2 A from the top site's centre.
  const molecule::Cavity& top = two.cavities.cavity(two.cavities.sites.front());
  CHECK(two_features(top)[column("metal_ions")] == 0);
  molecule::HeteroGroup zinc;
  zinc.residue_name = "ZN", zinc.chain = "A", zinc.atoms = {molecule::Atom{}};
  zinc.atoms[0].element = "Zn", zinc.atoms[0].position = top.center + alpha::Vec3{2, 0, 0};
  dimer.hetero_groups.push_back(zinc);
  CHECK(molecule::SiteFeatures(dimer, two.cavities)(top)[column("metal_ions")] == 1);
}

TEST_CASE("ligandability: the evaluator follows a hand-made model", "[ligandability]") {
  const LigandabilityModel model(toy_model(kToyTree));
  std::vector<double> x(molecule::site_feature_names().size(), 0.0);
  x[0] = 1.5, x[1] = -2;  // both thresholds met exactly: left, left
  CHECK(model.margin(x) == 0.5 + 2 * 0.25);
  x[1] = -1.9;
  CHECK(model.margin(x) == 0.5 + 2 * -1);
  x[0] = 1.50000001;  // rounds to the float 1.5: still left (scikit-learn compares float32 features)
  CHECK(model.margin(x) == 0.5 + 2 * -1);
  x[0] = 1.6;
  CHECK(model.margin(x) == 0.5 + 2 * 3);
  CHECK(model.probability(-5) == 0.1);
  CHECK(model.probability(0) == 0.1);
  CHECK(model.probability(1) == Approx(0.3).epsilon(1e-15));
  CHECK(model.probability(4) == 0.9);
  CHECK(model.probability(40) == 0.9);
  CHECK(model.rank_score(x) == model.margin(x));  // no ranking ensemble: the margin ranks
  CHECK_THROWS_AS(model.margin(std::vector<double>(3, 0.0)), alpha::Error);
  // A ranking ensemble (here the same tree, init -1, scale 0.5) gives the
  // rank score and leaves the margin and probability to the classifier.
  std::string ranked = toy_model(kToyTree);
  ranked.insert(ranked.size() - 1, R"(,"ranking":{"init":-1,"scale":0.5,"trees":[)" + kToyTree + "]}");
  const LigandabilityModel with_ranking(ranked);
  CHECK(with_ranking.margin(x) == 0.5 + 2 * 3);
  CHECK(with_ranking.rank_score(x) == -1 + 0.5 * 3);
  x[0] = 0, x[1] = -3;
  CHECK(with_ranking.margin(x) == 0.5 + 2 * 0.25);
  CHECK(with_ranking.rank_score(x) == -1 + 0.5 * 0.25);
}

TEST_CASE("ligandability: malformed models are refused", "[ligandability]") {
  CHECK_THROWS_AS(LigandabilityModel("{"), alpha::Error);
  CHECK_THROWS_AS(LigandabilityModel(R"({"features":["x"],"init":0,"scale":1,"trees":[],"calibration":{"x":[0],"y":[0]}})"),
                  alpha::Error);  // other features
  // A child before its parent (a walk could loop), a feature out of range,
  // arrays of different lengths, unsorted knots.
  std::string loop = kToyTree;
  loop.replace(loop.find(R"("left":[1)"), 9, R"("left":[0)");
  CHECK_THROWS_AS(LigandabilityModel(toy_model(loop)), alpha::Error);
  std::string far = kToyTree;
  far.replace(far.find(R"("feature":[0)"), 12, R"("feature":[999)");
  CHECK_THROWS_AS(LigandabilityModel(toy_model(far)), alpha::Error);
  std::string short_value = kToyTree;
  short_value.replace(short_value.find(",-1]}"), 5, "]}");
  CHECK_THROWS_AS(LigandabilityModel(toy_model(short_value)), alpha::Error);
  CHECK_THROWS_AS(LigandabilityModel(toy_model(kToyTree, R"("x":[4,0],"y":[0.1,0.9])")), alpha::Error);
  // Not a model's JSON: a key missing, text after the model, a fraction for
  // a child, a string with an escape.
  std::string no_scale = toy_model(kToyTree);
  no_scale.replace(no_scale.find(R"("scale":2,)"), 10, "");
  CHECK_THROWS_AS(LigandabilityModel(no_scale), alpha::Error);
  CHECK_THROWS_AS(LigandabilityModel(toy_model(kToyTree) + "}"), alpha::Error);
  std::string fraction = kToyTree;
  fraction.replace(fraction.find(R"("right":[2)"), 10, R"("right":[2.5)");
  CHECK_THROWS_AS(LigandabilityModel(toy_model(fraction)), alpha::Error);
  CHECK_THROWS_AS(LigandabilityModel(R"({"format":"a\"b",)" + toy_model(kToyTree).substr(1)), alpha::Error);
  // A ranking ensemble without its trees, or with a key of no ensemble.
  std::string no_trees = toy_model(kToyTree), other_key = no_trees;
  no_trees.insert(no_trees.size() - 1, R"(,"ranking":{"init":0,"scale":1})");
  CHECK_THROWS_AS(LigandabilityModel(no_trees), alpha::Error);
  other_key.insert(other_key.size() - 1, R"(,"ranking":{"init":0,"scale":1,"trees":[],"calibration":1})");
  CHECK_THROWS_AS(LigandabilityModel(other_key), alpha::Error);
  CHECK_NOTHROW(LigandabilityModel(toy_model(kToyTree)));
  // White space between tokens, and notes, are read over.
  std::string spaced;
  for (const char c : R"({"format":"a model",)" + toy_model(kToyTree).substr(1))
    spaced += std::string(c == ',' || c == ':' || c == '[' || c == '{' ? "\n\t " : "") + c + (c == ']' ? " " : "");
  std::vector<double> x(molecule::site_feature_names().size(), 0.0);
  x[0] = 2;
  CHECK(LigandabilityModel(spaced).margin(x) == 0.5 + 2 * 3);
}

TEST_CASE("ligandability: search_pockets ranks the sites by the model's rank score, or geometrically", "[ligandability]") {
  const molecule::Structure s = molecule::read_structure(std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb");
  const molecule::PocketSearch by_model = molecule::search_pockets(s, {});
  const molecule::PocketSearch geometric = molecule::search_pockets(s, {}, molecule::SiteRanking::geometric);
  const molecule::Cavities& a = by_model.cavities;
  const molecule::Cavities& b = geometric.cavities;
  REQUIRE(a.sites.size() >= 3);
  REQUIRE(a.sites.size() == b.sites.size());
  for (const auto* list : {&a.pockets, &a.voids})
    for (const molecule::Cavity& c : *list) {
      CHECK(c.probability >= 0);
      CHECK(c.probability <= 1);
      CHECK(c.probability == molecule::default_ligandability_model().probability(c.ligandability));
      CHECK(c.rank_score == molecule::default_ligandability_model().rank_score(molecule::SiteFeatures(s, a)(c)));
    }
  bool reordered = false;
  for (std::size_t k = 0; k < a.sites.size(); ++k) {
    if (k > 0) {
      CHECK(a.cavity(a.sites[k - 1]).rank_score >= a.cavity(a.sites[k]).rank_score);
      CHECK(b.cavity(b.sites[k - 1]).score >= b.cavity(b.sites[k]).score);
    }
    reordered |= a.sites[k].is_void != b.sites[k].is_void || a.sites[k].index != b.sites[k].index;
  }
  CHECK(reordered);  // the two rankings differ on this structure
  // On 1ytjA the ranker and the classifier order the sites differently: the
  // ranker's order is kept.
  const molecule::Structure t = molecule::read_structure(std::string(ALPHAPOCKET_TEST_DATA) + "/1ytjA.pdb");
  const molecule::PocketSearch ytj = molecule::search_pockets(t, {});
  const molecule::Cavities& c = ytj.cavities;
  REQUIRE(c.sites.size() >= 2);
  bool by_margin = true;
  for (std::size_t k = 1; k < c.sites.size(); ++k) {
    CHECK(c.cavity(c.sites[k - 1]).rank_score >= c.cavity(c.sites[k]).rank_score);
    by_margin &= c.cavity(c.sites[k - 1]).ligandability >= c.cavity(c.sites[k]).ligandability;
  }
  CHECK(!by_margin);
}
