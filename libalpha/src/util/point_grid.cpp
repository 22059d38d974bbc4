// SPDX-License-Identifier: Apache-2.0
#include "alpha/point_grid.hpp"

namespace alpha {

void PointGrid::finish() {
  for (const auto& e : entries_)
    for (int a = 0; a < 3; ++a) low_[a] = std::min(low_[a], e.first[a]), high_[a] = std::max(high_[a], e.first[a]);
  // Each occupied range's cell's first entry, when the range has not
  // many more cells than points (a query then finds a cell by index, not
  // by binary search); sorted keys run in cell-index order.
  start_.clear();
  double cells = 1;
  for (int a = 0; a < 3; ++a) cells *= double(high_[a]) - double(low_[a]) + 1;
  if (entries_.empty() || cells > 8 * double(entries_.size()) + 4096) {
    std::sort(entries_.begin(), entries_.end());
    return;
  }
  start_.assign(std::size_t(cells) + 1, Index(0));
  for (const auto& e : entries_) ++start_[cell_index(e.first) + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  // The same order as sorting the (key, id) pairs: by cell, counting,
  // then each cell's few entries by id (mostly added in that order).
  std::vector<std::pair<Key, Index>> sorted(entries_.size());
  std::vector<Index> next(start_.begin(), start_.end() - 1);
  for (const auto& e : entries_) sorted[next[cell_index(e.first)]++] = e;
  for (std::size_t c = 0; c + 1 < start_.size(); ++c)
    if (start_[c + 1] - start_[c] > 1) std::sort(sorted.begin() + start_[c], sorted.begin() + start_[c + 1]);
  entries_ = std::move(sorted);
}

}  // namespace alpha
