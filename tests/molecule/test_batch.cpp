// SPDX-License-Identifier: Apache-2.0
// The pieces of `alphapocket batch` below the CLI: which files an input
// names and their ids (batch/batch_inputs.hpp), predicted models and
// their pLDDT (structure.hpp, pocket_report.hpp), the one-structure
// pipeline (analysis.hpp) and records (batch_record.hpp). The runs
// themselves are tested through the CLI (tests/cli/batch.sh).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "alpha/error.hpp"
#include "alpha/input_file.hpp"
#include "molecule/analysis.hpp"
#include "outputs/pocket_outputs.hpp"
#include "outputs/pocket_report.hpp"
#include "outputs/tables.hpp"
#include "batch/batch_inputs.hpp"
#include "batch/batch_record.hpp"
#include "util/checksum.hpp"
#include "mesh_checks.hpp"

namespace fs = std::filesystem;
using testing::TempDir;

namespace {

const std::string kData = ALPHAPOCKET_TEST_DATA;
const std::string kAfPdb = kData + "/AF-X6R8D5-F1-model_v1.pdb.gz";
const std::string kAfCif = kData + "/AF-P29373-F1-model_v4.cif.gz";

void touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "x";
}

// Residue -> mean B-factor of its atoms, from a read that keeps everything.
std::map<std::tuple<std::string, int, char>, double> residue_b(const molecule::Structure& s) {
  std::map<std::tuple<std::string, int, char>, std::pair<double, int>> sum;
  for (const molecule::Atom& a : s.atoms) {
    auto& [b, n] = sum[{a.chain, a.seq_num, a.icode}];
    b += a.b_factor;
    ++n;
  }
  std::map<std::tuple<std::string, int, char>, double> out;
  for (const auto& [key, bn] : sum) out[key] = bn.first / bn.second;
  return out;
}

}  // namespace

TEST_CASE("batch inputs: ids are file names without structure extensions", "[batch]") {
  CHECK(molecule::structure_id("a/b/1abc.pdb") == "1abc");
  CHECK(molecule::structure_id("AF-P29373-F1-model_v4.cif.gz") == "AF-P29373-F1-model_v4");
  CHECK(molecule::structure_id("x.ENT.GZ") == "x");
  CHECK(molecule::structure_id("x.mmcif") == "x");
  CHECK(molecule::structure_id("x.tar.gz") == "x.tar");
  CHECK(molecule::structure_id(".pdb") == "structure");
}

TEST_CASE("batch inputs: directories are searched recursively, for regular files only", "[batch]") {
  TempDir dir;
  for (const char* f : {"a.pdb", "sub/b.cif.gz", "sub/deeper/c.ENT", "x.pdb/d.mmcif", "notes.txt", "e.pdb.bz2"})
    touch(dir / f);
  const std::vector<molecule::BatchInput> in = molecule::batch_inputs({dir.path().string()});
  std::vector<std::string> ids;
  for (const auto& i : in) ids.push_back(i.id);
  CHECK(ids == std::vector<std::string>{"a", "b", "c", "d"});  // sorted by id; x.pdb/ is searched, not read
  CHECK(in[3].path == (dir / "x.pdb/d.mmcif").string());
}

TEST_CASE("batch inputs: a duplicate id names both paths; the same path twice is one input", "[batch]") {
  TempDir dir;
  touch(dir / "a/1abc.pdb");
  touch(dir / "b/1abc.cif.gz");
  const std::string a = (dir / "a/1abc.pdb").string(), b = (dir / "b/1abc.cif.gz").string();
  CHECK(molecule::batch_inputs({a, (dir / "a/./1abc.pdb").string()}).size() == 1);
  try {
    molecule::batch_inputs({(dir / "b").string(), a});
    FAIL("no error");
  } catch (const alpha::Error& e) {
    CHECK(std::string(e.what()) == "two inputs with the structure id '1abc': " + a + " and " + b);
  }
  CHECK_THROWS_AS(molecule::batch_inputs({(dir / "missing").string()}), alpha::Error);
  touch(dir / "list.txt");
  CHECK_THROWS_AS(molecule::batch_inputs({(dir / "list.txt").string()}), alpha::Error);
}

TEST_CASE("batch inputs: lists and P2Rank datasets", "[batch]") {
  std::istringstream list("# comment\n\n  a/x.pdb  \n/abs/y.cif # trailing\n");
  CHECK(molecule::read_path_list(list, "list", false, "") == std::vector<std::string>{"a/x.pdb", "/abs/y.cif"});
  // pockets-dev.ds's layout: comments, a HEADER line, path then ligand codes.
  std::istringstream ds("# subset\n\nHEADER: protein ligand_codes\n\n1a26A.pdb  CNA\nsub/1a2kC.pdb\tGDP,GTP\n");
  CHECK(molecule::read_path_list(ds, "x.ds", true, "/data/set") ==
        std::vector<std::string>{"/data/set/1a26A.pdb", "/data/set/sub/1a2kC.pdb"});
}

TEST_CASE("predicted models: recognised by name or by ModelCIF's local pLDDT", "[batch]") {
  CHECK(molecule::read_structure(kAfPdb).report.predicted);
  CHECK(molecule::read_structure(kAfCif).report.predicted);
  // The mmCIF model under another name: still predicted (_ma_qa_metric_local).
  const std::string bytes = alpha::read_input_file(kAfCif);
  CHECK(molecule::parse_structure(bytes, "model.cif.gz").report.predicted);
  CHECK_FALSE(molecule::read_structure(kData + "/1fkgA.pdb").report.predicted);
  CHECK_FALSE(molecule::read_structure(kData + "/1UYD.cif").report.predicted);
}

TEST_CASE("predicted models: --min-plddt leaves out exactly the residues below it", "[batch]") {
  const molecule::Structure all = molecule::read_structure(kAfPdb);
  const auto b = residue_b(all);
  for (const double cut : {50.0, 70.0, 80.0}) {
    INFO("min_plddt " << cut);
    molecule::StructureOptions o;
    o.min_plddt = cut;
    const molecule::Structure kept = molecule::read_structure(kAfPdb, o);
    std::size_t expected = 0;
    for (const molecule::Atom& a : all.atoms) expected += b.at({a.chain, a.seq_num, a.icode}) >= cut;
    CHECK(kept.atoms.size() == expected);
    CHECK(kept.report.dropped_plddt == all.atoms.size() - expected);
    CHECK(kept.atoms.size() < all.atoms.size());
    for (const molecule::Atom& a : kept.atoms) CHECK(a.b_factor >= cut);
  }
  // An experimental structure: nothing dropped, a warning.
  molecule::StructureOptions o;
  o.min_plddt = 99;
  const molecule::Structure x = molecule::read_structure(kData + "/1fkgA.pdb", o);
  CHECK(x.atoms.size() == molecule::read_structure(kData + "/1fkgA.pdb").atoms.size());
  REQUIRE_FALSE(x.report.warnings.empty());
  CHECK(x.report.warnings.back() == "not a predicted model (no pLDDT): --min-plddt ignored");
}

TEST_CASE("analysis: each site's mean pLDDT is that of its lining residues; null for experimental", "[batch]") {
  molecule::AnalysisOptions options;
  options.version = "test";
  const molecule::Analysis a = molecule::analyse(kAfCif, options);
  const auto b = residue_b(a.structure);
  const nlohmann::ordered_json& r = a.report->json;
  REQUIRE(r["input"]["predicted"] == true);
  REQUIRE(!r["sites"].empty());
  for (const auto& site : r["sites"]) {
    const auto& cavity = r[site["kind"] == "void" ? "voids" : "pockets"][site["cavity_rank"].get<int>() - 1];
    double sum = 0;
    for (const auto& res : cavity["lining_residues"])
      sum += b.at({res["chain"], res["number"], res["insertion_code"].get<std::string>().empty()
                                                    ? '\0'
                                                    : res["insertion_code"].get<std::string>()[0]});
    CHECK(site["mean_plddt"].get<double>() == Approx(sum / cavity["lining_residues"].size()).margin(5e-4));
    CHECK(cavity["mean_plddt"] == site["mean_plddt"]);
  }
  const molecule::Analysis x = molecule::analyse(kData + "/1fkgA.pdb", options);
  CHECK(x.report->json["molecule"]["mean_plddt"].is_null());
  for (const auto& site : x.report->json["sites"]) CHECK(site["mean_plddt"].is_null());
}

TEST_CASE("analysis: failures come with their category", "[batch]") {
  molecule::AnalysisOptions options;
  const auto kind_of = [&](const std::string& file) {
    try {
      molecule::analyse(file, options);
    } catch (const molecule::AnalysisError& e) {
      CHECK(std::string(e.what()).find(file) != std::string::npos);  // names the file
      return std::make_pair(e.kind(), e.skipped());
    }
    FAIL("no error for " << file);
    return std::make_pair(molecule::FailureKind::Internal, false);
  };
  CHECK(kind_of(kData + "/bad/corrupt.pdb.gz").first == molecule::FailureKind::BadInput);
  CHECK(kind_of(kData + "/bad/three_atoms.pdb").first == molecule::FailureKind::BadInput);
  CHECK(kind_of(kData + "/missing.pdb").first == molecule::FailureKind::BadInput);
  options.max_atoms = 100;
  CHECK(kind_of(kData + "/1fkgA.pdb") == std::make_pair(molecule::FailureKind::LimitExceeded, true));
}

TEST_CASE("batch records: a line reads back the same; table_rows follows the report", "[batch]") {
  molecule::AnalysisOptions options;
  options.version = "test";
  const molecule::Analysis a = molecule::analyse(kData + "/1ytjA.pdb", options);
  molecule::BatchRecord r;
  r.id = "1ytjA";
  r.path = "x/1ytjA.pdb";
  r.checksum = molecule::sha256_hex("abc");
  r.key = molecule::batch_key({{"probe", 1.4}}, "test");
  r.status = "ok";
  r.seconds = 0.25;
  r.rows = molecule::table_rows(a);
  const std::string line = molecule::record_line(r);
  CHECK(line.find('\n') == std::string::npos);
  const molecule::BatchRecord back = molecule::parse_record(line);
  CHECK(molecule::record_line(back) == line);
  CHECK(r.checksum == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");  // FIPS 180-2
  CHECK(r.key != molecule::batch_key({{"probe", 1.5}}, "test"));
  CHECK(r.key != molecule::batch_key({{"probe", 1.4}}, "other"));
  CHECK(back.rows["sites"].size() == a.search.cavities.sites.size());
  CHECK(back.rows["tunnels"].size() == a.report->json["tunnels"].size());  // cycles, tunnels and pores
  CHECK(a.report->json["tunnels"].size() == a.search.cavities.tunnels.size() + a.paths.size());
  CHECK(back.rows["structure"][2] == a.structure.atoms.size());
  const auto& first = back.rows["sites"][0];
  CHECK(first[3] == a.report->json["sites"][0]["score"]);
  CHECK(first[4] == a.report->json["sites"][0]["probability"]);
  CHECK_THROWS_AS(molecule::parse_record(line.substr(0, line.size() / 2)), alpha::Error);  // a cut line
  CHECK_THROWS_AS(molecule::parse_record("{}"), alpha::Error);
}

TEST_CASE("table rows: every value is report.json's", "[batch]") {
  // The rows come from the typed results, the report from the same by its
  // own code: read the report as the tables' columns name it.
  using json = nlohmann::ordered_json;
  const auto or_null = [](const json& o, const char* key) { return o.contains(key) ? o.at(key) : json(nullptr); };
  const auto words = [](const json& items) {
    std::string out;
    for (const json& r : items) out += (out.empty() ? "" : " ") + (r.is_string() ? r : r.at("id")).get<std::string>();
    return out;
  };
  molecule::AnalysisOptions options;
  options.tunnels.pores = true;
  std::size_t sites = 0, tunnels = 0, with_ligands = 0;
  for (const std::string& file : {kAfPdb, kData + "/1UYD.pdb", std::string(ALPHAPOCKET_EXAMPLES_DATA) + "/1a26A.pdb"}) {
    INFO(file);
    const molecule::Analysis a = molecule::analyse(file, options);
    const json& report = a.report->json;
    const json rows = molecule::table_rows(a);
    const json& input = report.at("input");
    const json& m = report.at("molecule");
    CHECK(rows.at("structure") == json::array({input.at("format"), int(input.at("predicted") == true), m.at("atoms"),
                                               m.at("pockets"), m.at("voids"), m.at("sites"), m.at("tunnels"),
                                               m.at("sa_area"), m.at("sa_volume"), m.at("mean_plddt")}));
    REQUIRE(rows.at("sites").size() == report.at("sites").size());
    for (std::size_t i = 0; i < rows.at("sites").size(); ++i) {
      const json& s = report.at("sites")[i];
      const json& c = report.at(s.at("kind") == "void" ? "voids" : "pockets").at(s.at("cavity_rank").get<std::size_t>() - 1);
      const json& center = s.at("center");
      CHECK(rows.at("sites")[i] ==
            json::array({s.at("rank"), s.at("kind"), s.at("cavity_rank"), c.at("score"), c.at("probability"),
                         c.at("sa_volume"), c.at("ms_volume"), c.at("sa_area"), c.at("ms_area"), c.at("depth"),
                         c.at("mouths"), c.at("mouth_area"), c.at("buriedness"), c.at("burial_atoms"),
                         c.at("max_probe_radius"), center[0], center[1], center[2], s.at("mean_plddt"),
                         c.at("lining_residues").size(), words(c.at("lining_residues")),
                         s.at("ligands").empty() ? json(nullptr) : json(words(s.at("ligands")))}));
      with_ligands += !s.at("ligands").empty();
      ++sites;
    }
    REQUIRE(rows.at("tunnels").size() == report.at("tunnels").size());
    for (std::size_t i = 0; i < rows.at("tunnels").size(); ++i) {
      const json& t = report.at("tunnels")[i];
      const json& center = t.at("bottleneck_center");
      CHECK(rows.at("tunnels")[i] == json::array({t.at("rank"), t.at("kind"), t.at("bottleneck_radius"), center[0],
                                                  center[1], center[2], t.at("length"), or_null(t, "birth_alpha_sq"),
                                                  or_null(t, "death_alpha_sq"), words(t.at("lining_residues"))}));
      ++tunnels;
    }
  }
  CHECK(sites >= 10);
  CHECK(tunnels >= 5);
  CHECK(with_ligands >= 1);
}
