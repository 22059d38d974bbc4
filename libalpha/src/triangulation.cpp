// SPDX-License-Identifier: Apache-2.0
#include "alpha/triangulation.hpp"

#include <algorithm>
#include <bit>

#include <cmath>
#include <numeric>
#include <string>

#include "alpha/error.hpp"
#include "alpha/spatial_sort.hpp"
#include "huge_pages.hpp"

namespace alpha {
namespace {

// Far beyond any physical coordinate, yet squares and products of
// differences stay well inside double range for the filters.
constexpr double kMaxCoordinate = 1e15;
constexpr double kMaxWeight = 1e30;
constexpr double kMinExtent = 1e-100;

void check_input(const std::vector<Vec3>& points, const std::vector<double>& weights) {
  if (!weights.empty() && weights.size() != points.size())
    fail("got " + std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) +
         " points", ErrorKind::Misuse);
  if (points.size() >= kInfinite) fail("too many points: " + std::to_string(points.size()), ErrorKind::LimitExceeded);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    for (double v : {p.x, p.y, p.z})
      if (!std::isfinite(v) || std::fabs(v) > kMaxCoordinate)
        fail("point " + std::to_string(i) + ": coordinate " + std::to_string(v) +
             (std::isfinite(v) ? " is out of range (|x| > 1e15)" : " is not a finite number"));
    if (!weights.empty() && (!std::isfinite(weights[i]) || std::fabs(weights[i]) > kMaxWeight))
      fail("point " + std::to_string(i) + ": weight " + std::to_string(weights[i]) +
           " is not a finite number within 1e30");
  }
  // Sizes scale as the squared extent: below this, the doubles that report
  // them (spectrum values, alpha_sq) would round to 0 or subnormals.
  double extent = 0;
  for (const auto axis : {&Vec3::x, &Vec3::y, &Vec3::z}) {
    const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                              [&](const Vec3& a, const Vec3& b) { return a.*axis < b.*axis; });
    if (lo != points.end()) extent = std::max(extent, (*hi).*axis - (*lo).*axis);
  }
  if (extent > 0 && extent < kMinExtent)
    fail("the points span only " + std::to_string(extent) + " (below 1e-100): their sizes would underflow");
}

// The dimension of the affine hull of the points `order` lists (-1 if none,
// 0 to 3), and in `first` the points that span it, the first found in
// order: a; b, the first point other than a; c, the first off the line ab;
// d, the first off the plane abc. Exact.
int spanning_points(Kernel& kernel, const std::vector<Vec3>& p, const std::vector<Index>& order,
                    std::array<Index, 4>& first) {
  if (order.empty()) return -1;
  const Index a = order[0];
  const auto find = [&](auto off) {
    const auto it = std::find_if(order.begin(), order.end(), off);
    return it == order.end() ? kNone : *it;
  };
  const Index b = find([&](Index i) { return p[i] != p[a]; });
  if (b == kNone) return 0;
  const Index c = find([&](Index i) {
    for (int axis = 0; axis < 3; ++axis)  // collinear: coplanar with ab and each axis direction
      if (kernel.orient3d(p[a], p[b], p[i], Kernel::axis_offset(p[a], axis)) != 0) return true;
    return false;
  });
  if (c == kNone) return 1;
  const Index d = find([&](Index i) { return kernel.orient3d(p[a], p[b], p[c], p[i]) != 0; });
  if (d == kNone) return 2;
  first = {a, b, c, d};
  return 3;
}

}  // namespace

int affine_dimension(const std::vector<Vec3>& points) {
  Kernel kernel(points.data(), nullptr);
  std::vector<Index> order(points.size());
  std::iota(order.begin(), order.end(), Index(0));
  std::array<Index, 4> first;
  return spanning_points(kernel, points, order, first);
}

// The incremental construction; lives only while the triangulation is built.
// It works on a copy of the points in insertion order, so that consecutive
// insertions read nearby memory: a vertex id is a position in that order
// (input_[id] is its input index, which also orders the perturbation) until
// finish() writes the input indices into the cells.
class Triangulation::Builder {
public:
  explicit Builder(Triangulation& t) : t_(t) {}

  void run() {
    const std::vector<Index> reps = merge_duplicates();
    if (reps.size() < 4)
      fail("need at least 4 distinct points, got " + std::to_string(reps.size()));
    // A Delaunay triangulation of n random points has about 6.7 n cells;
    // reserving avoids repeated copies and page faults while growing.
    const std::size_t expected = reps.size() * 27 / 4 + 64;
    // The cell array is written at random places as it fills.
    reserve_huge(cells_, expected);
    cell_mark_.assign(expected, 0);
    input_ = brio_order(t_.points_, reps);
    points_.reserve(input_.size());
    for (Index i : input_) points_.push_back(t_.points_[i]);
    if (t_.weighted())
      for (Index i : input_) weights_.push_back(t_.weights_[i]);
    kernel_ = Kernel(points_.data(), weights_.empty() ? nullptr : weights_.data(), input_.data());
    const std::array<Index, 4> first = initial_simplex();
    Index hint = 0;
    for (Index p = 0; p < points_.size(); ++p) {
      if (p == first[0] || p == first[1] || p == first[2] || p == first[3]) continue;
      hint = insert(p, hint);
    }
    finish();
  }

private:
  struct Facet {  // a cavity boundary facet, copied before cells are reused
    std::array<Index, 4> v;  // the new cell's vertices (p replaces the conflict vertex)
    int i;                   // position of p
    Index outside;           // the neighbour that stays
    int mirror;              // its local index of the conflict cell
  };
  struct EdgeSlot {  // cavity edge table entry; empty unless stamp is this insertion's
    std::uint64_t key;
    Index cell;
    std::uint32_t stamp;
    int facet;
  };
  static constexpr std::uint64_t kUsedEdge = ~0ull;
  // kSideFacets[i]: for a new cell whose vertex i is p, each facet j != i
  // with the local indices a, b of the boundary edge it holds, in the order
  // (i, a, b) that kFacet[j] lists them cyclically. The new cell across that
  // facet sees it from the other side: it lists the same edge as (b, a).
  static constexpr std::array<std::array<std::array<int, 3>, 3>, 4> kSideFacets{{
      {{{1, 2, 3}, {2, 3, 1}, {3, 1, 2}}},
      {{{0, 3, 2}, {2, 0, 3}, {3, 2, 0}}},
      {{{0, 1, 3}, {1, 3, 0}, {3, 0, 1}}},
      {{{0, 2, 1}, {1, 0, 2}, {2, 1, 0}}},
  }};

  Triangulation& t_;
  std::vector<Index> input_;    // input index of each vertex id
  std::vector<Vec3> points_;    // point of each vertex id
  std::vector<double> weights_; // its weight (weighted input only)
  Kernel kernel_{nullptr, nullptr};  // on points_, once they are copied
  std::vector<Cell>& cells_ = t_.cells_;
  std::vector<std::uint32_t> cell_mark_;  // == stamp_: conflict, == stamp_+1: tested, no conflict
  std::uint32_t stamp_ = 2;
  std::vector<Index> free_cells_, conflict_, stack_;
  std::vector<Facet> boundary_;
  std::vector<EdgeSlot> edges_;
  std::vector<std::uint32_t> vertex_mark_;
  std::vector<Index> cavity_vertices_;
  std::uint32_t walk_rng_ = 0x9e3779b9u;

  // Groups equal points through a hash table of their coordinates (no sort:
  // its comparisons are unpredictable branches and scattered reads). Returns
  // the representatives in increasing order.
  std::vector<Index> merge_duplicates() {
    const auto& pts = t_.points_;
    const std::size_t n = pts.size();
    const int bits = std::bit_width(2 * n + 1);  // at most half full
    const std::size_t mask = (std::size_t(1) << bits) - 1;
    auto hash = [&](const Vec3& p) {
      // + 0.0 turns -0.0 into 0.0, which compares equal to it.
      std::uint64_t h = std::bit_cast<std::uint64_t>(p.x + 0.0);
      h = (h ^ std::bit_cast<std::uint64_t>(p.y + 0.0)) * 0x9e3779b97f4a7c15ull;
      h = (h ^ std::bit_cast<std::uint64_t>(p.z + 0.0)) * 0xbf58476d1ce4e5b9ull;
      return std::size_t(h >> (64 - bits));
    };
    std::vector<Index> table(mask + 1, kNone);  // slot -> the first point of its coordinates
    auto& rep = t_.representative_;
    rep.resize(n);
    std::vector<Index> first(n);
    for (Index i = 0; i < n; ++i) {
      std::size_t h = hash(pts[i]);
      while (table[h] != kNone && pts[table[h]] != pts[i]) h = (h + 1) & mask;
      if (table[h] == kNone) table[h] = i, rep[i] = i;
      first[i] = table[h];
      // The largest weight, then the smallest index, represents the group.
      Index& best = rep[first[i]];
      if (t_.weight(i) > t_.weight(best)) best = i;
    }
    t_.status_.assign(n, PointStatus::vertex);
    std::vector<Index> reps;
    for (Index i = 0; i < n; ++i) {
      rep[i] = rep[first[i]];  // first[i] <= i: already final
      if (rep[i] != i) t_.status_[i] = PointStatus::duplicate, ++t_.num_duplicates_;
      else reps.push_back(i);
    }
    return reps;
  }

  std::array<Index, 4> initial_simplex() {
    std::vector<Index> order(points_.size());
    std::iota(order.begin(), order.end(), Index(0));
    std::array<Index, 4> v;
    const int dimension = spanning_points(kernel_, points_, order, v);
    if (dimension == 1) fail("all points are collinear: a 3D triangulation needs 4 non-coplanar points");
    if (dimension == 2) fail("all points are coplanar: a 3D triangulation needs 4 non-coplanar points");
    if (kernel_.orient3d(v[0], v[1], v[2], v[3]) < 0) std::swap(v[0], v[1]);
    cells_.push_back({v, {1, 2, 3, 4}});
    for (int i = 0; i < 4; ++i) {
      // Replace vertex i by infinity and swap two others to keep the orientation.
      Cell inf{v, {}};
      inf.v[i] = kInfinite;
      inf.n[i] = 0;
      std::swap(inf.v[(i + 1) % 4], inf.v[(i + 2) % 4]);
      cells_.push_back(inf);
    }
    // Link infinite cells with each other: they share the facet holding
    // infinity and two vertices of the first cell.
    for (Index c = 1; c < 5; ++c)
      for (int k2 = 0; k2 < 4; ++k2) {
        if (cells_[c].v[k2] == kInfinite) continue;
        const Index missing = cells_[c].v[k2];  // the neighbour lacks this one
        for (Index o = 1; o < 5; ++o)
          if (o != c && index_of(o, missing) < 0) cells_[c].n[k2] = o;
      }
    return v;
  }

  int index_of(Index c, Index v) const {
    const auto& cv = cells_[c].v;
    for (int k = 0; k < 4; ++k)
      if (cv[k] == v) return k;
    return -1;
  }

  bool conflict(const Cell& cell, Index p) {
    const auto& v = cell.v;
    // kInfinite is the largest vertex id: one maximum tells a finite cell.
    if (std::max(std::max(v[0], v[1]), std::max(v[2], v[3])) == kInfinite) {
      const auto& f = kFacet[v[0] == kInfinite ? 0 : v[1] == kInfinite ? 1 : v[2] == kInfinite ? 2 : 3];
      return kernel_.hull_conflict(v[f[0]], v[f[1]], v[f[2]], p);
    }
    return kernel_.power_conflict(v, p);
  }

  // Visibility walk from `start` to a cell whose closure holds p (for a point
  // outside the hull: an infinite cell whose hull facet sees p).
  Index locate(Index p, Index start) {
    Index c = start, previous = kNone;
    for (;;) {
      const Cell& cell = cells_[c];
      const int inf = index_of(c, kInfinite);
      if (inf >= 0) {
        const auto& f = kFacet[inf];
        if (kernel_.orient3d(cell.v[f[0]], cell.v[f[1]], cell.v[f[2]], p) > 0) return c;
        previous = c, c = cell.n[inf];
        continue;
      }
      walk_rng_ ^= walk_rng_ << 13, walk_rng_ ^= walk_rng_ >> 17, walk_rng_ ^= walk_rng_ << 5;
      const int r = static_cast<int>(walk_rng_ & 3u);
      Index next = kNone;
      for (int j = 0; j < 4 && next == kNone; ++j) {
        const int i = (r + j) & 3;
        if (cell.n[i] == previous) continue;
        const auto& f = kFacet[i];
        if (kernel_.orient3d(cell.v[f[0]], cell.v[f[1]], cell.v[f[2]], p) < 0) next = cell.n[i];
      }
      if (next == kNone) return c;
      previous = c, c = next;
    }
  }

  // Inserts p; returns a live cell near p to start the next walk.
  Index insert(Index p, Index hint) {
    if (cell_mark_.size() < cells_.size()) cell_mark_.resize(cells_.size() * 2, 0);
    const Index start = locate(p, hint);
    stamp_ += 2;
    if (!conflict(cells_[start], p)) {
      t_.status_[input_[p]] = PointStatus::hidden;
      return start;
    }
    find_cavity(start, p);
    if (t_.weighted()) mark_cavity_vertices();
    const Index made = fill_cavity();
    if (t_.weighted()) hide_enclosed_vertices();
    return made;
  }

  void find_cavity(Index start, Index p) {
    conflict_.clear(), boundary_.clear(), stack_.clear();
    // Nothing here resizes the cells or their marks.
    const Cell* const cells = cells_.data();
    std::uint32_t* const mark = cell_mark_.data();
    const std::uint32_t in = stamp_, out = stamp_ + 1;
    mark[start] = in;
    stack_.push_back(start);
    while (!stack_.empty()) {
      const Index c = stack_.back();
      stack_.pop_back();
      conflict_.push_back(c);
      for (int i = 0; i < 4; ++i) {
        const Index n = cells[c].n[i];
        if (mark[n] == in) continue;
        if (mark[n] != out && conflict(cells[n], p)) {
          mark[n] = in;
          stack_.push_back(n);
          continue;
        }
        mark[n] = out;
        Facet f{cells[c].v, i, n, index_of_neighbor(n, c)};
        f.v[i] = p;
        boundary_.push_back(f);
      }
    }
  }

  int index_of_neighbor(Index c, Index n) const {
    const auto& cn = cells_[c].n;
    for (int k = 0; k < 4; ++k)
      if (cn[k] == n) return k;
    return -1;
  }

  // Replaces the conflict cells by p joined to each boundary facet: the
  // free cells first (last freed first), then new ids in increasing order.
  Index fill_cavity() {
    for (Index c : conflict_) free_cells_.push_back(c);
    Index next_new = static_cast<Index>(cells_.size());
    if (boundary_.size() > free_cells_.size()) {
      const std::size_t size = cells_.size() + boundary_.size() - free_cells_.size();
      // Cell ids are 32-bit, kNone and kInfinite reserved (some 6e8 points).
      if (size > kInfinite) fail("too many cells for 32-bit cell ids", ErrorKind::LimitExceeded);
      cells_.resize(size);
      if (cell_mark_.size() < size) cell_mark_.resize(size * 2, 0);
    }
    const std::size_t slots = std::bit_ceil(4 * boundary_.size() + 16);
    if (edges_.size() < slots) edges_.assign(slots, EdgeSlot{0, 0, 0, 0});
    const std::size_t mask = edges_.size() - 1;
    Cell* const cells = cells_.data();
    std::uint32_t* const mark = cell_mark_.data();
    EdgeSlot* const edges = edges_.data();
    const std::uint32_t stamp = stamp_;
    Index made = kNone;
    for (const Facet& f : boundary_) {
      Index c;
      if (!free_cells_.empty()) {
        c = free_cells_.back();
        free_cells_.pop_back();
      } else {
        c = next_new++;
      }
      mark[c] = 0;
      Cell& cell = cells[c];
      cell.v = f.v;
      cell.n[f.i] = f.outside;
      cells[f.outside].n[f.mirror] = c;
      // The other three facets contain p and one edge of the boundary facet;
      // the cell sharing that edge is the neighbour.
      // Edges are keyed by direction (no unpredictable min/max), hashed
      // symmetrically: a looks for the b -> a its neighbour left, in the same chain.
      for (const auto& [j, ka, kb] : kSideFacets[f.i]) {
        const Index a = f.v[ka], b = f.v[kb];
        const std::uint64_t wanted = std::uint64_t(b) << 32 | a;
        std::size_t h = ((std::uint64_t(a) + b) * 0x9e3779b97f4a7c15ull) >> 40 & mask;
        while (edges[h].stamp == stamp && edges[h].key != wanted) h = (h + 1) & mask;
        EdgeSlot& slot = edges[h];
        if (slot.stamp == stamp) {
          cell.n[j] = slot.cell;
          cells[slot.cell].n[slot.facet] = c;
          slot.key = kUsedEdge;  // each edge is shared by exactly two new cells
        } else {
          slot = {std::uint64_t(a) << 32 | b, c, stamp, j};
        }
      }
      made = c;
    }
    return made;
  }

  // Weighted points only: a vertex of the conflict cells that no boundary
  // facet keeps lies inside the cavity, and the new point hides it.
  void mark_cavity_vertices() {
    if (vertex_mark_.size() < points_.size()) vertex_mark_.assign(points_.size(), 0);
    cavity_vertices_.clear();
    for (Index c : conflict_)
      for (Index v : cells_[c].v)
        if (v != kInfinite && vertex_mark_[v] != stamp_) vertex_mark_[v] = stamp_, cavity_vertices_.push_back(v);
  }
  void hide_enclosed_vertices() {
    for (const Facet& f : boundary_)
      for (Index v : f.v)
        if (v != kInfinite) vertex_mark_[v] = stamp_ + 1;
    for (Index v : cavity_vertices_)
      if (vertex_mark_[v] == stamp_) t_.status_[input_[v]] = PointStatus::hidden;
  }

  // Drops unused cell slots, gives the vertices their input indices and
  // fills in counts and vertex-to-cell links.
  void finish() {
    std::vector<Index> remap(cells_.size(), 0);
    for (Index c : free_cells_) remap[c] = kNone;
    Index next = 0;
    for (Index c = 0; c < cells_.size(); ++c)
      if (remap[c] != kNone) remap[c] = next++;
    for (Index c = 0; c < cells_.size(); ++c) {
      if (remap[c] == kNone) continue;
      Cell cell = cells_[c];
      for (Index& n : cell.n) n = remap[n];
      for (Index& v : cell.v)
        if (v != kInfinite) v = input_[v];
      cells_[remap[c]] = cell;
    }
    cells_.resize(next);
    t_.vertex_cell_.assign(t_.points_.size(), kNone);
    for (Index c = 0; c < cells_.size(); ++c) {
      bool finite = true;
      for (Index v : cells_[c].v) {
        if (v == kInfinite) finite = false;
        else t_.vertex_cell_[v] = c;
      }
      t_.num_finite_cells_ += finite;
    }
    for (PointStatus s : t_.status_) {
      t_.num_hidden_ += s == PointStatus::hidden;
      t_.num_vertices_ += s == PointStatus::vertex;
    }
    t_.stats_ = kernel_.stats();
  }
};

Triangulation::Triangulation(std::vector<Vec3> points, std::vector<double> weights)
    : points_(std::move(points)), weights_(std::move(weights)) {
  check_input(points_, weights_);
  Builder(*this).run();
}

std::size_t Triangulation::memory_bytes() const {
  return points_.capacity() * sizeof(Vec3) + weights_.capacity() * sizeof(double) +
         status_.capacity() * sizeof(PointStatus) + representative_.capacity() * sizeof(Index) +
         cells_.capacity() * sizeof(Cell) + vertex_cell_.capacity() * sizeof(Index);
}

}  // namespace alpha
