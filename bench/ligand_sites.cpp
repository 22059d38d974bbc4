// SPDX-License-Identifier: Apache-2.0
// Ligand-binding-site benchmark of `alphapocket pockets`: how often a
// top-ranked site (a pocket, or a void that can hold a ligand: report.json's
// "sites") is where a ligand binds, on holo structures whose
// ligands were removed before the search (the pockets command drops hetero
// groups by default).
//
//   ligand_sites [options] [DATASET...] [-- ALPHAPOCKET-OPTIONS...]
//
//   DATASET            one of two layouts (each set scored on its own):
//                      COACH420's, a directory of structure files and one
//                      .ds file listing, per file, its ligand codes (P2Rank's
//                      format: "HEADER: protein ligand_codes", then
//                      "1abcA.pdb  ATP,MG"); or PoseBusters', one directory
//                      per entry holding protein.pdb.gz and ligands.sdf
//                      (every copy of the ligand of interest, absent from the
//                      protein file); default: ../shared/data/pockets-dev
//                      next to the source tree
//   --alphapocket EXE  the executable to run (default: the one built with this)
//   --reports DIR      score existing results instead of running anything:
//                      DIR/<name>/report.json for each structure <name>.pdb
//                      or entry <name>/ (DIR/<set>/<name>/ with several sets)
//   --keep DIR         run into DIR/<name>/ and keep the results (default: a
//                      temporary directory, removed at the end)
//   --details          one line per structure: sites, time, rank of the
//                      first hit per ligand
//   --json             the figures as one JSON object on stdout instead of the table
//   -- ...             further options for `alphapocket pockets` (e.g. --probe 1.6)
//
// REUSE (e.g. to tune the pocket score): generate reports with any build or
// options, `alphapocket pockets F -o DIR/<name>` per structure, then
// `ligand_sites --reports DIR --json` scores them without running anything;
// only "sites"[i]["center"] of report.json, in rank order, is read.
//
// Ligands (the dataset's definition, /work/shared/data/README.md): HETATM
// residues whose name is in the file's code list, hydrogens left out;
// residues closer than 1.7 A to each other (any atom pair) are merged into
// one ligand (glycans, peptides); its centre is the mean of its heavy atoms.
// A site HITS a ligand by DCC when its centre lies within 4 A of the
// ligand's centre, by DCA when within 4 A of any ligand atom. Top-k: some
// site of rank <= k hits; top-(n+2): k = number of ligands of the
// structure + 2. Figures are fractions of all ligands. PoseBusters: a target
// is an entry, found when a site hits any copy of its ligand (P2Rank's
// rule: every relevant ligand counts); the copies' heavy atoms come from
// ligands.sdf (MDL V2000); the entries of one protein chain and those of
// several are also scored apart. Runtime is the wall
// clock of one `alphapocket pockets` process (reading, computing, writing
// every output file), median over the structures.
//
// fpocket 4.0's and P2Rank 2.0's figures on the same files, scored the same
// way (from the dataset's README), are printed alongside.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <stdlib.h>  // mkdtemp

#include <nlohmann/json.hpp>

#include "median.hpp"
#include "molecule/structure.hpp"

namespace fs = std::filesystem;

namespace {

constexpr double kHitDistance = 4.0;   // A, DCC and DCA
constexpr double kMergeDistance = 1.7; // A, residues of one ligand

// Peers' figures on the datasets (the dataset's README; NaN: not known):
// fpocket 4.0 measured on pockets-dev, P2Rank 2.0 as run by its authors.
struct Peer {
  const char* name;
  const char* dataset;
  double dcc[3], dca[3];  // top-1, top-3, top-(n+2)
  double pockets, seconds;
};
constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
constexpr Peer kPeers[] = {
    {"P2Rank 2.0", "pockets-dev", {0.451, 0.471, kUnknown}, {0.725, 0.784, kUnknown}, kUnknown, kUnknown},
    {"fpocket 4.0", "pockets-dev", {0.431, 0.569, 0.569}, {0.627, 0.804, 0.804}, 13, 0.63},
    {"P2Rank 2.0", "pockets-train", {0.409, 0.440, kUnknown}, {0.653, 0.733, kUnknown}, kUnknown, kUnknown},
    {"fpocket 4.0", "pockets-dev-pb", {0.375, 0.450, kUnknown}, {0.425, 0.525, kUnknown}, 26, kUnknown},
};

struct Options {
  std::vector<fs::path> datasets;
  std::string alphapocket = ALPHAPOCKET_EXE;
  fs::path reports, keep;
  bool details = false, json = false;
  std::vector<std::string> pass_through;
};

struct Ligand {
  std::string name;  // residue names of its parts, e.g. "NAD" or "MAN+GLC"
  std::vector<alpha::Vec3> atoms;
  alpha::Vec3 center{};
};

// What a site must find: one ligand (COACH420), or any copy of one
// (PoseBusters).
using Target = std::vector<Ligand>;

// A structure of a dataset, with its targets.
struct Entry {
  std::string name;       // report directory: DIR/<name>/
  fs::path structure;
  std::vector<Target> targets;
  bool multi_chain = false;  // its protein atoms lie in more than one chain
};

double distance(const alpha::Vec3& a, const alpha::Vec3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void finish(Ligand& l) {
  l.center = {};
  for (const auto& p : l.atoms) l.center.x += p.x, l.center.y += p.y, l.center.z += p.z;
  const double n = double(l.atoms.size());
  l.center = {l.center.x / n, l.center.y / n, l.center.z / n};
}

// The .ds file of the dataset: file name -> ligand codes.
std::vector<std::pair<std::string, std::vector<std::string>>> read_ds(const fs::path& dataset) {
  fs::path ds;
  for (const auto& e : fs::directory_iterator(dataset))
    if (e.path().extension() == ".ds") {
      if (!ds.empty()) throw std::runtime_error(dataset.string() + ": more than one .ds file");
      ds = e.path();
    }
  if (ds.empty()) throw std::runtime_error(dataset.string() + ": no .ds file listing the ligand codes");
  std::ifstream in(ds);
  std::vector<std::pair<std::string, std::vector<std::string>>> entries;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string file, codes;
    if (!(words >> file) || file[0] == '#' || file == "HEADER:") continue;
    if (!(words >> codes)) throw std::runtime_error(ds.string() + ": no ligand codes for " + file);
    std::vector<std::string> list;
    std::istringstream split(codes);
    for (std::string code; std::getline(split, code, ',');) list.push_back(code);
    entries.emplace_back(file, list);
  }
  if (entries.empty()) throw std::runtime_error(ds.string() + ": no entries");
  return entries;
}

// The ligands of a structure file, by the dataset's definition.
std::vector<Ligand> read_ligands(const fs::path& file, const std::vector<std::string>& codes) {
  molecule::StructureOptions all;  // hetero groups kept: a peptide ligand may count as polymer
  all.keep_hetero = true;
  const molecule::Structure s = molecule::read_structure(file.string(), all);
  // Residues of the listed HETATM records.
  std::map<std::tuple<std::string, int, char, std::string>, Ligand> residues;
  for (const molecule::Atom& a : s.atoms) {
    if (!a.hetero || std::find(codes.begin(), codes.end(), a.residue_name) == codes.end()) continue;
    Ligand& r = residues[{a.chain, a.seq_num, a.icode, a.residue_name}];
    r.name = a.residue_name;
    r.atoms.push_back(a.position);
  }
  // Merge residues closer than kMergeDistance (single linkage).
  std::vector<Ligand> parts;
  for (auto& [key, r] : residues) parts.push_back(std::move(r));
  std::vector<std::size_t> group(parts.size());
  std::iota(group.begin(), group.end(), std::size_t(0));
  const auto find = [&](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  const auto close = [&](const Ligand& a, const Ligand& b) {
    for (const auto& p : a.atoms)
      for (const auto& q : b.atoms)
        if (distance(p, q) < kMergeDistance) return true;
    return false;
  };
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = i + 1; j < parts.size(); ++j)
      if (close(parts[i], parts[j])) group[std::max(find(i), find(j))] = std::min(find(i), find(j));
  std::vector<Ligand> ligands;
  std::map<std::size_t, std::size_t> index;  // group root -> ligand
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto [it, fresh] = index.try_emplace(find(i), ligands.size());
    if (fresh) ligands.emplace_back();
    Ligand& l = ligands[it->second];
    if (!l.name.empty()) l.name += '+';
    l.name += parts[i].name;
    l.atoms.insert(l.atoms.end(), parts[i].atoms.begin(), parts[i].atoms.end());
  }
  for (Ligand& l : ligands) finish(l);
  return ligands;
}

// Every molecule of an MDL SD file (V2000 molfiles), heavy atoms only.
std::vector<Ligand> read_sdf(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::vector<Ligand> out;
  std::string name, line;
  while (std::getline(in, name)) {
    std::string counts;
    if (!std::getline(in, line) || !std::getline(in, line) || !std::getline(in, counts) ||
        counts.find("V2000") == std::string::npos)
      throw std::runtime_error(file.string() + ": not an SD file of V2000 molfiles");
    Ligand l;
    l.name = name.substr(0, name.find_first_of(" \t\r"));
    const int atoms = std::stoi(counts.substr(0, 3));
    for (int i = 0; i < atoms; ++i) {
      if (!std::getline(in, line) || line.size() < 34)
        throw std::runtime_error(file.string() + ": truncated atom block of " + l.name);
      std::istringstream fields(line);
      alpha::Vec3 p;
      std::string element;
      if (!(fields >> p.x >> p.y >> p.z >> element))
        throw std::runtime_error(file.string() + ": bad atom line of " + l.name);
      if (element != "H" && element != "D") l.atoms.push_back(p);
    }
    while (std::getline(in, line) && line.rfind("$$$$", 0) != 0) {}
    if (l.atoms.empty()) throw std::runtime_error(file.string() + ": " + l.name + " has no heavy atom");
    finish(l);
    out.push_back(std::move(l));
  }
  if (out.empty()) throw std::runtime_error(file.string() + ": no molecule");
  return out;
}

bool multi_chain(const molecule::Structure& s) {
  for (const molecule::Atom& a : s.atoms)
    if (!a.hetero && a.chain != s.atoms.front().chain) return true;
  return false;
}

// The entries of a dataset in either layout (see the top of this file).
std::vector<Entry> read_dataset(const fs::path& dataset) {
  std::vector<Entry> out;
  bool ds = false;
  for (const auto& e : fs::directory_iterator(dataset)) ds = ds || e.path().extension() == ".ds";
  if (ds) {
    for (const auto& [file, codes] : read_ds(dataset)) {
      Entry e{fs::path(file).stem().string(), dataset / file, {}, false};
      for (Ligand& l : read_ligands(e.structure, codes)) e.targets.push_back({std::move(l)});
      if (e.targets.empty()) std::fprintf(stderr, "warning: %s: none of its listed ligands found\n", file.c_str());
      out.push_back(std::move(e));
    }
    return out;
  }
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(dataset))
    if (e.is_directory()) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  for (const fs::path& d : dirs) {
    Entry e{d.filename().string(), d / "protein.pdb.gz", {read_sdf(d / "ligands.sdf")}, false};
    e.multi_chain = multi_chain(molecule::read_structure(e.structure.string()));
    out.push_back(std::move(e));
  }
  if (out.empty())
    throw std::runtime_error(dataset.string() + ": neither a .ds file nor entry directories (ENTRY/protein.pdb.gz)");
  return out;
}

std::vector<alpha::Vec3> site_centers(const fs::path& report_file) {
  std::ifstream in(report_file);
  if (!in) throw std::runtime_error(report_file.string() + ": cannot open");
  const nlohmann::json report = nlohmann::json::parse(in);
  std::vector<alpha::Vec3> centers;
  for (const auto& p : report.at("sites")) {
    const auto& c = p.at("center");
    centers.push_back({c.at(0).get<double>(), c.at(1).get<double>(), c.at(2).get<double>()});
  }
  return centers;
}

// Rank (1-based) of the first site hitting a ligand of the target, 0 for none.
std::size_t first_hit(const std::vector<alpha::Vec3>& centers, const Target& target, bool dca) {
  for (std::size_t i = 0; i < centers.size(); ++i)
    for (const Ligand& l : target) {
      double d = distance(centers[i], l.center);
      if (dca)
        for (const auto& p : l.atoms) d = std::min(d, distance(centers[i], p));
      if (d <= kHitDistance) return i + 1;
    }
  return 0;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--") {
      o.pass_through.assign(argv + i + 1, argv + argc);
      break;
    } else if (a == "--alphapocket") {
      o.alphapocket = value();
    } else if (a == "--reports") {
      o.reports = value();
    } else if (a == "--keep") {
      o.keep = value();
    } else if (a == "--details") {
      o.details = true;
    } else if (a == "--json") {
      o.json = true;
    } else if (a == "-h" || a == "--help") {
      std::puts("usage: ligand_sites [--alphapocket EXE] [--reports DIR] [--keep DIR] [--details] [--json] [DATASET...] "
                "[-- ALPHAPOCKET-OPTIONS...]\n(see the comment at the top of bench/ligand_sites.cpp)");
      std::exit(0);
    } else if (!a.empty() && a[0] != '-') {
      o.datasets.push_back(fs::path(a).lexically_normal());
    } else {
      throw std::runtime_error("unknown argument '" + a + "' (see --help)");
    }
  }
  if (o.datasets.empty())
    o.datasets.push_back((fs::path(ALPHAPOCKET_SOURCE_DIR) / ".." / "shared" / "data" / "pockets-dev").lexically_normal());
  return o;
}

// The figures of one ranking over a set of entries.
struct Figures {
  std::array<std::size_t, 3> dcc{}, dca{};  // hits at top-1, top-3, top-(n+2)
  std::size_t ligands = 0;                   // targets: ligands, or entries (PoseBusters)
  std::vector<double> sites, seconds;        // per structure
  double fraction(std::size_t hits) const { return ligands ? double(hits) / double(ligands) : 0.0; }

  // Scores one entry's ranked site centres; its line of --details.
  std::string add(const Entry& e, const std::vector<alpha::Vec3>& centers) {
    std::string detail;
    sites.push_back(double(centers.size()));
    ligands += e.targets.size();
    for (const Target& t : e.targets) {
      const std::size_t by_center = first_hit(centers, t, false), by_atom = first_hit(centers, t, true);
      const std::array<std::size_t, 3> k{1, 3, e.targets.size() + 2};
      for (int i = 0; i < 3; ++i) {
        dcc[i] += by_center && by_center <= k[i];
        dca[i] += by_atom && by_atom <= k[i];
      }
      detail += "  " + t.front().name + " DCC " + (by_center ? std::to_string(by_center) : "-") + " DCA " +
                (by_atom ? std::to_string(by_atom) : "-");
    }
    return detail;
  }
};

// A dataset's figures: all entries, and those of one chain and of several.
struct SetFigures {
  Figures all, single, multi;
};

// Runs alphapocket into work/<name>/ (unless scoring given reports) with
// the extra options, and scores each entry's sites.
SetFigures score(const Options& o, const std::vector<Entry>& entries, const fs::path& work, const std::string& extra,
                 bool details) {
  SetFigures fig;
  fs::create_directories(work);
  for (const Entry& e : entries) {
    const fs::path outdir = work / e.name;
    double seconds = kUnknown;
    if (o.reports.empty()) {
      const std::string command = shell_quote(o.alphapocket) + " -q pockets " + shell_quote(e.structure.string()) +
                                  " -o " + shell_quote(outdir.string()) + extra + " > /dev/null";
      const auto start = std::chrono::steady_clock::now();
      if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    const std::vector<alpha::Vec3> centers = site_centers(outdir / "report.json");
    const std::string detail = fig.all.add(e, centers);
    (e.multi_chain ? fig.multi : fig.single).add(e, centers);
    if (!std::isnan(seconds)) fig.all.seconds.push_back(seconds);
    if (details) {
      char time[32] = "";
      if (!std::isnan(seconds)) std::snprintf(time, sizeof time, " %6.2f s", seconds);
      std::fprintf(stderr, "%-10s %3zu sites%s%s\n", e.name.c_str(), centers.size(), time, detail.c_str());
    }
  }
  return fig;
}

void print_row(const std::string& name, const double dcc[3], const double dca[3], double sites, double seconds) {
  const auto cell = [](double x, const char* format) {
    char text[16];
    if (std::isnan(x)) return std::string("-");
    std::snprintf(text, sizeof text, format, x);
    return std::string(text);
  };
  std::printf("%-30s %6s %6s %6s   %6s %6s %6s   %6s %8s\n", name.c_str(), cell(dcc[0], "%.3f").c_str(),
              cell(dcc[1], "%.3f").c_str(), cell(dcc[2], "%.3f").c_str(), cell(dca[0], "%.3f").c_str(),
              cell(dca[1], "%.3f").c_str(), cell(dca[2], "%.3f").c_str(), cell(sites, "%.1f").c_str(),
              cell(seconds, "%.2f").c_str());
}

void print_figures(const std::string& name, const Figures& f) {
  const double dcc[3] = {f.fraction(f.dcc[0]), f.fraction(f.dcc[1]), f.fraction(f.dcc[2])};
  const double dca[3] = {f.fraction(f.dca[0]), f.fraction(f.dca[1]), f.fraction(f.dca[2])};
  print_row(name, dcc, dca, f.sites.empty() ? kUnknown : bench::median(f.sites),
            f.seconds.empty() ? kUnknown : bench::median(f.seconds));
}

nlohmann::ordered_json figures_json(const Figures& f) {
  nlohmann::ordered_json j;
  j["ligands"] = f.ligands;
  j["dcc"] = {f.fraction(f.dcc[0]), f.fraction(f.dcc[1]), f.fraction(f.dcc[2])};
  j["dca"] = {f.fraction(f.dca[0]), f.fraction(f.dca[1]), f.fraction(f.dca[2])};
  j["sites_median"] = f.sites.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(bench::median(f.sites));
  j["seconds_median"] = f.seconds.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(bench::median(f.seconds));
  return j;
}

// Scores one dataset (its reports in work/) and prints its figures.
void run_set(const Options& o, const fs::path& dataset, const fs::path& work, const std::string& extra) {
  const std::vector<Entry> entries = read_dataset(dataset);
  const SetFigures fig = score(o, entries, work, extra, o.details);
  // Running: the geometric ranking too, into work/geometric/.
  const bool both = o.reports.empty();
  const SetFigures geo = both ? score(o, entries, work / "geometric", extra + " --ranking geometric", false) : SetFigures{};
  const bool chains = fig.multi.ligands > 0 && fig.single.ligands > 0;
  if (o.json) {
    nlohmann::ordered_json j;
    j["dataset"] = dataset.filename().string();
    j["structures"] = entries.size();
    j.update(figures_json(fig.all));
    if (chains) {
      j["single_chain"] = figures_json(fig.single);
      j["multi_chain"] = figures_json(fig.multi);
    }
    if (both) j["geometric"] = figures_json(geo.all);
    std::puts(j.dump().c_str());
    return;
  }
  std::printf("ligand-binding sites: %zu structures, %zu %s (%s)\n", entries.size(), fig.all.ligands,
              chains ? "targets" : "ligands", dataset.filename().c_str());
  std::printf("%-30s %6s %6s %6s   %6s %6s %6s   %6s %8s\n", "", "DCC@1", "DCC@3", "@(n+2)", "DCA@1", "DCA@3",
              "@(n+2)", "sites", "seconds");
  print_figures(both ? "alphapocket (probability)" : "alphapocket", fig.all);
  if (chains) {
    print_figures("  single-chain (" + std::to_string(fig.single.ligands) + ")", fig.single);
    print_figures("  multi-chain (" + std::to_string(fig.multi.ligands) + ")", fig.multi);
  }
  if (both) print_figures("alphapocket (geometric)", geo.all);
  for (const Peer& p : kPeers)
    if (dataset.filename() == p.dataset) print_row(p.name, p.dcc, p.dca, p.pockets, p.seconds);
}

int run(const Options& o) {
  fs::path work = o.reports.empty() ? o.keep : o.reports;
  const bool temporary = work.empty();
  if (temporary) {
    std::string tmpl = (fs::temp_directory_path() / "ligand_sites_XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary directory");
    work = tmpl;
  }
  std::string extra;
  for (const std::string& a : o.pass_through) extra += " " + shell_quote(a);
  try {
    for (const fs::path& dataset : o.datasets)  // several sets: each in work/<set>/
      run_set(o, dataset, o.datasets.size() > 1 ? work / dataset.filename() : work, extra);
  } catch (...) {
    if (temporary) fs::remove_all(work);
    throw;
  }
  if (temporary) fs::remove_all(work);
  if (!o.json)
    std::printf("(DCC/DCA <= 4 A at top-1, top-3, top-(n+2); targets: ligands, or entries whose ligand has copies "
                "(any copy counts); medians over the structures; seconds: wall clock of one `alphapocket pockets` "
                "run, all files written; peers: the dataset's README; spread over training seeds: training/train.py "
                "--seeds)\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
}
