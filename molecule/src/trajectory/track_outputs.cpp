// SPDX-License-Identifier: Apache-2.0
#include "trajectory/track_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "outputs/pocket_colors.hpp"
#include "molecule/residues.hpp"
#include "outputs/structure_copy.hpp"
#include "trajectory/volume_plot.hpp"

namespace molecule {
namespace {

// A CSV number: empty for NaN.
std::string number(double v, int digits = 3) { return std::isnan(v) ? "" : fmt::format("{:.{}f}", v == 0 ? 0.0 : v, digits); }

std::string frames_csv(const TrackResult& r) {
  std::string out = "frame,time,kind,track,rank,sa_volume,ms_volume,probability,mouths,bottleneck_radius,length,x,y,z\n";
  for (const Observation& o : r.observations) {
    const FrameInfo& f = r.frames[o.frame];
    const Track& t = r.tracks[o.track];
    const bool tunnel = t.kind == CavityKind::tunnel;
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", f.index, number(f.time), kind_name(t.kind), t.id,
                       o.rank, tunnel ? "" : number(o.sa_volume), tunnel ? "" : number(o.ms_volume),
                       number(o.probability), o.mouths, number(o.bottleneck_radius), tunnel ? number(o.length) : "",
                       number(o.center.x), number(o.center.y), number(o.center.z));
  }
  return out;
}

// "A:TYR:42=1.000 A:SER:43=0.500": each residue with the share of the track's frames it lines, most frequent first.
std::string residue_frequencies(const Track& t) {
  std::vector<std::pair<std::string, std::size_t>> rs(t.residues.begin(), t.residues.end());
  std::stable_sort(rs.begin(), rs.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string out;
  for (const auto& [id, n] : rs)
    out += (out.empty() ? "" : " ") + id + "=" + number(double(n) / double(t.observations.size()));
  return out;
}

std::string tracks_csv(const TrackResult& r) {
  std::string out =
      "track,kind,frames,frequency,transient,first_frame,last_frame,mean_sa_volume,min_sa_volume,max_sa_volume,"
      "mean_ms_volume,min_ms_volume,max_ms_volume,mean_probability,mean_bottleneck_radius,min_bottleneck_radius,"
      "max_bottleneck_radius,split_from,merged_into,residues\n";
  const auto id = [&](const std::optional<std::size_t>& t) { return t ? std::to_string(r.tracks[*t].id) : ""; };
  for (const Track& t : r.tracks) {
    const bool tunnel = t.kind == CavityKind::tunnel;
    const TrackStats sa = track_stats(r, t, &Observation::sa_volume);
    const TrackStats ms = track_stats(r, t, &Observation::ms_volume);
    const TrackStats p = track_stats(r, t, &Observation::probability);
    const TrackStats b = track_stats(r, t, &Observation::bottleneck_radius);
    const auto v = [&](double x) { return tunnel ? std::string() : number(x); };
    const auto w = [&](double x) { return tunnel ? number(x) : std::string(); };
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", t.id, kind_name(t.kind),
                       t.observations.size(), number(r.frequency_of(t)), r.frequency_of(t) < r.transient ? 1 : 0,
                       r.frames[r.observations[t.observations.front()].frame].index,
                       r.frames[r.observations[t.observations.back()].frame].index, v(sa.mean), v(sa.min), v(sa.max),
                       v(ms.mean), v(ms.min), v(ms.max), tunnel ? "" : number(p.mean), w(b.mean), w(b.min), w(b.max),
                       id(t.split_from), id(t.merged_into), residue_frequencies(t));
  }
  return out;
}

std::string events_csv(const TrackResult& r) {
  std::string out = "frame,time,event,track,other\n";
  for (const TrackEvent& e : r.events)
    out += fmt::format("{},{},{},{},{}\n", r.frames[e.frame].index, number(r.frames[e.frame].time), e.event,
                       r.tracks[e.track].id, r.tracks[e.other].id);
  return out;
}

// The first frame, the 0.5 isosurface of the frequency grid, and for each
// top pocket its residues lining it in at least half its frames (atom ids
// of structure.cif: no name from the input reaches the script) and a
// sphere at its centre in its first frame.
std::string pymol_script(const TrackResult& r) {
  std::string out =
      "# alphapocket track: the first frame, the pocket frequency grid's 0.5 isosurface and the top pockets\n"
      "load structure.cif, frame1\nhide everything, frame1\nshow cartoon, frame1\ncolor grey80, frame1\n"
      "load frequency.dx, frequency\nisosurface frequency_05, frequency, 0.5\ncolor grey50, frequency_05\n"
      "set transparency, 0.4\nload density.dx, density\n";
  const std::vector<Atom>& atoms = r.first_structure.atoms;
  std::size_t shown = 0;
  for (std::size_t t : top_pockets(r)) {
    if (shown == kTopTracks) break;
    const Track& track = r.tracks[t];
    const Rgb c = rank_color(++shown);
    const std::string name = fmt::format("pocket_{}", track.id);
    std::string ids;
    for (std::size_t i = 0; i < atoms.size(); ++i) {
      const auto it = track.residues.find(residue_id(atoms[i]));
      if (it != track.residues.end() && 2 * it->second >= track.observations.size())
        ids += (ids.empty() ? "" : "+") + std::to_string(i + 1);
    }
    out += fmt::format("set_color {}_color, [{}, {}, {}]\n", name, c.r, c.g, c.b);
    if (!ids.empty())
      out += fmt::format("select {}_lining, frame1 and id {}\nshow sticks, {}_lining and not name N+C+O\n"
                         "color {}_color, {}_lining and elem C\n",
                         name, ids, name, name, name);
    const Observation& o = r.observations[track.observations.front()];
    out += fmt::format("pseudoatom {}, pos=[{:.3f}, {:.3f}, {:.3f}], vdw=1.5\nshow spheres, {}\ncolor {}_color, {}\n",
                       name, o.center.x, o.center.y, o.center.z, name, name, name);
  }
  return out + "deselect\norient frame1\n";
}

}  // namespace

std::vector<std::size_t> top_pockets(const TrackResult& r) {
  std::vector<std::size_t> out;
  std::vector<double> mean(r.tracks.size(), 0);
  for (std::size_t t = 0; t < r.tracks.size(); ++t) {
    if (r.tracks[t].kind != CavityKind::pocket) continue;
    out.push_back(t);
    mean[t] = track_stats(r, r.tracks[t], &Observation::sa_volume).mean;
  }
  std::stable_sort(out.begin(), out.end(), [&](std::size_t a, std::size_t b) {
    const std::size_t na = r.tracks[a].observations.size(), nb = r.tracks[b].observations.size();
    return na != nb ? na > nb : mean[a] > mean[b];
  });
  return out;
}

std::string opendx(const SpaceGrid& g, const std::vector<float>& values, const std::string& title) {
  std::string out = fmt::format(
      "# {}\nobject 1 class gridpositions counts {} {} {}\norigin {:.6f} {:.6f} {:.6f}\ndelta {:.6f} 0 0\n"
      "delta 0 {:.6f} 0\ndelta 0 0 {:.6f}\nobject 2 class gridconnections counts {} {} {}\n"
      "object 3 class array type double rank 0 items {} data follows\n",
      title, g.nx, g.ny, g.nz, g.origin.x, g.origin.y, g.origin.z, g.spacing, g.spacing, g.spacing, g.nx, g.ny, g.nz,
      values.size());
  // Most points lie in no cavity: their 0 is written without formatting.
  out.reserve(out.size() + 2 * values.size());
  for (std::size_t p = 0; p < values.size(); ++p) {
    if (values[p] == 0 && !std::signbit(values[p]))
      out += '0';
    else
      fmt::format_to(std::back_inserter(out), "{:g}", values[p]);
    out += p % 3 == 2 || p + 1 == values.size() ? '\n' : ' ';
  }
  return out + fmt::format(
                   "attribute \"dep\" string \"positions\"\nobject \"{}\" class field\n"
                   "component \"positions\" value 1\ncomponent \"connections\" value 2\ncomponent \"data\" value 3\n",
                   title);
}

std::vector<std::string> track_output_names() {
  return {"frames.csv", "tracks.csv", "events.csv", "frequency.dx", "density.dx", "structure.cif", "track.pml", "volumes.svg"};
}

std::vector<std::pair<std::string, std::string>> track_output_files(const TrackResult& r) {
  std::vector<std::size_t> top = top_pockets(r);
  top.resize(std::min(top.size(), kTopTracks));
  return {{"frames.csv", frames_csv(r)},
          {"tracks.csv", tracks_csv(r)},
          {"events.csv", events_csv(r)},
          {"frequency.dx", opendx(r.grid, r.frequency, "pocket frequency")},
          {"density.dx", opendx(r.grid, r.density, "pocket density")},
          {"structure.cif", structure_copy(r.first_structure, "alphapocket track: first frame").cif},
          {"track.pml", pymol_script(r)},
          {"volumes.svg", volume_plot_svg(r, top)}};
}

}  // namespace molecule
