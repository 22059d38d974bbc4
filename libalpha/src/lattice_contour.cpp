// SPDX-License-Identifier: Apache-2.0
#include "alpha/lattice_contour.hpp"

#include <algorithm>
#include <unordered_map>

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

}  // namespace

SurfaceMesh contour(const Lattice& lattice, const std::vector<std::uint8_t>& inside,
                    const std::function<Vec3(std::size_t, std::size_t, std::size_t)>& vertex) {
  const auto& size = lattice.size;
  if (inside.size() != lattice.num_nodes()) fail("contour: one flag per lattice node expected");
  for (std::size_t n = 0; n < inside.size(); ++n) {
    if (!inside[n]) continue;
    const std::size_t i = n % size[0], j = n / size[0] % size[1], k = n / (size[0] * size[1]);
    if (i == 0 || j == 0 || k == 0 || i + 1 == size[0] || j + 1 == size[1] || k + 1 == size[2])
      fail("contour: a node on the lattice's border is inside");
  }
  static const std::array<Tet, 6> kTets = cube_tetrahedra();
  static const std::array<std::array<int, 4>, 12> kEven = even_permutations();

  SurfaceMesh mesh;
  // Edge (lower node, direction 1..7 as dx + 2 dy + 4 dz) -> its vertex.
  std::unordered_map<std::uint64_t, Index> edge_vertex;
  std::size_t o = 0;  // the cube being cut
  const auto point = [&](std::size_t a, std::size_t b) {  // a inside, b outside
    const std::size_t lo = std::min(a, b), hi = std::max(a, b);
    const std::size_t di = hi % size[0] - lo % size[0], dj = hi / size[0] % size[1] - lo / size[0] % size[1];
    const std::size_t dk = hi / (size[0] * size[1]) - lo / (size[0] * size[1]);
    const std::uint64_t key = std::uint64_t(lo) * 8 + (di + 2 * dj + 4 * dk);
    const auto [it, added] = edge_vertex.try_emplace(key, Index(mesh.points.size()));
    if (added) mesh.points.push_back(vertex(a, b, o));
    return it->second;
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
          mesh.triangles.push_back({point(a, b), point(a, c), point(a, d)});
        } else if (count == 3 && !a_in) {
          mesh.triangles.push_back({point(b, a), point(d, a), point(c, a)});
        } else if (count == 2 && a_in && b_in && !c_in && !d_in) {
          const Index ac = point(a, c), ad = point(a, d), bd = point(b, d), bc = point(b, c);
          mesh.triangles.push_back({ac, ad, bd});
          mesh.triangles.push_back({ac, bd, bc});
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

}  // namespace alpha
