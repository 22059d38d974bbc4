// SPDX-License-Identifier: Apache-2.0
// Dynamic update of a regular triangulation (docs/dynamic_update.md).
//
// The regular triangulation of the perturbed points is unique, so any
// repair that ends locally regular everywhere, with every point that is no
// vertex non-conflicting, is the fresh build's. A move: (1) with the new
// values, check the cells that hold a moved vertex (orientation, local
// regularity, hull convexity); (2) give the moved vertices of what fails
// their old values back, and of what then fails around them, until the
// cells are regular for these mixed values; (3) take those vertices out
// (with the mixed values, which are the new ones for every vertex left);
// (4) insert them at their new places with the construction's own
// insertion, and test every hidden point again. Taking a vertex out
// retriangulates its star from the regular triangulation of the star's
// boundary vertices (and, on removal, the hidden points nearby), with the
// same predicates and perturbation (indices in the same order). Whatever
// this cannot do locally (duplicates made or split, a star no 3D
// triangulation fills, more than 1/8 of the points to take out: then a
// rebuild costs less) is built afresh: slower, never different.
#include <algorithm>
#include <bit>
#include <numeric>
#include <optional>

#include "alpha/error.hpp"
#include "alpha/spatial_sort.hpp"
#include "alpha/triangulation.hpp"
#include "triangulation_input.hpp"

namespace alpha {
namespace {

// Whether a point of `moved` has the coordinates of another point (a fresh
// build would merge them as duplicates). Open addressing on the moved ones.
bool coincide(const std::vector<Vec3>& points, const std::vector<Index>& moved, const std::vector<char>& is_moved) {
  const int bits = std::bit_width(2 * moved.size() + 1);
  const std::size_t mask = (std::size_t(1) << bits) - 1;
  const auto hash = [&](const Vec3& p) {
    std::uint64_t h = std::bit_cast<std::uint64_t>(p.x + 0.0);  // -0.0 as 0.0
    h = (h ^ std::bit_cast<std::uint64_t>(p.y + 0.0)) * 0x9e3779b97f4a7c15ull;
    h = (h ^ std::bit_cast<std::uint64_t>(p.z + 0.0)) * 0xbf58476d1ce4e5b9ull;
    return std::size_t(h >> (64 - bits));
  };
  std::vector<Index> table(mask + 1, kNone);
  for (Index i : moved) {
    std::size_t h = hash(points[i]);
    for (; table[h] != kNone; h = (h + 1) & mask)
      if (points[table[h]] == points[i]) return true;
    table[h] = i;
  }
  for (Index i = 0; i < points.size(); ++i) {
    if (is_moved[i]) continue;
    for (std::size_t h = hash(points[i]); table[h] != kNone; h = (h + 1) & mask)
      if (points[table[h]] == points[i]) return true;
  }
  return false;
}

// A facet as three vertex ids rotated to put the smallest first: the same
// key for the same oriented facet, another for the facet seen from behind.
using FacetKey = std::array<Index, 3>;
FacetKey facet_key(Index a, Index b, Index c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

}  // namespace

class Triangulation::Updater {
public:
  // before / before_weights: the values the cells are regular for; the
  // triangulation already holds the new ones.
  Updater(Triangulation& t, std::vector<Vec3> before, std::vector<double> before_weights)
      : t_(t), before_(std::move(before)), before_w_(std::move(before_weights)) {}

  // Repairs after the points `moved` changed; false when it cannot be done
  // locally (the cells are then unusable: the caller builds afresh).
  bool move(const std::vector<Index>& moved) {
    const std::size_t n = t_.points_.size();
    is_moved_.assign(n, 0);
    for (Index i : moved) is_moved_[i] = 1;
    if (involves_duplicates(moved) || coincide(t_.points_, moved, is_moved_)) return false;
    removed_.assign(n, 0);
    reverted_.assign(n, 0);
    cell_stamp_.assign(t_.cells_.size(), 0);
    // (1) With the new values, check every cell holding a moved vertex (a
    // facet between two such cells from the one with the smaller id).
    const auto touched = [&](Index c) {
      for (Index v : t_.cells_[c].v)
        if (v != kInfinite && is_moved_[v]) return true;
      return false;
    };
    Kernel now = t_.kernel();
    for (Index c = 0; c < t_.cells_.size(); ++c)
      if (touched(c)) check(now, c, [&](Index other) { return other < c || !touched(other); });
    // Beyond this share, taking out and inserting costs more than a rebuild.
    if (pending_.size() > n / kMaxShare) return false;
    // (2) The moved vertices of what failed go back to their old values,
    // and so do those of what then fails around them: the cells are
    // regular for these mixed values.
    at_ = t_.points_, at_w_ = t_.weights_;
    Kernel mixed(at_.data(), at_w_.empty() ? nullptr : at_w_.data());
    std::vector<Index> star;
    for (std::size_t k = 0; k < pending_.size(); ++k) {
      const Index u = pending_[k];
      at_[u] = before_[u];
      if (!at_w_.empty()) at_w_[u] = before_w_[u];
      reverted_[u] = 1;
      star_of(u, star);
      for (Index c : star) check(mixed, c, [](Index) { return true; });
    }
    if (stuck_ || pending_.size() > n / kMaxShare) return false;
    // (3) Taking them out leaves the regular triangulation of the other
    // vertices at their new values; (4) they go in at their new places, and
    // every hidden point is tested again.
    for (Index v : pending_)
      if (!take_out(v)) return false;
    std::vector<Index> again;
    for (Index i = 0; i < n; ++i)
      if (removed_[i] || t_.status_[i] == PointStatus::hidden) again.push_back(i);
    return reinsert(std::move(again));
  }

  // Takes the vertices `ids` out for good (hidden ones have nothing to do);
  // false when it cannot be done locally.
  bool remove(const std::vector<Index>& ids) {
    const std::size_t n = t_.points_.size();
    is_moved_.assign(n, 0);
    if (involves_duplicates(ids)) return false;
    removed_.assign(n, 0);
    cell_stamp_.assign(t_.cells_.size(), 0);
    at_ = before_, at_w_ = before_w_;
    for (Index i : ids) removed_[i] = 1;  // before hidden_: none of them comes back
    for (Index i = 0; i < n; ++i)
      if (t_.status_[i] == PointStatus::hidden && !removed_[i]) hidden_.push_back(i);
    for (Index v : ids)
      if (t_.status_[v] == PointStatus::vertex && !take_out(v)) return false;
    for (Index v : ids) t_.status_[v] = PointStatus::hidden;
    return true;
  }

  // Inserts points appended to the triangulation.
  bool insert(Index first) {
    const std::size_t n = t_.points_.size();
    is_moved_.assign(n, 0);
    std::vector<Index> added(n - first);
    std::iota(added.begin(), added.end(), first);
    for (Index i : added) is_moved_[i] = 1;
    if (coincide(t_.points_, added, is_moved_)) return false;
    removed_.assign(n, 0);
    return reinsert(std::move(added));
  }

  std::size_t relocated() const { return relocated_; }
  std::size_t reinserted() const { return reinserted_; }
  std::vector<Index> take_free_cells() { return std::move(free_); }

private:
  static constexpr std::uint32_t kDead = ~0u;
  static constexpr std::size_t kMaxShare = 8;  // of the points taken out and inserted, at most 1/kMaxShare
  Triangulation& t_;
  std::vector<Vec3> before_;
  std::vector<double> before_w_;
  std::vector<Vec3> at_;  // the values the cells are regular for, which take_out uses
  std::vector<double> at_w_;
  bool stuck_ = false;  // a failing cell without a moved vertex: cannot happen, yet never left as is
  std::vector<char> is_moved_, removed_, reverted_, pending_mark_;
  std::vector<Index> hidden_, pending_, free_;
  std::vector<std::uint32_t> cell_stamp_;  // kDead, else the last take_out that saw it
  std::uint32_t stamp_ = 0;
  std::size_t relocated_ = 0, reinserted_ = 0;

  // Whether a point of ids is a duplicate or represents one.
  bool involves_duplicates(const std::vector<Index>& ids) const {
    if (t_.num_duplicates_ == 0) return false;
    std::vector<char> grouped(t_.points_.size(), 0);
    for (Index i = 0; i < t_.points_.size(); ++i)
      if (t_.status_[i] == PointStatus::duplicate) grouped[i] = grouped[t_.representative_[i]] = 1;
    return std::any_of(ids.begin(), ids.end(), [&](Index i) { return grouped[i]; });
  }

  // Checks cell c with the new values: orientation, and the facets toward
  // the neighbours `other(n)` accepts. The moved vertices of what fails
  // are taken out next.
  template <class Other>
  void check(Kernel& kernel, Index c, Other other) {
    const Cell& cell = t_.cells_[c];
    const int inf = t_.infinite_position(c);
    bool bad = inf < 0 && kernel.orient3d(cell.v[0], cell.v[1], cell.v[2], cell.v[3]) <= 0;
    if (bad) take_moved(cell.v, kInfinite);
    for (int i = 0; i < 4; ++i) {
      const Index nb = cell.n[i];
      if (!other(nb)) continue;
      const Index far = t_.cells_[nb].v[t_.mirror_index(c, i)];
      if (far == kInfinite) continue;
      const bool conflict = inf >= 0 ? kernel.hull_conflict(cell.v[kFacet[inf][0]], cell.v[kFacet[inf][1]],
                                                          cell.v[kFacet[inf][2]], far)
                                     : kernel.power_conflict(cell.v, far);
      if (conflict) take_moved(cell.v, far);
    }
  }
  void take_moved(const std::array<Index, 4>& v, Index far) {
    if (pending_mark_.empty()) pending_mark_.assign(t_.points_.size(), 0);
    bool any = false;  // a moved vertex still at its new values
    for (Index u : {v[0], v[1], v[2], v[3], far})
      if (u != kInfinite && is_moved_[u]) {
        any |= !reverted_[u];
        if (!pending_mark_[u]) pending_mark_[u] = 1, pending_.push_back(u);
      }
    stuck_ |= !any;
  }

  // The cells holding vertex v.
  void star_of(Index v, std::vector<Index>& star) {
    ++stamp_;
    star.assign(1, t_.vertex_cell_[v]);
    cell_stamp_[star[0]] = stamp_;
    for (std::size_t k = 0; k < star.size(); ++k)
      for (Index nb : t_.cells_[star[k]].n)
        if (cell_stamp_[nb] != stamp_ && t_.index_of(nb, v) >= 0) cell_stamp_[nb] = stamp_, star.push_back(nb);
  }

  // Takes vertex v out with the values at_: its star becomes the cells of
  // the regular triangulation of the star's boundary vertices (and the
  // hidden points within their box) that lie inside the star. Cells of
  // Reg(P \ v) inside the star are empty for any subset of P \ v holding
  // their vertices, so they are cells of that triangulation too.
  bool take_out(Index v) {
    auto& cells = t_.cells_;
    std::vector<Index> star;
    star_of(v, star);
    // The boundary facets, as the star sees them (v on their positive side).
    struct Boundary {
      FacetKey key;
      Index outside;
      int mirror;
      Index cell = kNone;  // the sub-triangulation's cell on v's side
      int facet = 0;
    };
    std::vector<Boundary> boundary;
    std::vector<Index> ids;  // the sub-triangulation's points, as input ids
    for (Index c : star) {
      const int iv = t_.index_of(c, v);
      const auto& f = kFacet[iv];
      const auto& cv = cells[c].v;
      boundary.push_back({facet_key(cv[f[0]], cv[f[1]], cv[f[2]]), cells[c].n[iv], t_.mirror_index(c, iv)});
      for (int k : f)
        if (cv[k] != kInfinite) ids.push_back(cv[k]);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    Vec3 lo = at_[v], hi = lo;
    for (Index i : ids) {
      const Vec3& p = at_[i];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    for (Index h : hidden_) {
      const Vec3& p = at_[h];
      if (!removed_[h] && t_.status_[h] == PointStatus::hidden && p.x >= lo.x && p.x <= hi.x && p.y >= lo.y &&
          p.y <= hi.y && p.z >= lo.z && p.z <= hi.z)
        ids.push_back(h);
    }
    std::optional<Triangulation> sub = regular_of(ids);
    if (!sub) {  // coplanar or too few (a hull vertex's star): add the vertices beyond its boundary
      for (const Boundary& b : boundary)
        if (const Index far = cells[b.outside].v[b.mirror]; far != kInfinite) ids.push_back(far);
      sub = regular_of(ids);
      if (!sub) return false;
    }
    const auto global = [&](Index x) { return x == kInfinite ? kInfinite : ids[x]; };
    {
      // Match each boundary facet with the sub cell on v's side.
      std::sort(boundary.begin(), boundary.end(), [](const Boundary& a, const Boundary& b) { return a.key < b.key; });
      std::vector<std::uint8_t> walls(sub->num_cells(), 0);  // bit k: facet k is a boundary facet
      for (Index s = 0; s < sub->num_cells(); ++s)
        for (int k = 0; k < 4; ++k) {
          const auto& sv = sub->cell(s).v;
          const auto& f = kFacet[k];
          const FacetKey key = facet_key(global(sv[f[0]]), global(sv[f[1]]), global(sv[f[2]]));
          const auto it = std::lower_bound(boundary.begin(), boundary.end(), key,
                                           [](const Boundary& b, const FacetKey& k) { return b.key < k; });
          if (it == boundary.end() || it->key != key) continue;
          it->cell = s, it->facet = k;
          walls[s] |= std::uint8_t(1u << k);
        }
      // The sub cells inside the star: from the boundary, never across it.
      std::vector<Index> inside, number(sub->num_cells(), kNone);
      for (const Boundary& b : boundary) {
        if (b.cell == kNone) return false;
        if (number[b.cell] == kNone) number[b.cell] = 0, inside.push_back(b.cell);
      }
      for (std::size_t k = 0; k < inside.size(); ++k)
        for (int i = 0; i < 4; ++i) {
          const Index s = sub->cell(inside[k]).n[i];
          if (!(walls[inside[k]] >> i & 1) && number[s] == kNone) number[s] = 0, inside.push_back(s);
        }
      // Cell ids: the star's first, then unused ones, then new ones.
      for (Index c : star) cell_stamp_[c] = kDead, free_.push_back(c);
      for (Index s : inside) {
        Index c;
        if (!free_.empty()) {
          c = free_.back();
          free_.pop_back();
        } else {
          c = Index(cells.size());
          cells.push_back({});
          cell_stamp_.push_back(0);
        }
        cell_stamp_[c] = 0;
        number[s] = c;
      }
      for (Index s : inside) {
        Cell& cell = cells[number[s]];
        for (int k = 0; k < 4; ++k) {
          cell.v[k] = global(sub->cell(s).v[k]);
          cell.n[k] = number[sub->cell(s).n[k]];  // kNone across the boundary, set below
        }
        for (Index u : cell.v)
          if (u != kInfinite) t_.vertex_cell_[u] = number[s], t_.status_[u] = PointStatus::vertex;
      }
      for (const Boundary& b : boundary) {
        cells[number[b.cell]].n[b.facet] = b.outside;
        cells[b.outside].n[b.mirror] = number[b.cell];
      }
    }
    removed_[v] = 1;
    t_.status_[v] = PointStatus::hidden;
    t_.vertex_cell_[v] = kNone;
    ++relocated_;
    return true;
  }

  // The regular triangulation of the points ids (with the old values), ids
  // sorted and unique: in increasing input order the perturbation orders
  // them as in the whole set. None when they span no 3D triangulation.
  std::optional<Triangulation> regular_of(std::vector<Index>& ids) const {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<Vec3> pts(ids.size());
    std::vector<double> ws(at_w_.empty() ? 0 : ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) {
      pts[k] = at_[ids[k]];
      if (!ws.empty()) ws[k] = at_w_[ids[k]];
    }
    try {
      return Triangulation(std::move(pts), std::move(ws));
    } catch (const Error&) {
      return std::nullopt;
    }
  }

  // Inserts `points` at their current values, in spatial order.
  bool reinsert(std::vector<Index> points) {
    Index hint = kNone;
    for (Index u = 0; u < t_.points_.size() && hint == kNone; ++u)
      if (t_.status_[u] == PointStatus::vertex && !removed_[u]) hint = t_.vertex_cell_[u];
    if (hint == kNone) return false;
    const std::vector<Index> order = brio_order(t_.points_, std::move(points));
    for (Index p : order) t_.status_[p] = PointStatus::vertex;
    reinserted_ = order.size();
    t_.insert_into(order, std::move(free_), hint);
    return true;
  }
};

namespace {

// The whole point set's values after the update, checked as the constructor checks them.
void check_weights_given(bool weighted, std::size_t points, std::size_t weights) {
  if (weights != (weighted ? points : 0))
    fail("got " + std::to_string(weights) + " weights for " + std::to_string(points) + " points of " +
             (weighted ? "a weighted" : "an unweighted") + " triangulation",
         ErrorKind::Misuse);
}

}  // namespace

UpdateReport Triangulation::move_points(std::span<const Index> ids, std::span<const Vec3> to,
                                        std::span<const double> weights) {
  if (ids.size() != to.size())
    fail("got " + std::to_string(to.size()) + " positions for " + std::to_string(ids.size()) + " points",
         ErrorKind::Misuse);
  check_weights_given(weighted(), ids.size(), weights.size());
  std::vector<Vec3> points = points_;
  std::vector<double> w = weights_;
  std::vector<char> seen(points.size(), 0);
  std::vector<Index> moved;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Index i = ids[k];
    if (i >= points.size() || seen[i])
      fail("point id " + std::to_string(i) + " is out of range or given twice", ErrorKind::Misuse);
    seen[i] = 1;
    if (points[i] == to[k] && (w.empty() || w[i] == weights[k])) continue;
    points[i] = to[k];
    if (!w.empty()) w[i] = weights[k];
    moved.push_back(i);
  }
  check_input(points, w);
  UpdateReport report;
  if (moved.empty()) return report;
  std::swap(points, points_);
  std::swap(w, weights_);
  // points, w: the values before.
  Updater updater(*this, points, w);
  if (updater.move(moved)) {
    report.relocated = updater.relocated();
    report.reinserted = updater.reinserted();
    return report;
  }
  report.rebuilt = true;
  std::vector<Vec3> now = points_;
  std::vector<double> now_w = weights_;
  try {
    *this = Triangulation(std::move(now), std::move(now_w));
  } catch (const Error&) {
    *this = Triangulation(std::move(points), std::move(w));  // as it was
    throw;
  }
  return report;
}

UpdateReport Triangulation::move_points(std::span<const Vec3> to, std::span<const double> weights) {
  if (to.size() != points_.size())
    fail("got " + std::to_string(to.size()) + " positions for " + std::to_string(points_.size()) + " points",
         ErrorKind::Misuse);
  std::vector<Index> ids(to.size());
  std::iota(ids.begin(), ids.end(), Index(0));
  return move_points(ids, to, weights);
}

UpdateReport Triangulation::insert_points(std::span<const Vec3> points, std::span<const double> weights) {
  check_weights_given(weighted(), points.size(), weights.size());
  std::vector<Vec3> all = points_;
  all.insert(all.end(), points.begin(), points.end());
  std::vector<double> w = weights_;
  w.insert(w.end(), weights.begin(), weights.end());
  check_input(all, w);
  UpdateReport report;
  if (points.empty()) return report;
  const Index first = Index(points_.size());
  const std::vector<Vec3> before = points_;
  const std::vector<double> before_w = weights_;
  points_ = all, weights_ = w;
  status_.resize(all.size(), PointStatus::vertex);
  representative_.resize(all.size());
  std::iota(representative_.begin() + first, representative_.end(), first);
  vertex_cell_.resize(all.size(), kNone);
  Updater updater(*this, before, before_w);
  if (updater.insert(first)) {
    report.reinserted = updater.reinserted();
    return report;
  }
  report.rebuilt = true;
  *this = Triangulation(std::move(all), std::move(w));  // only duplicates fail locally: this cannot throw
  return report;
}

UpdateReport Triangulation::remove_points(std::span<const Index> ids) {
  const std::size_t n = points_.size();
  std::vector<char> leaves(n, 0);
  std::vector<Index> gone;
  for (Index i : ids) {
    if (i >= n || leaves[i]) fail("point id " + std::to_string(i) + " is out of range or given twice", ErrorKind::Misuse);
    leaves[i] = 1;
    gone.push_back(i);
  }
  // The others' new ids close the gaps.
  std::vector<Index> renumber(n, kNone);
  std::vector<Vec3> rest;
  std::vector<double> rest_w;
  for (Index i = 0; i < n; ++i)
    if (!leaves[i]) {
      renumber[i] = Index(rest.size());
      rest.push_back(points_[i]);
      if (weighted()) rest_w.push_back(weights_[i]);
    }
  UpdateReport report;
  if (gone.empty()) return report;
  std::vector<Vec3> before = points_;
  std::vector<double> before_w = weights_;
  Updater updater(*this, points_, weights_);
  if (!updater.remove(gone)) {
    report.rebuilt = true;
    try {
      *this = Triangulation(std::move(rest), std::move(rest_w));
    } catch (const Error&) {
      *this = Triangulation(std::move(before), std::move(before_w));  // as it was
      throw;
    }
    return report;
  }
  report.relocated = updater.relocated();
  std::vector<Index> free_cells = updater.take_free_cells();
  std::vector<char> dead(cells_.size(), 0);
  for (Index c : free_cells) dead[c] = 1;
  for (Index c = 0; c < cells_.size(); ++c)
    if (!dead[c])
      for (Index& v : cells_[c].v)
        if (v != kInfinite) v = renumber[v];
  std::vector<PointStatus> status;
  std::vector<Index> representative;
  for (Index i = 0; i < n; ++i)
    if (!leaves[i]) status.push_back(status_[i]), representative.push_back(renumber[representative_[i]]);
  points_ = std::move(rest), weights_ = std::move(rest_w);
  status_ = std::move(status), representative_ = std::move(representative);
  vertex_cell_.assign(points_.size(), kNone);
  Index hint = kNone;
  for (Index c = 0; c < cells_.size() && hint == kNone; ++c)
    if (!dead[c]) hint = c;
  insert_into({}, std::move(free_cells), hint);  // compacts the cells, counts again
  return report;
}

}  // namespace alpha
