// SPDX-License-Identifier: Apache-2.0
// The outputs of `alphapocket pockets` (molecule::PocketOutputDir and what
// it writes): report.json against its documented schema (docs/outputs.md),
// pockets.csv, meshes read back through OpenMesh, pockets.pml, pockets.pdb
// read back through the structure reader; hand-made cavities on a grid for
// the meshes; output directory errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "outputs/pocket_colors.hpp"
#include "outputs/pocket_outputs.hpp"
#include "outputs/pocket_report.hpp"
#include "molecule/analysis.hpp"
#include "molecule/ligand_sites.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/residues.hpp"
#include "molecule/structure.hpp"
#include "outputs/structure_copy.hpp"
#include "outputs/tables.hpp"
#include "mesh_checks.hpp"
#include "point_sets.hpp"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;  // keeps the file's key order
using testing::ReadMesh;
using testing::TempDir;

namespace {

const std::string kStructure = std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb";

// The default outputs and the meshes (not written by default).
molecule::OutputSelection with_meshes() {
  molecule::OutputSelection s;
  s.meshes = true;
  return s;
}

// One run on examples/data/1a26A.pdb, written once for all tests below.
struct Run {
  TempDir dir;
  molecule::PocketRun run;
  std::vector<std::string> written;
  json report;

  Run() {
    run.file = kStructure;
    run.options.version = "test";
    run.structure = molecule::read_structure(kStructure);
    run.search = molecule::search_pockets(run.structure, {}, molecule::SiteRanking::probability, /*keep_bodies=*/true);
    run.meshes = molecule::pocket_meshes(run.search, molecule::kDefaultMeshResolution);
    run.ligands = molecule::ligand_sites(run.structure, run.search);
    molecule::PocketOutputDir out((dir / "out").string(), with_meshes());
    written = out.write(run);
    report = json::parse(testing::read_text(dir / "out/report.json"));
  }
  fs::path file(const std::string& name) const { return dir / ("out/" + name); }
};

Run& the_run() {
  static Run run;
  return run;
}

// A field of the shared run changed until the end of the scope.
template <class T>
struct Changed {
  T& field;
  T old;
  Changed(T& f, T value) : field(f), old(std::exchange(f, std::move(value))) {}
  ~Changed() { field = std::move(old); }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!s.empty() && s.back() == sep) parts.emplace_back();
  return parts;
}

// Volume of the tetrahedra of a cavity.
double cells_volume(const alpha::Triangulation& t, const std::vector<alpha::Index>& cells) {
  double v = 0;
  for (const alpha::Index c : cells) {
    const auto& cv = t.cell(c).v;
    v += alpha::tetrahedron_volume(t.point(cv[0]), t.point(cv[1]), t.point(cv[2]), t.point(cv[3]));
  }
  return v;
}

// Faces of the colour c and of its mouth tint.
std::pair<std::size_t, std::size_t> count_colors(const ReadMesh& mesh, molecule::Rgb c) {
  const molecule::Rgb tint = molecule::mouth_tint(c);
  std::size_t plain = 0, tinted = 0;
  for (auto f : mesh.faces()) {
    const auto col = mesh.color(f);
    if (col[0] == c.r && col[1] == c.g && col[2] == c.b) ++plain;
    if (col[0] == tint.r && col[1] == tint.g && col[2] == tint.b) ++tinted;
  }
  return {plain, tinted};
}

void check_number(const json& j, const char* key, bool non_negative = true) {
  INFO(key);
  REQUIRE(j.contains(key));
  REQUIRE(j[key].is_number());
  if (non_negative) CHECK(j[key].get<double>() >= 0);
}

// The cavity entries of report.json: keys, types, ranks 1..n, scores not
// increasing, lining residues = the residues of the lining atoms.
void check_cavities(const json& list, const std::vector<molecule::Cavity>& cavities, const std::string& kind,
                    const molecule::Structure& structure) {
  REQUIRE(list.is_array());
  REQUIRE(list.size() == cavities.size());
  std::set<int> serials;
  for (const molecule::Atom& a : structure.atoms) serials.insert(a.serial);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& p = list[i];
    INFO(kind << " " << i + 1);
    CHECK(p["rank"] == i + 1);
    for (const char* key : {"score", "sa_volume", "sa_area", "ms_volume", "ms_area", "mouth_area", "buriedness",
                            "burial_atoms", "depth", "tetrahedra", "max_probe_radius"})
      check_number(p, key);
    CHECK(p["ms_volume"].get<double>() >= p["sa_volume"].get<double>());
    CHECK(p["mouths_to_outside"].get<std::size_t>() <= p["mouths"].get<std::size_t>());
    for (const char* key : {"max_alpha_sq", "close_alpha_sq", "fill_alpha_sq"}) check_number(p, key, false);
    if (i > 0) CHECK(p["score"].get<double>() <= list[i - 1]["score"].get<double>());
    // 4 significant digits however small (a small molecule's scores are ~1e-6).
    CHECK(p["score"].get<double>() == Approx(cavities[i].score).epsilon(5e-4));
    CHECK(p["tetrahedra"] == cavities[i].cells.size());
    CHECK(p["fill_alpha_sq"].get<double>() > 0);  // empty at alpha_sq = 0
    CHECK(p["max_probe_radius"].get<double>() == Approx(cavities[i].max_probe_radius).margin(5e-4));
    REQUIRE(p["mouths"].is_number_unsigned());
    REQUIRE(p["mouth_areas"].is_array());
    CHECK(p["mouths"] == p["mouth_areas"].size());
    if (kind == "void") {
      CHECK(p["mouths"] == 0);
      CHECK(p["close_alpha_sq"].get<double>() <= 0);
      CHECK(p["depth"] == 0);
    } else {
      CHECK(p["mouths"].get<std::size_t>() >= 1);
    }
    double mouth_sum = 0;
    for (const json& a : p["mouth_areas"]) mouth_sum += a.get<double>();
    CHECK(mouth_sum == Approx(p["mouth_area"].get<double>()).margin(2e-3 * double(p["mouths"].get<std::size_t>())));
    REQUIRE(p["center"].is_array());
    REQUIRE(p["center"].size() == 3);
    for (const json& x : p["center"]) CHECK(x.is_number());
    CHECK(p["mesh"] == "meshes/" + kind + "_" + std::to_string(i + 1) + ".ply");

    REQUIRE(p["lining_atoms"].is_array());
    REQUIRE(p["lining_atoms"].size() == cavities[i].lining_atoms.size());
    CHECK(p["lining_atoms"].size() >= 4);  // at least one tetrahedron's vertices
    std::set<std::string> residues_of_atoms;
    for (const json& a : p["lining_atoms"]) {
      REQUIRE(a["serial"].is_number_integer());
      CHECK(serials.count(a["serial"].get<int>()) == 1);
      REQUIRE(a["name"].is_string());
      REQUIRE(a["element"].is_string());
      residues_of_atoms.insert(a["residue"].get<std::string>());
    }
    std::set<std::string> residues;
    for (const json& r : p["lining_residues"]) {
      const std::string id = r["chain"].get<std::string>() + ":" + r["name"].get<std::string>() + ":" +
                             std::to_string(r["number"].get<int>()) + r["insertion_code"].get<std::string>();
      CHECK(r["id"] == id);
      CHECK(residues.insert(id).second);  // each residue once
    }
    CHECK(residues == residues_of_atoms);
  }
}

}  // namespace

TEST_CASE("pockets outputs: report.json follows its schema", "[pocket_outputs]") {
  const Run& r = the_run();
  const json& j = r.report;
  const molecule::Cavities& cav = r.run.search.cavities;
  REQUIRE(j.is_object());
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  CHECK(keys == std::vector<std::string>{"alphapocket", "input", "parameters", "molecule", "pockets", "voids",
                                         "sites", "ligands", "tunnels"});
  CHECK(j["alphapocket"] == "test");

  const json& in = j["input"];
  CHECK(in["file"] == kStructure);
  CHECK(in["format"] == "PDB");
  CHECK(in["model"] == 1);
  CHECK(in["atoms_kept"] == r.run.structure.atoms.size());
  std::size_t dropped = 0;
  for (const char* why : {"chain", "altloc", "water", "hetero", "hydrogen"}) dropped += in["atoms_dropped"][why].get<std::size_t>();
  CHECK(in["atoms_kept"].get<std::size_t>() + dropped == in["atoms_in_model"].get<std::size_t>());
  CHECK(in["atoms_dropped"]["hetero"] == 27);  // the ligand CNA of 1A26 is not part of the molecule
  CHECK(in["warnings"].is_array());

  const json& par = j["parameters"];
  CHECK(par["probe"] == 1.4);
  CHECK(par["min_volume"] == molecule::CavityOptions{}.min_volume);
  CHECK(par["split_persistence"] == molecule::CavityOptions{}.split_persistence);
  CHECK(par["split_volume"] == molecule::CavityOptions{}.split_volume);
  CHECK(par["split_min_volume"] == molecule::CavityOptions{}.split_min_volume);
  CHECK(par["radii"] == "ProtOr");
  CHECK(par["alpha_sq"] == 0.0);

  const json& mol = j["molecule"];
  CHECK(mol["atoms"] == r.run.structure.atoms.size());
  CHECK(mol["sa_area"].get<double>() > 0);
  CHECK(mol["sa_volume"].get<double>() > 0);
  CHECK(mol["pockets"] == cav.pockets.size());
  CHECK(mol["voids"] == cav.voids.size());
  CHECK(mol["sites"] == cav.sites.size());
  CHECK(mol["tunnels"] == cav.tunnels.size());
  CHECK(mol["mesh"] == "meshes/surface.ply");

  REQUIRE_FALSE(cav.pockets.empty());  // 1A26 has its ligand's pocket, at least
  check_cavities(j["pockets"], cav.pockets, "pocket", r.run.structure);
  check_cavities(j["voids"], cav.voids, "void", r.run.structure);

  // Each site names its cavity, whose score it repeats, and gives its
  // (cluster's) centre.
  REQUIRE(j["sites"].size() == cav.sites.size());
  for (std::size_t i = 0; i < cav.sites.size(); ++i) {
    const json& site = j["sites"][i];
    INFO("site " << i + 1);
    CHECK(site["rank"] == i + 1);
    CHECK(site["kind"] == (cav.sites[i].is_void ? "void" : "pocket"));
    CHECK(site["cavity_rank"] == cav.sites[i].index + 1);
    const json& cavity = j[cav.sites[i].is_void ? "voids" : "pockets"].at(cav.sites[i].index);
    for (const char* key : {"score", "sa_volume", "lining_residues"}) CHECK(site[key] == cavity[key]);
    const alpha::Vec3& c = cav.sites[i].center;
    const double xyz[] = {c.x, c.y, c.z};
    for (int k = 0; k < 3; ++k) CHECK(site["center"][k].get<double>() == Approx(xyz[k]).margin(1e-3));
  }

  REQUIRE(j["tunnels"].size() == cav.tunnels.size());
  for (std::size_t i = 0; i < cav.tunnels.size(); ++i) {
    const json& t = j["tunnels"][i];
    INFO("tunnel " << i + 1);
    CHECK(t["rank"] == i + 1);
    // Alive at alpha_sq = 0: born at or before, dies after.
    CHECK(t["birth_alpha_sq"].get<double>() <= 0);
    CHECK(t["death_alpha_sq"].get<double>() > 0);
    if (i > 0) CHECK(t["death_alpha_sq"].get<double>() <= j["tunnels"][i - 1]["death_alpha_sq"].get<double>());
    check_number(t, "bottleneck_radius");
    const alpha::Vec3& c = cav.tunnels[i].bottleneck_center;
    REQUIRE(t["bottleneck_center"].size() == 3);
    CHECK(t["bottleneck_center"][0].get<double>() == Approx(c.x).margin(1e-3));
    CHECK(t["bottleneck_center"][1].get<double>() == Approx(c.y).margin(1e-3));
    CHECK(t["bottleneck_center"][2].get<double>() == Approx(c.z).margin(1e-3));
    CHECK(t["lining_atoms"].size() == 3);  // the bottleneck triangle
    CHECK(t["lining_residues"].size() >= 1);
    CHECK(t["lining_residues"].size() <= 3);
  }
}

TEST_CASE("pockets outputs: pockets.csv has one row per pocket, as in report.json", "[pocket_outputs]") {
  const Run& r = the_run();
  const std::vector<std::string> lines = lines_of(testing::read_text(r.file("pockets.csv")));
  REQUIRE(lines.size() == 1 + r.run.search.cavities.pockets.size());
  CHECK(lines[0] ==
        "rank,score,probability,sa_volume,ms_volume,sa_area,ms_area,mouths,mouth_area,depth,center_x,center_y,"
        "center_z,lining_residues,residues,mean_plddt");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    INFO(lines[i]);
    const std::vector<std::string> f = split(lines[i], ',');
    REQUIRE(f.size() == 16);
    CHECK(f[15].empty());  // an experimental structure: no pLDDT
    const json& p = r.report["pockets"][i - 1];
    CHECK(std::stoul(f[0]) == i);
    CHECK(std::stod(f[1]) == p["score"].get<double>());
    CHECK(std::stod(f[2]) == p["probability"].get<double>());
    CHECK(std::stod(f[2]) == Approx(r.run.search.cavities.pockets[i - 1].probability).margin(5e-5));
    CHECK(std::stod(f[3]) == p["sa_volume"].get<double>());  // the same text
    CHECK(std::stod(f[4]) == p["ms_volume"].get<double>());
    CHECK(std::stod(f[6]) == p["ms_area"].get<double>());
    CHECK(std::stoul(f[7]) == p["mouths"].get<std::size_t>());
    CHECK(std::stod(f[10]) == p["center"][0].get<double>());
    CHECK(std::stoul(f[13]) == p["lining_residues"].size());
    std::string ids;
    for (const json& res : p["lining_residues"]) {
      if (!ids.empty()) ids += ' ';
      ids += res["id"].get<std::string>();
    }
    CHECK(f[14] == ids);
  }
}

TEST_CASE("pockets outputs: the surface and the casts are closed manifolds of the reported volumes, coloured by site",
          "[pocket_outputs]") {
  const Run& r = the_run();
  const molecule::CavityColors colors = molecule::cavity_colors(r.run.search.cavities);
  const molecule::CavityRanks ranks = molecule::cavity_ranks(r.run.search.cavities);
  auto check_list = [&](const std::vector<molecule::Cavity>& list, const std::vector<molecule::Rgb>& color,
                        const std::vector<std::size_t>& rank, const std::string& kind) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const molecule::Cavity& c = list[i];
      INFO(kind << " " << i + 1 << ": ms_volume " << c.ms_volume);
      const ReadMesh mesh = testing::read_back(r.file(molecule::cavity_mesh_path(kind, i + 1, "ply")), true);
      CHECK(testing::closed_and_consistent(mesh));
      // The cast holds the cavity's space as the molecular surface bounds
      // it: ms_volume, up to the lattice's error, which the smallest
      // pockets feel most (1a26A: -1.4% at worst from 10 A^3 up, -2.4%
      // for its 7 A^3 pocket).
      CHECK(testing::signed_volume(mesh) == Approx(c.ms_volume).epsilon(c.ms_volume >= 10 ? 0.015 : 0.03));
      CHECK(count_colors(mesh, color.at(i)).first == mesh.n_faces());
      const auto sites = testing::vertex_sites(r.file(molecule::cavity_mesh_path(kind, i + 1, "ply")));
      CHECK(std::count(sites.begin(), sites.end(), int(rank.at(i))) == long(sites.size()));
    }
  };
  check_list(r.run.search.cavities.pockets, colors.pockets, ranks.pockets, "pocket");
  check_list(r.run.search.cavities.voids, colors.voids, ranks.voids, "void");

  const ReadMesh surface = testing::read_back(r.file("meshes/surface.ply"), true);
  CHECK(testing::closed_and_consistent(surface));
  // examples/data/1a26A.pdb's molecular volume (docs/cli.md, surface --json).
  CHECK(testing::signed_volume(surface) == Approx(44941.63).epsilon(0.01));
  // Every site is painted on it, with its rank as the vertices' site.
  const auto sites = testing::vertex_sites(r.file("meshes/surface.ply"));
  REQUIRE(sites.size() == surface.n_vertices());
  for (std::size_t k = 1; k <= r.run.search.cavities.sites.size(); ++k) {
    INFO("site " << k);
    CHECK(std::count(sites.begin(), sites.end(), int(k)) > 0);
    CHECK(count_colors(surface, molecule::rank_color(k)).first > 0);
  }
  CHECK(std::count(sites.begin(), sites.end(), 0) > long(sites.size() / 2));  // grey elsewhere
}

TEST_CASE("pockets outputs: the analysis makes the meshes when its outputs include them, and only then",
          "[pocket_outputs]") {
  const Run& r = the_run();
  molecule::AnalysisOptions options;
  CHECK(!options.outputs.meshes);  // not unless asked: they cost 10-20 times the analysis
  options.outputs.meshes = true;
  const molecule::Analysis a = molecule::analyse(kStructure, options);
  REQUIRE(a.meshes);
  // Of the search's own body, the same as from a search that kept it;
  // the body is freed once meshed.
  CHECK(a.meshes->surface.points == r.run.meshes->surface.points);
  CHECK(a.meshes->surface.face_colors == r.run.meshes->surface.face_colors);
  CHECK(a.meshes->pockets.size() == a.search.cavities.pockets.size());
  CHECK(a.meshes->voids.size() == a.search.cavities.voids.size());
  CHECK(!a.search.bodies.accessible);
  CHECK(!a.search.bodies.excluded);
  CHECK(a.mesh_format() == "ply");

  options.outputs.meshes = false;
  const molecule::Analysis b = molecule::analyse(kStructure, options);
  CHECK(!b.meshes);
  CHECK(!b.search.bodies.excluded);
  CHECK(b.mesh_format().empty());
}

TEST_CASE("pockets outputs: cavity colours follow the site ranking, then the other pockets and voids", "[pocket_outputs]") {
  molecule::Cavities cav;
  cav.pockets.resize(3);
  cav.voids.resize(3);
  // Void 2 is the second site; pocket 3 (of a low probability) and voids 1
  // and 3 are no sites.
  cav.sites = {{false, 0}, {true, 1}, {false, 1}};
  const molecule::CavityColors colors = molecule::cavity_colors(cav);
  using molecule::rank_color;
  CHECK(colors.pockets == std::vector<molecule::Rgb>{rank_color(1), rank_color(3), rank_color(4)});
  CHECK(colors.voids == std::vector<molecule::Rgb>{rank_color(5), rank_color(2), rank_color(6)});
  // No colour repeats (a cycle of 12 made site 13 red like site 1), nor
  // is the molecule's, the tunnels' or the ligands'.
  std::set<std::tuple<int, int, int>> seen;
  for (const molecule::Rgb c : {molecule::kMoleculeColor, molecule::kTunnelColor, molecule::kLigandColor})
    seen.insert({c.r, c.g, c.b});
  for (std::size_t rank = 1; rank <= 250; ++rank) {
    const molecule::Rgb c = rank_color(rank);
    INFO(rank);
    CHECK(seen.insert({c.r, c.g, c.b}).second);
  }
}

TEST_CASE("pockets outputs: tunnel colours are distinct cyans, apart from the shown sites'", "[pocket_outputs]") {
  std::set<std::tuple<int, int, int>> seen;
  for (std::size_t rank = 1; rank <= 12; ++rank) {
    const molecule::Rgb c = molecule::rank_color(rank);
    seen.insert({c.r, c.g, c.b});
  }
  for (std::size_t k = 0; k < 30; ++k) {
    const molecule::Rgb c = molecule::tunnel_color(k);
    INFO("tunnel " << k << ": " << int(c.r) << " " << int(c.g) << " " << int(c.b));
    CHECK(seen.insert({c.r, c.g, c.b}).second);
    // Hue between 170 and 205 degrees: green and blue well above red.
    const int hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    REQUIRE(hi > lo);
    const double hue = 60 * (4 + double(c.r - c.g) / (hi - lo));  // blue largest
    const double hue_g = 60 * (2 + double(c.b - c.r) / (hi - lo));  // green largest
    CHECK((c.b >= c.g ? hue : hue_g) >= 170);
    CHECK((c.b >= c.g ? hue : hue_g) <= 205);
  }
}

namespace {

// The atom ids of "select NAME, [NAME or ](OBJ and id 1-3+7)" lines, by
// selection name.
std::map<std::string, std::set<std::size_t>> pml_selections(const std::string& pml, const std::string& obj) {
  std::map<std::string, std::set<std::size_t>> selected;
  const std::regex kLine("select (\\w+), (?:\\1 or )?\\(" + obj + " and id ([0-9+-]+)\\)");
  for (const std::string& line : lines_of(pml)) {
    std::smatch m;
    if (!std::regex_match(line, m, kLine)) continue;
    for (const std::string& run : split(m[2], '+')) {
      const std::size_t dash = run.find('-');
      const std::size_t first = std::stoul(run.substr(0, dash));
      const std::size_t last = dash == std::string::npos ? first : std::stoul(run.substr(dash + 1));
      for (std::size_t id = first; id <= last; ++id) selected[m[1]].insert(id);
    }
  }
  return selected;
}

}  // namespace

TEST_CASE("pockets outputs: pockets.pml selects the lining atoms and marks the centres", "[pocket_outputs]") {
  const Run& r = the_run();
  const std::string pml = testing::read_text(r.file("pockets.pml"));
  // It loads the copy beside it, never the input by its path.
  CHECK(pml.find("\"structure.cif\"), \"1a26A\")\n") != std::string::npos);
  CHECK(pml.find(kStructure + "\"") == std::string::npos);
  const std::map<std::string, std::set<std::size_t>> selected = pml_selections(pml, "1a26A");
  std::map<std::string, std::vector<double>> centers;
  for (const std::string& line : lines_of(pml)) {
    if (line.rfind("pseudoatom ", 0) != 0) continue;
    const std::string name = line.substr(11, line.find(',') - 11);
    double x = 0, y = 0, z = 0;
    REQUIRE(std::sscanf(line.c_str() + line.find("pos=["), "pos=[%lf, %lf, %lf]", &x, &y, &z) == 3);
    if (name.find("_space") == std::string::npos) centers[name] = {x, y, z};
  }
  const std::vector<molecule::Atom>& atoms = r.run.structure.atoms;
  const molecule::CavityColors colors = molecule::cavity_colors(r.run.search.cavities);
  const auto check = [&](const json& list, const std::vector<molecule::Rgb>& color, const std::string& kind) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string name = kind + "_" + std::to_string(i + 1);
      INFO(name);
      std::set<int> serials;  // of the report's lining atoms, against those of the selected ids
      for (const json& a : list[i]["lining_atoms"]) serials.insert(a["serial"].get<int>());
      std::set<int> picked;
      REQUIRE(selected.count(name) == 1);
      for (const std::size_t id : selected.at(name)) picked.insert(atoms.at(id - 1).serial);
      REQUIRE(!serials.empty());
      CHECK(picked == serials);
      REQUIRE(centers.count(name + "_center") == 1);
      for (int k = 0; k < 3; ++k)  // both print 3 decimals, rounded on their own
        CHECK(centers[name + "_center"][k] == Approx(list[i]["center"][k].get<double>()).margin(1.1e-3));
      const molecule::Rgb c = color.at(i);
      CHECK(pml.find("set_color ap_" + name + ", [" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " +
                     std::to_string(c.b) + "]\n") != std::string::npos);
    }
  };
  check(r.report["pockets"], colors.pockets, "pocket");
  check(r.report["voids"], colors.voids, "void");
  // The ligand (CNA, left out of the search) is in the copy and selected.
  REQUIRE(selected.count("ligands") == 1);
  CHECK(selected.at("ligands").size() == r.run.structure.hetero_groups.at(0).atoms.size());
  CHECK(*selected.at("ligands").begin() == atoms.size() + 1);
  // Tunnels: the bottleneck's atoms, and a sphere of the bottleneck radius
  // at its centre.
  const json& tunnels = r.report["tunnels"];
  REQUIRE(!tunnels.empty());
  for (std::size_t i = 0; i < tunnels.size(); ++i) {
    const std::string name = "tunnel_" + std::to_string(i + 1);
    INFO(name);
    CHECK(selected.at(name).size() == 3);
    REQUIRE(centers.count(name + "_bottleneck") == 1);
    for (int k = 0; k < 3; ++k)
      CHECK(centers[name + "_bottleneck"][k] ==
            Approx(tunnels[i]["bottleneck_center"][k].get<double>()).margin(1.1e-3));
  }
  CHECK(pml.find("show spheres, tunnel_*_bottleneck\n") != std::string::npos);
  CHECK(centers.size() == r.report["pockets"].size() + r.report["voids"].size() + tunnels.size());
  // The best site (report.json's first; the model ranks them) is in the middle of the view.
  const json& best = r.report["sites"].at(0);
  const std::string top = best["kind"].get<std::string>() + "_" + std::to_string(best["cavity_rank"].get<int>());
  CHECK(pml.find("\norient " + top + "_space or byres " + top + "\n") != std::string::npos);
}

TEST_CASE("pockets outputs: structure.cif reads back as the atoms searched, then the ligands", "[pocket_outputs]") {
  const Run& r = the_run();
  molecule::StructureOptions all;
  all.keep_hetero = true;
  const molecule::Structure copy = molecule::read_structure(r.file("structure.cif").string(), all);
  CHECK(copy.report.format == "mmCIF");
  const std::vector<molecule::Atom>& atoms = r.run.structure.atoms;
  const std::vector<molecule::Atom>& ligand = r.run.structure.hetero_groups.at(0).atoms;
  REQUIRE(copy.atoms.size() == atoms.size() + ligand.size());
  for (std::size_t i = 0; i < copy.atoms.size(); ++i) {
    const molecule::Atom& a = copy.atoms[i];
    const molecule::Atom& b = i < atoms.size() ? atoms[i] : ligand[i - atoms.size()];
    INFO(i);
    CHECK(a.serial == int(i + 1));
    CHECK(std::tie(a.name, a.residue_name, a.chain, a.seq_num, a.icode, a.element) ==
          std::tie(b.name, b.residue_name, b.chain, b.seq_num, b.icode, b.element));
    CHECK(alpha::norm(a.position - b.position) < 1e-3);
  }
}

TEST_CASE("pockets outputs: pockets.pdb reads back with one STP residue per cavity", "[pocket_outputs]") {
  const Run& r = the_run();
  const std::string text = testing::read_text(r.file("pockets.pdb"));
  std::size_t centers = 0;
  for (const std::string& line : lines_of(text)) {
    if (line.rfind("HETATM", 0) != 0) continue;
    CHECK(line.size() == 80);
    CHECK(line.substr(17, 3) == "STP");
    centers += line.substr(12, 4) == " CEN" || line.substr(12, 4) == " BTN";
  }
  const std::vector<molecule::Tunnel>& tunnels = r.run.search.cavities.tunnels;
  REQUIRE(!tunnels.empty());
  CHECK(centers == r.run.search.cavities.pockets.size() + r.run.search.cavities.voids.size() + tunnels.size());

  molecule::StructureOptions keep;
  keep.keep_hetero = true;
  const molecule::Structure back = molecule::read_structure(r.file("pockets.pdb").string(), keep);
  REQUIRE(back.hetero_groups.size() == centers);
  std::map<std::string, std::size_t> next_rank{{"P", 1}, {"V", 1}, {"T", 1}};
  for (const molecule::HeteroGroup& g : back.hetero_groups) {
    INFO(g.chain << g.seq_num);
    CHECK(g.residue_name == "STP");
    REQUIRE(next_rank.count(g.chain) == 1);
    CHECK(std::size_t(g.seq_num) == next_rank[g.chain]++);  // residue number = rank
    if (g.chain == "T") {  // a tunnel: its bottleneck, B = its radius
      const molecule::Tunnel& t = tunnels[std::size_t(g.seq_num) - 1];
      REQUIRE(g.atoms.size() == 1);
      CHECK(g.atoms[0].name == "BTN");
      CHECK(g.atoms[0].position.y == Approx(t.bottleneck_center.y).margin(1e-3));
      CHECK(g.atoms[0].b_factor == Approx(t.bottleneck_radius).margin(0.006));
      continue;
    }
    const molecule::Cavity& c =
        (g.chain == "P" ? r.run.search.cavities.pockets : r.run.search.cavities.voids)[std::size_t(g.seq_num) - 1];
    REQUIRE(g.atoms.front().name == "CEN");
    CHECK(g.atoms.front().position.x == Approx(c.center.x).margin(1e-3));
    CHECK(g.atoms.front().position.z == Approx(c.center.z).margin(1e-3));
    CHECK(g.atoms.size() >= 2);  // a cavity drains into at least one sink
    for (std::size_t k = 1; k < g.atoms.size(); ++k) CHECK(g.atoms[k].name == "SNK");
  }
}

TEST_CASE("pockets outputs: residues with insertion codes, CSV quoting", "[pocket_outputs]") {
  molecule::Structure s;
  const auto atom = [](int serial, const char* chain, const char* res, int num, char icode) {
    molecule::Atom a;
    a.serial = serial;
    a.name = "CA";
    a.element = "C";
    a.chain = chain;
    a.residue_name = res;
    a.seq_num = num;
    a.icode = icode;
    return a;
  };
  s.atoms = {atom(1, "A", "TYR", 42, '\0'), atom(2, "A", "TYR", 42, '\0'), atom(3, "A", "GLY", 42, 'B'),
             atom(4, "x,y", "SER", -3, '\0')};
  CHECK(molecule::residue_id(s.atoms[2]) == "A:GLY:42B");
  CHECK(molecule::residue_id(s.atoms[3]) == "x,y:SER:-3");
  CHECK(molecule::residues_of(s.atoms, {3, 1, 0, 2}) == std::vector<alpha::Index>{0, 2, 3});
  CHECK_THROWS_AS(molecule::residues_of(s.atoms, {4}), alpha::Error);

  molecule::PocketSearch search;
  molecule::Cavity c;
  c.lining_atoms = {0, 1, 2, 3};
  c.mouths.resize(1);
  search.cavities.pockets = {c};
  molecule::PocketRun run;
  run.structure = s;
  run.search = std::move(search);
  const std::vector<std::string> lines = lines_of(molecule::pockets_csv(run));
  REQUIRE(lines.size() == 2);
  CHECK(lines[1].substr(lines[1].rfind(",3,")) == ",3,\"A:TYR:42 A:GLY:42B x,y:SER:-3\",");

  const auto report = molecule::pocket_report(run);
  const auto& residues = report["pockets"][0]["lining_residues"];
  REQUIRE(residues.size() == 3);
  CHECK(residues[1]["insertion_code"] == "B");
  CHECK(residues[0]["insertion_code"] == "");
  CHECK(residues[2]["number"] == -3);
  CHECK(report["pockets"][0].count("mesh") == 0);  // no mesh format: no meshes
}

TEST_CASE("pockets outputs: the ligands' sites are the run's, one per hetero group", "[pocket_outputs]") {
  const Run& r = the_run();
  REQUIRE(r.run.structure.hetero_groups.size() == r.run.ligands.size());
  REQUIRE(!r.run.ligands.empty());
  // Hand-made sites for each group: report.json writes what it is given.
  std::vector<molecule::LigandSite> ligands = r.run.ligands;
  for (molecule::LigandSite& l : ligands) {
    l.site = l.nearest_site = 2;
    l.distance = 1.23456;
    l.atoms_in_site = 1;
    l.holding = {{1, 3}, {2, 1}};
  }
  Changed<std::vector<molecule::LigandSite>> given(the_run().run.ligands, ligands);
  const molecule::PocketRun& run = r.run;
  const json report = molecule::pocket_report(run);
  REQUIRE(report["ligands"].size() == ligands.size());
  const molecule::HeteroGroup& g = r.run.structure.hetero_groups[0];
  CHECK(report["ligands"][0]["site"] == 2);
  CHECK(report["ligands"][0]["atoms_in_site"] == 1);
  CHECK(report["ligands"][0]["in_sites"][0]["atoms"] == 3);
  if (!g.kept) CHECK(report["ligands"][0]["distance"] == 1.235);
  // Every site a group lies in lists it, no other.
  for (std::size_t rank = 1; rank <= report["sites"].size(); ++rank)
    CHECK(report["sites"][rank - 1]["ligands"].size() == (rank <= 2 ? ligands.size() : 0));

  // A run without them, or with a number other than the groups', is a caller's bug.
  const auto kind = [&] {
    try {
      molecule::pocket_report(run);
    } catch (const alpha::Error& e) {
      return e.kind();
    }
    return alpha::ErrorKind::Internal;  // not thrown
  };
  the_run().run.ligands.clear();
  CHECK(kind() == alpha::ErrorKind::Misuse);
  ligands.pop_back();
  the_run().run.ligands = ligands;
  CHECK(kind() == alpha::ErrorKind::Misuse);
}

TEST_CASE("pockets outputs: structure.cif quotes CIF reserved words and keeps printf's digits", "[pocket_outputs]") {
  molecule::Structure s;
  const std::vector<std::string> chains{"Loop_A", "data_1", "STOP_", "Global_x", "save_", "_A", "B"};
  for (std::size_t k = 0; k < chains.size(); ++k) {
    molecule::Atom a;
    a.serial = int(k + 1);
    a.name = "CA";
    a.element = "C";
    a.chain = chains[k];
    a.residue_name = "ALA";
    a.seq_num = int(k + 1);
    a.position = {-1.0005 - 3.0 * double(k), 12.3125, 0.0625};  // halfway between two 3-decimal values: even wins
    a.occupancy = 0.125f;  // ties at 2 decimals too: 0.12
    a.b_factor = 20.125f;
    s.atoms.push_back(a);
  }
  const std::string cif = molecule::structure_copy(s, "x").cif;
  CHECK(cif.find(" 'Loop_A' ") != std::string::npos);
  CHECK(cif.find(" 'STOP_' ") != std::string::npos);
  CHECK(cif.find(" B ") != std::string::npos);  // a plain word stays bare
  CHECK(cif.find(" 12.312 0.062 0.12 20.12 ") != std::string::npos);
  molecule::StructureOptions all;
  all.keep_hetero = true;  // one-residue chains read as hetero groups
  const molecule::Structure copy = molecule::parse_structure(cif, "copy", all);
  REQUIRE(copy.atoms.size() == s.atoms.size());
  for (const molecule::Atom& a : copy.atoms) {  // read back in another order: by residue number
    REQUIRE(a.seq_num >= 1);
    REQUIRE(a.seq_num <= int(chains.size()));
    CHECK(a.chain == chains[a.seq_num - 1]);
    CHECK(alpha::norm(a.position - s.atoms[a.seq_num - 1].position) < 1e-3);
  }
}

TEST_CASE("pockets outputs: structure.cif of a file with several models holds the model searched",
          "[pocket_outputs]") {
  const std::string file = std::string(ALPHAPOCKET_TEST_DATA) + "/1d3z_models_1_2.pdb.gz";
  molecule::StructureOptions second;
  second.model = 2;
  const molecule::Structure s = molecule::read_structure(file, second);
  CHECK(s.report.models == 2);
  const molecule::Structure copy = molecule::parse_structure(molecule::structure_copy(s, "x").cif, "copy");
  CHECK(copy.report.models == 1);
  REQUIRE(copy.atoms.size() == s.atoms.size());
  for (std::size_t i = 0; i < s.atoms.size(); ++i) CHECK(alpha::norm(copy.atoms[i].position - s.atoms[i].position) < 1e-3);
  // Model 1 differs there: the copy is not the first model.
  const molecule::Structure first = molecule::read_structure(file);
  CHECK(alpha::norm(first.atoms[0].position - copy.atoms[0].position) > 1e-3);
}

TEST_CASE("pockets outputs: output directory errors leave nothing behind", "[pocket_outputs]") {
  TempDir dir;
  std::ofstream(dir / "file") << "x";
  const auto one_line_naming = [](const std::string& path, const std::function<void()>& f) {
    try {
      f();
      FAIL("no error");
    } catch (const alpha::Error& e) {
      const std::string what = e.what();
      CHECK(what.find(path) == 0);
      CHECK(what.find('\n') == std::string::npos);
    }
  };
  // Under a regular file (works as root too, unlike a read-only directory).
  const std::string under_file = (dir / "file/out").string();
  one_line_naming(under_file, [&] { molecule::PocketOutputDir out(under_file); });
  // A regular file of that name.
  one_line_naming((dir / "file").string(), [&] { molecule::PocketOutputDir out((dir / "file").string()); });
  // A missing parent.
  const std::string orphan = (dir / "missing/out").string();
  one_line_naming(orphan, [&] { molecule::PocketOutputDir out(orphan); });
  CHECK(dir.files() == std::vector<std::string>{"file"});

  // A run that fails before writing removes the directories it created,
  // and only those.
  { molecule::PocketOutputDir out((dir / "new").string()); }
  CHECK_FALSE(fs::exists(dir / "new"));
  fs::create_directory(dir / "old");
  { molecule::PocketOutputDir out((dir / "old").string()); }
  CHECK(fs::is_directory(dir / "old"));
  CHECK_FALSE(fs::exists(dir / "old/meshes"));
}

TEST_CASE("pockets outputs: an earlier run is replaced whole, other files are refused", "[pocket_outputs]") {
  const Run& r = the_run();
  TempDir dir;
  fs::create_directories(dir / "out/meshes");
  for (const char* name : {"pocket_999.ply", "void_1.stl", "molecule.ply", "surface.obj"})
    std::ofstream(dir / ("out/meshes/" + std::string(name))) << "old";
  std::ofstream(dir / "out/tunnels.csv") << "old";
  const Changed<std::string> obj(the_run().run.options.mesh_format, "obj");
  const molecule::PocketRun& run = r.run;
  molecule::OutputSelection selection = with_meshes();
  selection.tunnels = false;  // no tunnel files this time
  const std::vector<std::string> written = molecule::PocketOutputDir((dir / "out").string(), selection).write(run);
  CHECK(std::count(written.begin(), written.end(), "meshes/surface.obj") == 1);
  CHECK(std::count(written.begin(), written.end(), "meshes/surface.mtl") == 1);
  CHECK(std::count(written.begin(), written.end(), "tunnels.csv") == 0);
  // Exactly the files written, none of the earlier run's, nothing beside.
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir / "out"))
    if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir / "out").string());
  std::vector<std::string> expected = written;
  std::sort(files.begin(), files.end());
  std::sort(expected.begin(), expected.end());
  CHECK(files == expected);
  CHECK(testing::read_text(dir / "out/meshes/surface.obj") != "old");
  CHECK(dir.files() == std::vector<std::string>{"out"});

  // Anything else in it (a file of another name, a directory where a file
  // of ours goes) is refused, before and after the work, naming it.
  std::ofstream(dir / "out/meshes/notes.txt") << "mine";
  CHECK_THROWS_WITH(molecule::PocketOutputDir((dir / "out").string()),
                    Catch::Contains("holds files that are not alphapocket outputs ('meshes/notes.txt')"));
  fs::remove(dir / "out/meshes/notes.txt");
  molecule::PocketOutputDir out((dir / "out").string(), selection);
  fs::create_directory(dir / "out/report.json.d");
  CHECK_THROWS_WITH(out.write(run), Catch::Contains("('report.json.d')"));
  CHECK(testing::read_text(dir / "out/meshes/surface.obj") != "old");
  CHECK(dir.files() == std::vector<std::string>{"out"});
}

TEST_CASE("pockets outputs: a write that fails leaves the earlier run as it was", "[pocket_outputs]") {
  const Run& r = the_run();
  TempDir dir;
  molecule::PocketOutputDir out((dir / "out").string(), with_meshes());
  out.write(r.run);
  // A directory where a file of ours goes appears while the run works.
  fs::remove(dir / "out/meshes/surface.ply");
  fs::create_directory(dir / "out/meshes/surface.ply");
  std::map<std::string, std::string> before;
  for (const auto& e : fs::recursive_directory_iterator(dir / "out"))
    if (e.is_regular_file()) before[e.path().string()] = testing::read_text(e.path());
  const Changed<std::string> other(the_run().run.options.version, "other");
  CHECK_THROWS_WITH(out.write(r.run), Catch::Contains("meshes/surface.ply"));
  std::map<std::string, std::string> after;
  for (const auto& e : fs::recursive_directory_iterator(dir / "out"))
    if (e.is_regular_file()) after[e.path().string()] = testing::read_text(e.path());
  CHECK(after == before);  // no file of the new run
  CHECK(dir.files() == std::vector<std::string>{"out"});  // no hidden sibling left
}

TEST_CASE("pockets outputs: pockets.pdb leaves out what the PDB columns cannot hold", "[pocket_outputs]") {
  const Run& r = the_run();
  // The same molecule 20000 A away: every centre is beyond the columns.
  molecule::Structure far = r.run.structure;
  for (molecule::Atom& a : far.atoms) a.position.x += 20000;
  molecule::PocketRun run;
  run.file = kStructure;
  run.structure = far;
  run.search = molecule::search_pockets(far, {});
  run.ligands = molecule::ligand_sites(far, run.search);
  const molecule::PocketSearch& search = run.search;
  TempDir dir;
  molecule::PocketOutputDir out((dir / "out").string());
  out.write(run);
  const std::string text = testing::read_text(dir / "out/pockets.pdb");
  const std::size_t cavities = search.cavities.pockets.size() + search.cavities.voids.size();
  REQUIRE(cavities > 0);
  CHECK(text.find("HETATM") == std::string::npos);
  CHECK(text.find("pseudo-atoms left out") != std::string::npos);
  REQUIRE(out.warnings().size() == 1);
  CHECK(out.warnings()[0].find("pockets.pdb: ") == 0);
  // Everything else is written as usual.
  CHECK(json::parse(testing::read_text(dir / "out/report.json"))["pockets"].size() == search.cavities.pockets.size());
  // A normal run has no warning.
  molecule::PocketOutputDir near((dir / "near").string());
  near.write(r.run);
  CHECK(near.warnings().empty());
}
