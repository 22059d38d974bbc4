// SPDX-License-Identifier: Apache-2.0
#include "molecule/track_result.hpp"

#include <algorithm>
#include <cmath>

namespace molecule {

const char* kind_name(CavityKind kind) {
  return kind == CavityKind::pocket ? "pocket" : kind == CavityKind::void_ ? "void" : "tunnel";
}

TrackStats track_stats(const TrackResult& r, const Track& t, double Observation::*measure) {
  TrackStats s{0, INFINITY, -INFINITY};
  for (std::size_t o : t.observations) {
    const double v = r.observations[o].*measure;
    s.mean += v, s.min = std::min(s.min, v), s.max = std::max(s.max, v);
  }
  s.mean /= double(t.observations.size());
  return s;
}

}  // namespace molecule
