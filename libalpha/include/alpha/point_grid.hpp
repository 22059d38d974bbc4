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
  void finish() { std::sort(entries_.begin(), entries_.end()); }

  // Calls f(id) for every point in the grid cells that meet the cube of
  // half-side `radius` about `center`: a superset of the points within
  // `radius`, in a fixed order.
  template <class F>
  void visit(const Vec3& center, double radius, F f) const {
    const Key lo = key({center.x - radius, center.y - radius, center.z - radius});
    const Key hi = key({center.x + radius, center.y + radius, center.z + radius});
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const Key k{x, y, z};
          auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(k, Index(0)));
          for (; it != entries_.end() && it->first == k; ++it) f(it->second);
        }
  }

private:
  using Key = std::array<std::int64_t, 3>;
  Key key(const Vec3& p) const {
    return {std::int64_t(std::floor(p.x / spacing_)), std::int64_t(std::floor(p.y / spacing_)),
            std::int64_t(std::floor(p.z / spacing_))};
  }
  double spacing_;
  std::vector<std::pair<Key, Index>> entries_;
};

}  // namespace alpha
