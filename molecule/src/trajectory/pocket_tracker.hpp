// SPDX-License-Identifier: Apache-2.0
// Follows cavities from frame to frame: which cavity of a new frame
// continues which track, which start new ones, split or merge (the rule in
// molecule/track.hpp and docs/trajectories.md).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "trajectory/frame_cavities.hpp"

namespace molecule {

class PocketTracker {
public:
  explicit PocketTracker(double min_lining_overlap) : min_overlap_(min_lining_overlap) {}

  // Appends the frame to `result`: its FrameInfo, its observations, the
  // tracks they extend or start, the splits and merges.
  void add(FrameCavities frame, TrackResult& result);

private:
  struct Last {  // a track's last appearance
    std::vector<std::uint32_t> atoms;  // lining atom ids, sorted
    std::vector<std::uint32_t> space;  // grid points, sorted
    std::size_t frame = 0;
  };
  std::vector<std::uint32_t> atom_ids(const std::vector<std::string>& names);

  double min_overlap_;
  std::map<std::string, std::uint32_t> atom_ids_;       // lining atoms by name, numbered as first seen
  std::vector<Last> last_;                              // per track
  std::vector<std::vector<std::uint32_t>> tracks_of_;  // atom id -> tracks whose last lining holds it
};

}  // namespace molecule
