// SPDX-License-Identifier: Apache-2.0
// A piece of the eroded union's layer split by power cell (the per-atom
// split, eroded_union_shares.cpp): the balls whose cells can hold its
// points and its volume and area per cell.
#pragma once
#include <utility>
#include <vector>

#include "alpha/eroded_union.hpp"

namespace alpha {
namespace eroded_union_detail {

// The balls whose power cells can hold the points of a piece (the
// piece's balls and their neighbours): power_m(x) = |x - p|^2 - w.
struct Site {
  Vec3 p;
  double w;
  Index id;
};

// One piece's volume and area per power cell, integrated at nodes: scaled
// to the piece's total when added (see add_scaled).
struct PieceShares {
  std::vector<std::pair<Index, LayerShare>> parts;
  void add(Index id, double volume, double area) {
    for (auto& [k, x] : parts)
      if (k == id) {
        x.volume += volume;
        x.area += area;
        return;
      }
    parts.push_back({id, {volume, area}});
  }
};

}  // namespace eroded_union_detail
}  // namespace alpha
