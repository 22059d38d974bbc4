// SPDX-License-Identifier: Apache-2.0
#include "trajectory/pocket_tracker.hpp"

#include <algorithm>
#include <optional>
#include <tuple>
#include <unordered_map>

namespace molecule {
namespace {

std::size_t common(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  std::size_t n = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();)
    if (*i < *j) ++i;
    else if (*j < *i) ++j;
    else ++n, ++i, ++j;
  return n;
}

struct Candidate {
  double overlap;  // Jaccard index of the linings
  std::size_t shared_space;
  std::size_t track, cavity;
  // Best first; ties by track, then cavity: the same pairs on every run.
  bool operator<(const Candidate& o) const {
    return std::tie(o.overlap, o.shared_space, track, cavity) < std::tie(overlap, shared_space, o.track, o.cavity);
  }
};

}  // namespace

std::vector<std::uint32_t> PocketTracker::atom_ids(const std::vector<std::string>& names) {
  std::vector<std::uint32_t> ids;
  for (const std::string& n : names) {
    const auto [it, added] = atom_ids_.try_emplace(n, std::uint32_t(atom_ids_.size()));
    if (added) tracks_of_.emplace_back();
    ids.push_back(it->second);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

void PocketTracker::add(FrameCavities frame, TrackResult& result) {
  const std::size_t fp = result.frames.size();
  result.frames.push_back(frame.info);
  std::vector<FrameCavity>& cavities = frame.cavities;
  std::vector<std::vector<std::uint32_t>> atoms;
  for (const FrameCavity& c : cavities) atoms.push_back(atom_ids(c.lining_atoms));

  // Every (track, cavity) pair of one kind sharing enough lining and some space.
  std::vector<Candidate> candidates;
  for (std::size_t c = 0; c < cavities.size(); ++c) {
    std::unordered_map<std::size_t, std::size_t> shared;  // track -> common lining atoms
    for (std::uint32_t a : atoms[c])
      for (std::uint32_t t : tracks_of_[a]) ++shared[t];
    for (const auto& [t, n] : shared) {
      if (result.tracks[t].kind != cavities[c].kind) continue;
      const double overlap = double(n) / double(atoms[c].size() + last_[t].atoms.size() - n);
      const std::size_t space = common(cavities[c].space, last_[t].space);
      const bool space_ok = space > 0 || cavities[c].space.empty() || last_[t].space.empty();
      if (overlap >= min_overlap_ && space_ok) candidates.push_back({overlap, space, t, c});
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<std::optional<std::size_t>> track_of(cavities.size());  // cavity -> track
  std::vector<bool> taken(result.tracks.size(), false);
  for (const Candidate& k : candidates)
    if (!taken[k.track] && !track_of[k.cavity]) taken[k.track] = true, track_of[k.cavity] = k.track;

  // Left-over cavities start tracks, split from a track this frame continues if they match one.
  for (std::size_t c = 0; c < cavities.size(); ++c) {
    if (track_of[c]) continue;
    Track t;
    t.id = result.tracks.size() + 1;
    t.kind = cavities[c].kind;
    for (const Candidate& k : candidates)  // best first
      if (k.cavity == c && taken[k.track]) {
        t.split_from = k.track;
        result.events.push_back({fp, "split", result.tracks.size(), k.track});
        break;
      }
    track_of[c] = result.tracks.size();
    result.tracks.push_back(std::move(t));
    last_.emplace_back();
    taken.push_back(true);
  }
  // Tracks of the previous frame not continued but matching a continued cavity merged into its track.
  for (const Candidate& k : candidates) {
    Track& t = result.tracks[k.track];
    if (taken[k.track] || t.merged_into || last_[k.track].frame + 1 != fp) continue;
    t.merged_into = *track_of[k.cavity];
    result.events.push_back({fp, "merge", k.track, *track_of[k.cavity]});
  }

  for (std::size_t c = 0; c < cavities.size(); ++c) {
    const std::size_t t = *track_of[c];
    Observation o = cavities[c].measures;
    o.frame = fp;
    o.track = t;
    result.tracks[t].observations.push_back(result.observations.size());
    result.observations.push_back(o);
    for (const std::string& r : cavities[c].residues) ++result.tracks[t].residues[r];
    Last& last = last_[t];
    for (std::uint32_t a : last.atoms) std::erase(tracks_of_[a], std::uint32_t(t));
    for (std::uint32_t a : atoms[c]) tracks_of_[a].push_back(std::uint32_t(t));
    last.atoms = std::move(atoms[c]);
    last.space = std::move(cavities[c].space);
    last.frame = fp;
  }
}

}  // namespace molecule
