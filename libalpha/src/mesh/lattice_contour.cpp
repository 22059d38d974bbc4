// SPDX-License-Identifier: Apache-2.0
#include "alpha/lattice_contour.hpp"

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

#include "alpha/error.hpp"

namespace alpha {
namespace {

using Corner = std::array<int, 3>;
using Tet = std::array<Corner, 4>;

double det(const Corner& a, const Corner& b, const Corner& c) {
  return double(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]));
}

// The 6 tetrahedra of the unit cube along its diagonal from (0,0,0) to
// (1,1,1), one per order of the axes, each positively oriented.
std::array<Tet, 6> cube_tetrahedra() {
  std::array<Tet, 6> out;
  std::array<int, 3> axis{0, 1, 2};
  int n = 0;
  do {
    Tet t{};
    for (int k = 1; k < 4; ++k) {
      t[k] = t[k - 1];
      if (k < 3) t[k][axis[k - 1]] = 1;
    }
    t[3] = {1, 1, 1};
    if (det(t[1], t[2], t[3]) < 0) std::swap(t[1], t[2]);
    out[n++] = t;
  } while (std::next_permutation(axis.begin(), axis.end()));
  return out;
}

// The 12 even permutations of (0, 1, 2, 3): they keep the orientation.
std::array<std::array<int, 4>, 12> even_permutations() {
  std::array<std::array<int, 4>, 12> out;
  std::array<int, 4> p{0, 1, 2, 3};
  int n = 0;
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
    if (inversions % 2 == 0) out[n++] = p;
  } while (std::next_permutation(p.begin(), p.end()));
  return out;
}

// Edge keys (never 0: the direction is 1..7) to vertex ids: open
// addressing, linear probing, at most half full (a node-based hash map
// allocated and freed a node per vertex: a tenth of the surface mesh's time).
class EdgeTable {
public:
  // The id stored for key, kNone when new (then to be set).
  Index& at(std::uint64_t key) {
    if (2 * (used_ + 1) > keys_.size()) grow();
    std::size_t k = slot(key);
    while (keys_[k] != 0 && keys_[k] != key) k = (k + 1) & (keys_.size() - 1);
    if (keys_[k] == 0) keys_[k] = key, ids_[k] = kNone, ++used_;
    return ids_[k];
  }

private:
  std::size_t slot(std::uint64_t key) const {
    return std::size_t((key * 0x9E3779B97F4A7C15ull) >> 32) & (keys_.size() - 1);
  }
  void grow() {
    std::vector<std::uint64_t> keys(std::max<std::size_t>(1024, 2 * keys_.size()), 0);
    std::vector<Index> ids(keys.size(), kNone);
    keys.swap(keys_);
    ids.swap(ids_);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (keys[k] == 0) continue;
      std::size_t j = slot(keys[k]);
      while (keys_[j] != 0) j = (j + 1) & (keys_.size() - 1);
      keys_[j] = keys[k], ids_[j] = ids[k];
    }
  }
  std::vector<std::uint64_t> keys_;
  std::vector<Index> ids_;
  std::size_t used_ = 0;
};

}  // namespace

SurfaceMesh contour(const Lattice& lattice, const std::vector<std::uint8_t>& inside,
                    const std::function<Vec3(std::size_t, std::size_t, std::size_t)>& vertex,
                    const ContourSplit& split) {
  const auto& size = lattice.size;
  if (inside.size() != lattice.num_nodes()) fail("contour: one flag per lattice node expected", ErrorKind::Misuse);
  for (std::size_t n = 0; n < inside.size(); ++n) {
    if (!inside[n]) continue;
    const std::size_t i = n % size[0], j = n / size[0] % size[1], k = n / (size[0] * size[1]);
    if (i == 0 || j == 0 || k == 0 || i + 1 == size[0] || j + 1 == size[1] || k + 1 == size[2])
      fail("contour: a node on the lattice's border is inside", ErrorKind::Misuse);
  }
  static const std::array<Tet, 6> kTets = cube_tetrahedra();
  static const std::array<std::array<int, 4>, 12> kEven = even_permutations();

  SurfaceMesh mesh;
  // Edge (lower node, direction 1..7 as dx + 2 dy + 4 dz) -> its vertex.
  EdgeTable edge_vertex;
  std::size_t o = 0;  // the cube being cut
  const auto point = [&](std::size_t a, std::size_t b) {  // a inside, b outside
    const std::size_t lo = std::min(a, b), hi = std::max(a, b);
    const std::size_t di = hi % size[0] - lo % size[0], dj = hi / size[0] % size[1] - lo / size[0] % size[1];
    const std::size_t dk = hi / (size[0] * size[1]) - lo / (size[0] * size[1]);
    const std::uint64_t key = std::uint64_t(lo) * 8 + (di + 2 * dj + 4 * dk);
    Index& slot = edge_vertex.at(key);
    if (slot == kNone) {
      slot = Index(mesh.points.size());
      mesh.points.push_back(vertex(a, b, o));
    }
    return slot;
  };
  // Segment (its two vertex ids) -> the point inserted on it, kNone for
  // none, kNone - 1 when split() declined.
  EdgeTable segment_point;
  constexpr Index kDeclined = kNone - 1;
  // Fans the polygon (vertex ids counter-clockwise from outside) from its
  // first inserted point, or from its first vertex when none.
  const auto polygon = [&](std::initializer_list<Index> ids) {
    std::array<Index, 8> v{};
    std::size_t n = 0, apex = 0;
    bool inserted = false;
    for (auto it = ids.begin(); it != ids.end(); ++it) {
      v[n++] = *it;
      if (!split) continue;
      const Index p = *it, q = it + 1 == ids.end() ? *ids.begin() : *(it + 1);
      Index& s = segment_point.at((std::uint64_t(std::min(p, q)) << 32) + std::max(p, q));
      if (s == kNone) {
        const std::optional<Vec3> x = split(p, q);
        s = x ? Index(mesh.points.size()) : kDeclined;
        if (x) mesh.points.push_back(*x);
      }
      if (s == kDeclined) continue;
      if (!inserted) apex = n, inserted = true;
      v[n++] = s;
    }
    for (std::size_t k = 1; k + 1 < n; ++k) mesh.triangles.push_back({v[apex], v[(apex + k) % n], v[(apex + k + 1) % n]});
  };
  const std::size_t dj = size[0], dk = size[0] * size[1];
  const auto cube = [&](std::size_t i, std::size_t j, std::size_t k) {
    // Most cubes have all corners alike (no surface): told by 8 reads.
    o = lattice.index(i, j, k);
    const std::uint8_t first = inside[o];
    if (inside[o + 1] == first && inside[o + dj] == first && inside[o + dj + 1] == first && inside[o + dk] == first &&
        inside[o + dk + 1] == first && inside[o + dk + dj] == first && inside[o + dk + dj + 1] == first)
      return;
    for (const Tet& t : kTets) {
      std::array<std::size_t, 4> node;
      int mask = 0, count = 0;
      for (int c = 0; c < 4; ++c) {
        node[c] = lattice.index(i + t[c][0], j + t[c][1], k + t[c][2]);
        if (inside[node[c]]) mask |= 1 << c, ++count;
      }
      if (count == 0 || count == 4) continue;
      // An even permutation (a, b, c, d) with the lone node first (count 1
      // or 3), or the two inside nodes first (count 2).
      for (const auto& p : kEven) {
        const bool a_in = mask >> p[0] & 1, b_in = mask >> p[1] & 1, c_in = mask >> p[2] & 1, d_in = mask >> p[3] & 1;
        const std::size_t a = node[p[0]], b = node[p[1]], c = node[p[2]], d = node[p[3]];
        if (count == 1 && a_in) {
          polygon({point(a, b), point(a, c), point(a, d)});
        } else if (count == 3 && !a_in) {
          polygon({point(b, a), point(d, a), point(c, a)});
        } else if (count == 2 && a_in && b_in && !c_in && !d_in) {
          polygon({point(a, c), point(a, d), point(b, d), point(b, c)});
        } else {
          continue;
        }
        break;
      }
    }
  };
  const std::size_t B = kContourBlock;
  for (std::size_t bk = 0; bk + 1 < size[2]; bk += B)
    for (std::size_t bj = 0; bj + 1 < size[1]; bj += B)
      for (std::size_t bi = 0; bi + 1 < size[0]; bi += B)
        for (std::size_t k = bk; k < std::min(bk + B, size[2] - 1); ++k)
          for (std::size_t j = bj; j < std::min(bj + B, size[1] - 1); ++j)
            for (std::size_t i = bi; i < std::min(bi + B, size[0] - 1); ++i) cube(i, j, k);
  return mesh;
}

double enclosed_volume(const SurfaceMesh& mesh) {
  double v = 0;
  for (const auto& [a, b, c] : mesh.triangles) v += dot(mesh.points[a], cross(mesh.points[b], mesh.points[c]));
  return v / 6;
}

}  // namespace alpha
