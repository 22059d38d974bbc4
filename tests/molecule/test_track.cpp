// SPDX-License-Identifier: Apache-2.0
// Pockets followed through frames (molecule/track.hpp): the identity rule
// on constructed cavities, a pocket that opens and closes in a real
// protein, the same results for any number of threads, and the frequency
// map of mdpocket's CHK1 ensemble against mdpocket's own.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "alpha/input_file.hpp"
#include "molecule/track.hpp"
#include "trajectory/track_outputs.hpp"
#include "trajectory/frame_cavities.hpp"
#include "trajectory/pdb_models.hpp"
#include "trajectory/pocket_tracker.hpp"
#include "trajectory/volume_plot.hpp"
#include "util/gunzip.hpp"

using namespace molecule;

namespace {

const std::string kData = ALPHAPOCKET_TEST_DATA;

// A cavity lining atoms a..b-1 ("A:ALA:i:CA") and owning grid points s..e-1.
FrameCavity cavity(int a, int b, std::uint32_t s, std::uint32_t e, CavityKind kind = CavityKind::pocket) {
  FrameCavity c;
  c.kind = kind;
  for (int i = a; i < b; ++i) {
    c.residues.push_back("A:ALA:" + std::to_string(i));
    c.lining_atoms.push_back(c.residues.back() + ":CA");
  }
  std::sort(c.residues.begin(), c.residues.end());
  std::sort(c.lining_atoms.begin(), c.lining_atoms.end());
  for (std::uint32_t p = s; p < e; ++p) c.space.push_back(p);
  return c;
}

FrameCavities frame(std::vector<FrameCavity> cavities) {
  FrameCavities f;
  f.cavities = std::move(cavities);
  return f;
}

// The frames (positions in the run) a track is present in.
std::vector<std::size_t> life(const TrackResult& r, std::size_t track) {
  std::vector<std::size_t> out;
  for (std::size_t o : r.tracks[track].observations) out.push_back(r.observations[o].frame);
  return out;
}

// Frames given in a list (atoms may differ between frames).
class ListFrames : public FrameSource {
public:
  explicit ListFrames(std::vector<Structure> frames) : frames_(std::move(frames)) {}
  std::optional<Frame> next() override {
    if (next_ == frames_.size()) return std::nullopt;
    Frame f;
    f.index = next_;
    f.time = double(next_);
    f.name = "frame " + std::to_string(next_);
    f.structure = frames_[next_++];
    return f;
  }

private:
  std::vector<Structure> frames_;
  std::size_t next_ = 0;
};

}  // namespace

TEST_CASE("a track continues through gaps, splits and merges", "[track]") {
  TrackResult r;
  PocketTracker tracker(0.3);
  tracker.add(frame({cavity(0, 10, 0, 10)}), r);                       // 0: one pocket
  tracker.add(frame({cavity(0, 6, 0, 5), cavity(5, 10, 5, 10)}), r);   // 1: it splits in two
  tracker.add(frame({cavity(0, 10, 0, 10)}), r);                       // 2: they merge again
  tracker.add(frame({}), r);                                           // 3: closed
  tracker.add(frame({cavity(1, 10, 2, 9), cavity(50, 60, 50, 60)}), r);  // 4: it reopens; a new pocket
  // Shares lining but no space with pocket 1: a different pocket.
  tracker.add(frame({cavity(0, 10, 100, 110)}), r);
  // Same lining and space, but a void: not the pocket.
  tracker.add(frame({cavity(0, 10, 0, 10, CavityKind::void_)}), r);

  REQUIRE(r.frames.size() == 7);
  REQUIRE(r.tracks.size() == 5);
  CHECK(life(r, 0) == std::vector<std::size_t>{0, 1, 2, 4});
  CHECK(life(r, 1) == std::vector<std::size_t>{1});
  CHECK(r.tracks[1].split_from == 0u);
  CHECK(r.tracks[1].merged_into == 0u);  // the pocket of frame 2 shares more with track 0
  CHECK(life(r, 2) == std::vector<std::size_t>{4});
  CHECK(life(r, 3) == std::vector<std::size_t>{5});
  CHECK(r.tracks[4].kind == CavityKind::void_);
  REQUIRE(r.events.size() == 2);
  CHECK(r.events[0].event == "split");
  CHECK(r.events[0].frame == 1);
  CHECK(r.events[1].event == "merge");
  CHECK(r.events[1].frame == 2);
  CHECK(r.tracks[0].residues.at("A:ALA:0") == 3);  // frames 0, 1, 2; not 4
  CHECK(r.tracks[0].residues.at("A:ALA:5") == 4);
}

TEST_CASE("no shared lining atoms, no identity; the overlap threshold decides", "[track]") {
  for (const double threshold : {0.3, 0.7}) {
    TrackResult r;
    PocketTracker tracker(threshold);
    tracker.add(frame({cavity(0, 10, 0, 10)}), r);
    tracker.add(frame({cavity(3, 13, 0, 10)}), r);  // Jaccard 7/13 = 0.54
    tracker.add(frame({cavity(20, 30, 0, 10)}), r);  // same space, other atoms
    CHECK(r.tracks.size() == (threshold < 0.54 ? 2u : 3u));
  }
}

TEST_CASE("a pocket filled and emptied keeps its identity and its life", "[track]") {
  // FKBP12: its FK506 site is the top pocket. Closed frames fill that
  // pocket's space with carbon atoms of a residue of their own.
  Structure protein = read_structure(kData + "/1fkgA.pdb");
  AnalysisOptions options;
  options.tunnels_from = "none";
  const Analysis open = analyse_structure("1fkgA", protein, options);
  const SpaceGrid grid = grid_around(protein.atoms, 1.0, 6);
  const FrameCavities cavities = frame_cavities(open, grid);
  const FrameCavity& site = cavities.cavities.front();
  REQUIRE(site.kind == CavityKind::pocket);
  REQUIRE(site.space.size() >= 20);
  Structure closed = protein;
  for (std::size_t k = 0; k < site.space.size(); ++k) {
    Atom a;
    a.name = "C" + std::to_string(k);
    a.element = "C";
    a.residue_name = "FIL";
    a.chain = "Z";
    a.seq_num = 1;
    a.position = grid.point(site.space[k]);
    a.radius = 1.7;
    closed.atoms.push_back(a);
  }
  // Frames 2-5 and 8-9 open; every frame's protein jiggled by up to 0.1 A.
  const std::set<std::size_t> open_frames{2, 3, 4, 5, 8, 9};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jiggle(-0.1, 0.1);
  std::vector<Structure> frames;
  for (std::size_t f = 0; f < 10; ++f) {
    Structure s = open_frames.count(f) ? protein : closed;
    for (Atom& a : s.atoms)
      if (a.chain != "Z") a.position = a.position + alpha::Vec3{jiggle(random), jiggle(random), jiggle(random)};
    frames.push_back(std::move(s));
  }
  TrackOptions track_options;
  track_options.analysis = options;
  ListFrames source(frames);
  const TrackResult r = track(source, track_options);
  REQUIRE(r.frames.size() == 10);
  // The track of frame 2's best pocket is the site: present exactly in the open frames.
  const Observation& first = *std::find_if(r.observations.begin(), r.observations.end(), [&](const Observation& o) {
    return o.frame == 2 && r.tracks[o.track].kind == CavityKind::pocket && o.rank == 1;
  });
  const std::vector<std::size_t> lived = life(r, first.track);
  CHECK(lived == std::vector<std::size_t>(open_frames.begin(), open_frames.end()));
  CHECK(r.frequency_of(r.tracks[first.track]) == Approx(0.6));
  CHECK(first.sa_volume == Approx(site.measures.sa_volume).epsilon(0.2));
}

TEST_CASE("the NMR ensemble's results do not depend on the number of threads", "[track]") {
  StructureOptions selection;
  std::vector<std::vector<std::pair<std::string, std::string>>> outputs;
  for (const unsigned jobs : {1u, 3u}) {
    TrackOptions options;
    options.jobs = jobs;
    options.end = 8;  // frames 1, 3, 5, 7
    options.begin = 1;
    options.stride = 2;
    const auto frames = open_frames(kData + "/1l2y.pdb.gz", {}, selection);
    TrackResult r = track(*frames, options);
    REQUIRE(r.frames.size() == 4);
    CHECK(r.frames[1].index == 3);
    CHECK(r.frames[1].name == kData + "/1l2y.pdb.gz model 4");
    outputs.push_back(track_output_files(r));
  }
  REQUIRE(outputs[0].size() == outputs[1].size());
  for (std::size_t k = 0; k < outputs[0].size(); ++k) {
    INFO(outputs[0][k].first);
    CHECK(outputs[0][k].second == outputs[1][k].second);
  }
}

TEST_CASE("the CHK1 ensemble's frequency map finds the ATP site of mdpocket's 0.5 iso-surface", "[track]") {
  // The ten superposed CHK1 structures of mdpocket's example, and the
  // points of mdpocket's frequency iso-surface at 0.5 near the ATP site
  // (within 8 A of 2YEX's inhibitor).
  const std::string dir = kData + "/chk1_mdpocket/";
  const std::vector<std::string> names{"2yex", "3ot3", "3pa3", "3pa4", "3tki", "4hyi", "4rvk", "5opb", "5opu", "5oq5"};
  std::vector<std::string> rest;
  for (std::size_t k = 1; k < names.size(); ++k) rest.push_back(dir + names[k] + ".pdb.gz");
  const auto frames = open_frames(dir + names[0] + ".pdb.gz", rest, {});
  TrackOptions options;
  options.analysis.tunnels_from = "none";
  const TrackResult r = track(*frames, options);
  REQUIRE(r.frames.size() == 10);

  const Structure holo = read_structure(dir + "2yex.pdb.gz");
  REQUIRE(!holo.hetero_groups.empty());
  std::vector<alpha::Vec3> ligand;
  for (const HeteroGroup& g : holo.hetero_groups)
    if (g.atoms.size() >= 10)
      for (const Atom& a : g.atoms) ligand.push_back(a.position);
  REQUIRE(ligand.size() >= 10);
  const auto near = [](const alpha::Vec3& p, const std::vector<alpha::Vec3>& set, double d) {
    return std::any_of(set.begin(), set.end(), [&](const alpha::Vec3& q) {
      const alpha::Vec3 v = p - q;
      return v.x * v.x + v.y * v.y + v.z * v.z <= d * d;
    });
  };
  std::vector<alpha::Vec3> theirs;
  std::ifstream iso(dir + "mdpout_freq_iso_0_5.pdb");
  for (std::string line; std::getline(iso, line);)
    if (line.rfind("ATOM", 0) == 0) {
      const alpha::Vec3 p{std::stod(line.substr(30, 8)), std::stod(line.substr(38, 8)), std::stod(line.substr(46, 8))};
      if (near(p, ligand, 8)) theirs.push_back(p);
    }
  REQUIRE(theirs.size() >= 100);
  std::vector<alpha::Vec3> ours;  // our grid points at frequency >= 0.5
  for (std::size_t p = 0; p < r.frequency.size(); ++p)
    if (r.frequency[p] >= 0.5) ours.push_back(r.grid.point(p));
  std::size_t ours_at_ligand = 0;
  for (const alpha::Vec3& p : ours) ours_at_ligand += near(p, ligand, 3);
  std::size_t covered = 0;
  for (const alpha::Vec3& p : theirs) covered += near(p, ours, 2);
  const double overlap = double(covered) / double(theirs.size());
  WARN("CHK1: " << ours.size() << " grid points at frequency >= 0.5, " << ours_at_ligand << " within 3 A of the "
                << "ligand; mdpocket's ATP-site iso-surface points within 2 A of them: " << covered << " of "
                << theirs.size() << " (" << overlap << ")");
  CHECK(ours_at_ligand >= 20);
  CHECK(overlap >= 0.6);
  // The ATP site is a pocket followed through most frames.
  bool site_tracked = false;
  for (const Track& t : r.tracks) {
    if (t.kind != CavityKind::pocket || t.observations.size() < 5) continue;
    for (std::size_t o : t.observations)
      if (r.observations[o].frame == 0 && near(r.observations[o].center, ligand, 3)) site_tracked = true;
  }
  CHECK(site_tracked);
}

TEST_CASE("volumes.svg keeps round axes for one frame and no pocket, and names its time axis", "[track]") {
  // The tick labels of the plot: its <text> elements' contents.
  const auto labels = [](const std::string& svg) {
    std::vector<std::string> out;
    for (std::size_t at = svg.find("<text"); at != std::string::npos; at = svg.find("<text", at + 1)) {
      const std::size_t from = svg.find('>', at) + 1;
      out.push_back(svg.substr(from, svg.find('<', from) - from));
    }
    return out;
  };
  TrackResult r;
  r.frames.resize(1);
  std::string svg = volume_plot_svg(r, {});
  std::vector<std::string> text = labels(svg);
  for (const std::string& t : text) CHECK(t.find("e-") == std::string::npos);  // not 2e-10
  CHECK(std::count(text.begin(), text.end(), "1") == 2);  // 0..1 frame, 0..1 A^3
  CHECK(std::find(text.begin(), text.end(), "frame") != text.end());
  CHECK(std::find(text.begin(), text.end(), "no pocket in any frame") != text.end());
  // A trajectory's pocket over 0.2 ps.
  r.time_in_ps = true;
  r.frames.resize(3);
  for (std::size_t k = 0; k < 3; ++k) {
    r.frames[k].time = 0.1 * double(k);
    r.observations.push_back({});
    r.observations.back().frame = k;
    r.observations.back().sa_volume = 10 + double(k);
  }
  r.tracks.resize(1);
  r.tracks[0].id = 1;
  r.tracks[0].observations = {0, 1, 2};
  svg = volume_plot_svg(r, {0});
  text = labels(svg);
  CHECK(std::find(text.begin(), text.end(), "time (ps)") != text.end());
  CHECK(std::find(text.begin(), text.end(), "0.2") != text.end());
  CHECK(std::find(text.begin(), text.end(), "pocket 1 (100%)") != text.end());
  CHECK(svg.find("<polyline") != std::string::npos);
}

TEST_CASE("a multi-model PDB file's models one at a time are the models parsed whole", "[track]") {
  const std::string text = gunzip(alpha::read_input_file(kData + "/1l2y.pdb.gz"), "1l2y.pdb.gz", 1 << 24);
  const std::vector<Structure> whole = parse_models(text, "1l2y.pdb");
  const PdbModels models(text);
  REQUIRE(models.size() == 38);
  REQUIRE(whole.size() == 38);
  for (const std::size_t k : {0u, 1u, 17u, 37u}) {
    const Structure one = parse_structure(models.text(k), "1l2y.pdb");
    CHECK(one.report.model == whole[k].report.model);
    REQUIRE(one.atoms.size() == whole[k].atoms.size());
    for (std::size_t i = 0; i < one.atoms.size(); ++i) {
      CHECK(one.atoms[i].position.x == whole[k].atoms[i].position.x);
      CHECK(one.atoms[i].position.z == whole[k].atoms[i].position.z);
    }
  }
  // A bad line in a later model: the file's line number in the message.
  std::string broken = text;
  const std::size_t model3 = broken.find("MODEL        3");
  const std::size_t line = broken.find("\nATOM", model3 + 500) + 1;
  broken.replace(line + 30, 8, "  x.y.z ");
  std::string whole_message, one_message;
  try {
    parse_models(broken, "1l2y.pdb");
  } catch (const std::exception& e) {
    whole_message = e.what();
  }
  try {
    parse_structure(PdbModels(broken).text(2), "1l2y.pdb");
  } catch (const std::exception& e) {
    one_message = e.what();
  }
  CHECK(!whole_message.empty());
  CHECK(one_message == whole_message);
  CHECK(PdbModels("ATOM      1  N   ASN A   1      -6.919   6.901   0.917  1.00  0.00           N\n").size() == 0);
}
