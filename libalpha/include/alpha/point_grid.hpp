// SPDX-License-Identifier: Apache-2.0
// Points bucketed in a uniform grid, for "all points near x" queries when
// the query radius is about the grid's spacing.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "alpha/geometry.hpp"

namespace alpha {

class PointGrid {
public:
  explicit PointGrid(double spacing = 1) : spacing_(spacing > 0 ? spacing : 1) {}

  void add(const Vec3& p, Index id) { entries_.emplace_back(key(p), id); }
  // Call once after the last add, before any query.
  void finish();

  // Calls f(id) for every point in the grid cells that meet the cube of
  // half-side `radius` about `center`: a superset of the points within
  // `radius`, in key order. A cube of more cells than there are points
  // (huge, or over sparse points) is answered by a scan of the points, so
  // no query walks more cells than there are points; a NaN visits nothing.
  // (A NaN point is kept in an extreme cell: defined, not meaningful.)
  template <class F>
  void visit(const Vec3& center, double radius, F f) const {
    any(center, radius, [&](Index id) {
      f(id);
      return false;
    });
  }

  // The same visit, stopping at the first point for which f(id) is true;
  // whether there was one.
  template <class F>
  bool any(const Vec3& center, double radius, F f) const {
    Key lo, hi;
    if (!range(center, radius, lo, hi)) return false;
    double cells = 1;
    for (int a = 0; a < 3; ++a) cells *= double(hi[a]) - double(lo[a]) + 1;  // in doubles: no overflow
    if (cells > double(entries_.size())) {
      for (const auto& [k, id] : entries_)
        if (lo[0] <= k[0] && k[0] <= hi[0] && lo[1] <= k[1] && k[1] <= hi[1] && lo[2] <= k[2] && k[2] <= hi[2] &&
            f(id))
          return true;
      return false;
    }
    if (!start_.empty()) {
      for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
          // The row's cells lo[2]..hi[2] hold consecutive entries.
          const std::size_t row = row_index(x, y);
          const Index end = start_[row + std::size_t(hi[2] - low_[2]) + 1];
          for (Index e = start_[row + std::size_t(lo[2] - low_[2])]; e < end; ++e)
            if (f(entries_[e].second)) return true;
        }
      return false;
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const Key k{x, y, z};
          auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(k, Index(0)));
          for (; it != entries_.end() && it->first == k; ++it)
            if (f(it->second)) return true;
        }
    return false;
  }

  // Whether visit(center, radius) reaches every point.
  bool covers_all(const Vec3& center, double radius) const {
    Key lo, hi;
    return entries_.empty() || (range(center, radius, lo, hi) && lo == low_ && hi == high_);
  }

private:
  using Key = std::array<std::int64_t, 3>;
  static constexpr std::int64_t kFar = std::int64_t(1) << 62;

  // The occupied cells meeting the cube, per axis; false if none.
  bool range(const Vec3& c, double r, Key& lo, Key& hi) const {
    const double center[3] = {c.x, c.y, c.z};
    for (int a = 0; a < 3; ++a) {
      const double l = (center[a] - r) / spacing_, h = (center[a] + r) / spacing_;
      if (std::isnan(l) || std::isnan(h)) return false;
      lo[a] = std::max(low_[a], cell(l));
      hi[a] = std::min(high_[a], cell(h));
      if (lo[a] > hi[a]) return false;
    }
    return true;
  }
  // floor(v), saturated: the cast of a far or infinite value is undefined.
  static std::int64_t cell(double v) {
    const double f = std::floor(v);
    return f >= double(kFar) ? kFar : f > -double(kFar) ? std::int64_t(f) : -kFar;  // NaN: -kFar, defined
  }
  // Of a cell in the occupied range, x major (the keys' order).
  std::size_t row_index(std::int64_t x, std::int64_t y) const {
    const std::size_t ny = std::size_t(high_[1] - low_[1] + 1), nz = std::size_t(high_[2] - low_[2] + 1);
    return (std::size_t(x - low_[0]) * ny + std::size_t(y - low_[1])) * nz;
  }
  std::size_t cell_index(const Key& k) const { return row_index(k[0], k[1]) + std::size_t(k[2] - low_[2]); }
  Key key(const Vec3& p) const { return {cell(p.x / spacing_), cell(p.y / spacing_), cell(p.z / spacing_)}; }
  double spacing_;
  std::vector<std::pair<Key, Index>> entries_;
  std::vector<Index> start_;  // per cell of the occupied range, or empty
  Key low_{kFar, kFar, kFar}, high_{-kFar, -kFar, -kFar};  // occupied cells' range
};

}  // namespace alpha
