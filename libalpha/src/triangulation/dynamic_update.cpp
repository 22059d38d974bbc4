// SPDX-License-Identifier: Apache-2.0
// Dynamic update of a regular triangulation (docs/dynamic_update.md).
//
// The regular triangulation of the perturbed points is unique, so any
// repair that ends locally regular everywhere, with every point that is no
// vertex non-conflicting, is the fresh build's. A move: (1) with the new
// values, check the cells that hold a moved vertex (orientation, local
// regularity, hull convexity); (2) give a moved vertex of each failing one
// its old values back, until nothing fails with these mixed values, except
// a facet between two positive finite cells: that is flipped (2-3, 3-2, or
// 4-1 where a weighted vertex becomes redundant) until all are regular; (3)
// take the reverted vertices out (with the mixed values, the new ones for
// every vertex left): the cells holding them, each part of that region on
// its own, are refilled from the regular triangulation of their other
// vertices (and, on removal, the hidden points nearby), with
// the same predicates and perturbation (indices in the same order); (4)
// insert them at their new places with the construction's own insertion,
// and test every hidden point again. Whatever this cannot do locally
// (duplicates made or split, a region no 3D triangulation fills, a facet
// no flip mends, more than 1/16 of the points sent back, or a sample of the
// cells to check failing so often that a rebuild costs less) is built
// afresh: slower, never different.
#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <optional>

#include "alpha/error.hpp"
#include "alpha/spatial_sort.hpp"
#include "alpha/triangulation.hpp"
#include "triangulation/triangulation_input.hpp"
#include "util/huge_pages.hpp"

namespace alpha {
namespace {

// Whether a point of `moved` has the coordinates of another one of them or
// of a point of `others`. Open addressing on the moved ones.
bool coincide_with(const std::vector<Vec3>& points, const std::vector<Index>& moved, const std::vector<Index>& others) {
  const int bits = std::bit_width(2 * moved.size() + 1);
  const std::size_t mask = (std::size_t(1) << bits) - 1;
  const auto hash = [&](const Vec3& p) {
    std::uint64_t h = std::bit_cast<std::uint64_t>(p.x + 0.0);  // -0.0 as 0.0
    h = (h ^ std::bit_cast<std::uint64_t>(p.y + 0.0)) * 0x9e3779b97f4a7c15ull;
    return (h ^ std::bit_cast<std::uint64_t>(p.z + 0.0)) * 0xbf58476d1ce4e5b9ull;
  };
  // Each slot keeps its point's full hash: most probes end without reading the point.
  struct Slot {
    std::uint64_t key;
    Index point = kNone;
  };
  std::vector<Slot> table(mask + 1);
  for (Index i : moved) {
    const std::uint64_t key = hash(points[i]);
    std::size_t h = key >> (64 - bits);
    for (; table[h].point != kNone; h = (h + 1) & mask)
      if (table[h].key == key && points[table[h].point] == points[i]) return true;
    table[h] = {key, i};
  }
  for (Index i : others) {
    const std::uint64_t key = hash(points[i]);
    for (std::size_t h = key >> (64 - bits); table[h].point != kNone; h = (h + 1) & mask)
      if (table[h].key == key && points[table[h].point] == points[i]) return true;
  }
  return false;
}

// Whether a point of `moved` has the coordinates of another point (a fresh
// build would merge them as duplicates).
bool coincide_any(const std::vector<Vec3>& points, const std::vector<Index>& moved, const std::vector<char>& is_moved) {
  std::vector<Index> others;
  for (Index i = 0; i < points.size(); ++i)
    if (!is_moved[i]) others.push_back(i);
  return coincide_with(points, moved, others);
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
  explicit Updater(Triangulation& t) : t_(t) {}

  // Repairs after the points `moved` changed (the triangulation holds their
  // new values; `old_points` and `old_weights`, in the same order, the ones
  // the cells are regular for); false when it cannot be done locally (the
  // cells are then unusable: the caller builds afresh, from the new values).
  bool move(const std::vector<Index>& moved, std::vector<Vec3> old_points, std::vector<double> old_weights) {
    const std::size_t n = t_.points_.size();
    assign_huge(is_moved_, n, char(0));
    for (Index i : moved) is_moved_[i] = 1;
    old_p_ = std::move(old_points), old_w_ = std::move(old_weights);
    new_p_.resize(moved.size()), new_w_.resize(old_w_.size());
    assign_huge(slot_, n, kNone);
    for (std::size_t k = 0; k < moved.size(); ++k) {
      slot_[moved[k]] = Index(k), new_p_[k] = t_.points_[moved[k]];
      if (!new_w_.empty()) new_w_[k] = t_.weights_[moved[k]];
    }
    if (involves_duplicates(moved)) return false;
    // A failing facet between two positive finite cells is flipped; the
    // rest (inverted cells, the hull) sends a moved vertex back. Beyond
    // kMaxShare of the points sent back, taking them out and inserting
    // them costs more than a rebuild: stop as soon as that is passed (a
    // few always go: on a small set either costs little).
    limit_ = std::max(n / kMaxShare, kMinLimit);
    assign_huge(removed_, n, char(0));
    assign_huge(reverted_, n, char(0));
    assign_huge(cell_stamp_, t_.cells_.size(), std::uint32_t(0));
    Kernel now = t_.kernel();  // reads the values as they change (mixed from step 2 on)
    list_cells(moved);
    foretold_ = too_far(now);
    if (foretold_ || coincide(moved)) return false;
    const bool mended = mend(now);
    for (Index u : pending_) values(u, new_p_, new_w_);  // the vertices sent back: their new values again
    if (!mended) return false;
    // (4) The vertices taken out go in at their new places, and every
    // hidden point is tested again.
    std::vector<Index> again;
    for (Index i = 0; i < n; ++i)
      if (removed_[i] || t_.status_[i] == PointStatus::hidden) again.push_back(i);
    return reinsert(std::move(again));
  }

  // The cells step (1) checks: those holding a moved vertex, in memory
  // order. From 1/kStarShare of the points moved, every cell is read and
  // tested for one (every_: a scan in memory order costs less than
  // walking the stars, 1e6 points, 10 % moved: 1.5 s instead of 2.8 s);
  // else the stars of the moved vertices are listed.
  void list_cells(const std::vector<Index>& moved) {
    all_ = moved.size() == t_.points_.size();
    every_ = moved.size() * kStarShare >= t_.points_.size();
    to_check_.clear();
    if (every_) return;
    std::vector<char> seen;
    assign_huge(seen, t_.cells_.size(), char(0));
    std::vector<Index> star;
    for (Index u : moved) {
      if (t_.status_[u] != PointStatus::vertex) continue;
      star_of(u, star);
      for (Index c : star)
        if (!seen[c]) seen[c] = 1, to_check_.push_back(c);
    }
    std::sort(to_check_.begin(), to_check_.end());
  }
  std::size_t to_check() const { return every_ ? t_.cells_.size() : to_check_.size(); }
  Index to_check(std::size_t k) const { return every_ ? Index(k) : to_check_[k]; }

  bool touched(Index c) const {
    if (all_) return true;
    for (Index v : t_.cells_[c].v)
      if (v != kInfinite && is_moved_[v]) return true;
    return false;
  }
  // Step (1)'s check of cell c: a facet between two cells that hold a
  // moved vertex is checked from the one with the smaller id.
  void check_first(Kernel& kernel, Index c) {
    if (touched(c)) check(kernel, c, [&](Index other) { return other < c || !touched(other); });
  }

  // Whether a sample of the cells to check (1/kSampleStride of them, at
  // least kMinSample and at most kSample, evenly spread) foretells more failures (facets to flip, cells sent back) than
  // kRebuildRate of the cells: mending would cost more than building
  // (bench_dynamic_update: from about 0.08 NN when every point moves).
  // Fewer than kMinSample cells to check are not judged. What the sample
  // found stays queued, and the pass finds it again, harmlessly.
  bool too_far(Kernel& kernel) {
    const std::size_t count = to_check();
    if (count < kMinSample) return false;
    const std::size_t stride = count / std::clamp(count / kSampleStride, kMinSample, kSample);
    std::size_t sampled = 0;
    for (std::size_t k = stride / 2; k < count && pending_.size() <= limit_; k += stride)
      check_first(kernel, to_check(k)), ++sampled;
    const double failing = double(flip_queue_.size() + pending_.size());
    return pending_.size() > limit_ ||
           failing * double(count) > kRebuildRate * double(sampled) * double(t_.cells_.size());
  }

  // Steps (1) to (3) of a move: the moved vertices sent back are out, the
  // others in place at their new values.
  bool mend(Kernel& now) {
    // (1) With the new values, check every cell holding a moved vertex.
    for (std::size_t k = 0; k < to_check() && pending_.size() <= limit_; ++k) check_first(now, to_check(k));
    if (pending_.size() > limit_) return false;
    // (2) The moved vertices of what failed go back to their old values,
    // and so do those of what then fails around them, and the failing
    // facets between positive cells are flipped; where no flip mends one
    // (yet), a moved vertex of it goes back too, and so on: the cells are
    // then regular for these mixed values.
    Kernel& mixed = now;
    std::vector<Index> star;
    for (std::size_t k = 0;;) {
      for (; k < pending_.size() && pending_.size() <= limit_; ++k) {
        const Index u = pending_[k];
        values(u, old_p_, old_w_);
        reverted_[u] = 1;
        if (t_.status_[u] != PointStatus::vertex) continue;  // hidden by a 4-1 flip: in no cell
        star_of(u, star);
        for (Index c : star) check(mixed, c, [](Index) { return true; });
      }
      if (stuck_ || pending_.size() > limit_) return false;
      if (flip_all(mixed)) {
        if (!retry(mixed)) break;
        k = pending_.size();
        continue;
      }
      const std::size_t sent = pending_.size();
      std::vector<Queued> unflipped;
      unflipped.swap(flip_queue_);
      for (const Queued& q : unflipped) {
        const Index c = q.cell;
        const Cell& cell = t_.cells_[c];
        for (int i = 0; i < 4; ++i) {
          const Index far = t_.cells_[cell.n[i]].v[t_.mirror_index(c, i)];
          if (far != kInfinite && mixed.power_conflict(cell.v, far)) take_moved(cell.v, far);
        }
      }
      if (stuck_ || pending_.size() == sent) return false;
    }
    for (Index u : retried_) returned_ += !(pending_mark_[u] & kPending);
    // (3) Taking them out leaves the regular triangulation of the other
    // vertices at their new values.
    return take_out(pending_);
  }

  // Each vertex sent back goes to its new values again, alone and at most
  // kRetries times, where the cells around it stay positive (and the hull convex) there:
  // most were sent back for a cell that other moves or flips have since
  // mended, and flips cost far less than taking out and inserting. Its
  // star is checked as in step 2; what fails then is mended the same way.
  // Whether one went.
  bool retry(Kernel& mixed) {
    std::vector<Index> star, still;
    bool any = false;
    for (Index u : pending_) {
      if (pending_mark_[u] / kRetried >= kRetries || t_.status_[u] != PointStatus::vertex) {
        still.push_back(u);
        continue;
      }
      if (pending_mark_[u] < kRetried) retried_.push_back(u);
      pending_mark_[u] += kRetried;
      values(u, new_p_, new_w_);
      star_of(u, star);
      if (!fits(mixed, star)) {
        values(u, old_p_, old_w_);
        still.push_back(u);
        continue;
      }
      pending_mark_[u] &= ~kPending, reverted_[u] = 0, any = true;
      for (Index c : star) check(mixed, c, [](Index) { return true; });
    }
    pending_.swap(still);
    return any;
  }

  // Whether the cells `star` are positively oriented and, on the hull, convex.
  bool fits(Kernel& kernel, const std::vector<Index>& star) {
    for (Index c : star) {
      const Cell& cell = t_.cells_[c];
      const int inf = t_.infinite_position(c);
      if (inf < 0) {
        if (kernel.orient3d(cell.v[0], cell.v[1], cell.v[2], cell.v[3]) <= 0) return false;
        continue;
      }
      const auto& f = kFacet[inf];
      for (int i = 0; i < 4; ++i) {
        const Index far = t_.cells_[cell.n[i]].v[t_.mirror_index(c, i)];
        if (far != kInfinite && kernel.hull_conflict(cell.v[f[0]], cell.v[f[1]], cell.v[f[2]], far)) return false;
      }
    }
    return true;
  }

  // Takes the vertices `ids` out for good (hidden ones have nothing to do);
  // false when it cannot be done locally.
  bool remove(const std::vector<Index>& ids) {
    const std::size_t n = t_.points_.size();
    assign_huge(is_moved_, n, char(0));
    if (involves_duplicates(ids)) return false;
    assign_huge(removed_, n, char(0));
    assign_huge(cell_stamp_, t_.cells_.size(), std::uint32_t(0));
    for (Index i : ids) removed_[i] = 1;  // before hidden_: none of them comes back
    for (Index i = 0; i < n; ++i)
      if (t_.status_[i] == PointStatus::hidden && !removed_[i]) hidden_.push_back(i);
    std::vector<Index> vertices;
    for (Index v : ids)
      if (t_.status_[v] == PointStatus::vertex) vertices.push_back(v);
    if (!take_out(vertices)) return false;
    for (Index v : ids) t_.status_[v] = PointStatus::hidden;
    return true;
  }

  // Inserts points appended to the triangulation.
  bool insert(Index first) {
    const std::size_t n = t_.points_.size();
    assign_huge(is_moved_, n, char(0));
    std::vector<Index> added(n - first);
    std::iota(added.begin(), added.end(), first);
    for (Index i : added) is_moved_[i] = 1;
    if (coincide_any(t_.points_, added, is_moved_)) return false;
    assign_huge(removed_, n, char(0));
    return reinsert(std::move(added));
  }

  // What it did, into `report`.
  void tell(UpdateReport& report) const {
    report.relocated = relocated_, report.reinserted = reinserted_, report.returned = returned_;
    report.flips23 = flips23_, report.flips32 = flips32_, report.flips41 = flips41_;
  }
  std::vector<Index> take_free_cells() { return std::move(free_); }
  bool foretold() const { return foretold_; }

private:
  static constexpr std::uint32_t kDead = ~0u;
  static constexpr std::size_t kMaxShare = 16;  // of the points sent back (most return by flips), at most 1/kMaxShare
  static constexpr std::size_t kMinLimit = 64;   // or this many
  static constexpr std::size_t kStarShare = 64;  // from 1/kStarShare of the points moved, check all cells
  static constexpr std::size_t kSampleStride = 32, kMinSample = 128, kSample = 2048;  // the sample that may foretell a rebuild
  static constexpr double kRebuildRate = 1.0 / 6;  // failures per cell beyond which a rebuild costs less
  std::size_t limit_ = 0;
  Triangulation& t_;
  bool all_ = false, every_ = false;  // every point moved; most did (see list_cells)
  bool foretold_ = false;             // too_far said so
  std::vector<Index> to_check_;
  // The moved points' old and new values, and each one's place in them (kNone: not moved).
  std::vector<Index> slot_;
  std::vector<Vec3> old_p_, new_p_;
  std::vector<double> old_w_, new_w_;
  bool stuck_ = false;
  // A cell that may have a facet to flip; bit k of `regular`: facet k is
  // locally regular (made so by the flip that made the cell).
  struct Queued {
    Index cell;
    std::uint8_t regular;
  };
  std::vector<Queued> flip_queue_;
  std::vector<char> is_moved_, removed_, reverted_;
  // pending_mark_: bit 0 on the way back, above it the retries (at most kRetries).
  static constexpr char kPending = 1, kRetried = 2;
  static constexpr int kRetries = 2;
  std::vector<char> pending_mark_;
  std::vector<Index> hidden_, pending_, retried_, free_;
  std::vector<std::uint32_t> cell_stamp_;  // kDead, else the last take_out that saw it
  std::uint32_t stamp_ = 0;
  std::uint32_t walk_ = 0x9e3779b9u;  // locate's random choices
  std::size_t relocated_ = 0, reinserted_ = 0, returned_ = 0, flips23_ = 0, flips32_ = 0, flips41_ = 0;

  // Gives the moved point u its values in `p` and `w` (old or new).
  void values(Index u, const std::vector<Vec3>& p, const std::vector<double>& w) {
    t_.points_[u] = p[slot_[u]];
    if (!w.empty()) t_.weights_[u] = w[slot_[u]];
  }

  // Whether a moved point now has the coordinates of another point (a
  // fresh build would merge them as duplicates). Moved points against each
  // other and against the hidden ones by a hash of their coordinates; against
  // the vertices left in place by locating each new place among the old
  // values: a point at a vertex lies in the closure of a cell only if the
  // vertex is the cell's. When most points move, all by the hash.
  bool coincide(const std::vector<Index>& moved) {
    const auto& points = t_.points_;
    if (moved.size() * kStarShare >= points.size()) return coincide_any(points, moved, is_moved_);
    std::vector<Index> hidden;
    for (Index i = 0; i < points.size(); ++i)
      if (!is_moved_[i] && t_.status_[i] == PointStatus::hidden) hidden.push_back(i);
    if (coincide_with(points, moved, hidden)) return true;
    for (Index u : moved) values(u, old_p_, old_w_);
    bool found = false;
    Kernel old = t_.kernel();
    Index start = 0;  // the cells are compact: every id is a cell
    for (std::size_t k = 0; k < moved.size() && !found; ++k) {
      if (t_.status_[moved[k]] == PointStatus::vertex) start = t_.vertex_cell_[moved[k]];  // else from the last
      const Index c = locate(old, new_p_[k], start);
      if (c == kNone) continue;  // outside the hull: at no vertex
      for (Index v : t_.cells_[c].v)
        if (v != kInfinite && !is_moved_[v] && points[v] == new_p_[k]) found = true;
    }
    for (Index u : moved) values(u, new_p_, new_w_);
    return found;
  }

  // A visibility walk (randomised: it ends in a regular triangulation) from
  // cell `start` to a finite cell whose closure holds q; kNone when q lies
  // beyond the hull.
  Index locate(Kernel& kernel, const Vec3& q, Index start) {
    Index c = start, previous = kNone;
    for (;;) {
      const Cell& cell = t_.cells_[c];
      const auto at = [&](Index v) -> const Vec3& { return t_.points_[v]; };
      const int inf = t_.infinite_position(c);
      Index next = kNone;
      if (inf >= 0) {
        const auto& f = kFacet[inf];
        if (kernel.orient3d(at(cell.v[f[0]]), at(cell.v[f[1]]), at(cell.v[f[2]]), q) > 0) return kNone;
        next = cell.n[inf];
      } else {
        walk_ ^= walk_ << 13, walk_ ^= walk_ >> 17, walk_ ^= walk_ << 5;
        for (int j = 0; j < 4 && next == kNone; ++j) {
          const int i = int(walk_ + j) & 3;
          const auto& f = kFacet[i];
          if (cell.n[i] != previous && kernel.orient3d(at(cell.v[f[0]]), at(cell.v[f[1]]), at(cell.v[f[2]]), q) < 0)
            next = cell.n[i];
        }
        if (next == kNone) return c;
      }
      previous = c, c = next;
    }
  }

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
      if (!conflict) continue;
      if (inf < 0 && !bad) flip_queue_.push_back({c, 0});  // both cells finite: a flip may mend it
      else take_moved(cell.v, far);
    }
  }

  // Flips the facets that fail local regularity (with `kernel`'s values)
  // until none does: 2-3 where the two cells' union is convex, 3-2 around
  // an edge of degree 3. Each flip lowers the lifted surface, so this ends;
  // false when some facets flip no way (then the caller rebuilds).
  bool flip_all(Kernel& kernel) {
    std::vector<Queued> stuck;
    for (bool flipped = true; flipped;) {
      flipped = false;
      while (!flip_queue_.empty()) {
        const auto [c, regular] = flip_queue_.back();
        flip_queue_.pop_back();
        if (cell_stamp_[c] == kDead || t_.infinite_position(c) >= 0) continue;
        bool failing = false, done = false;
        for (int i = 0; i < 4 && !done; ++i) {
          if (regular >> i & 1) continue;
          const Index far = t_.cells_[t_.cells_[c].n[i]].v[t_.mirror_index(c, i)];
          if (far == kInfinite || !kernel.power_conflict(t_.cells_[c].v, far)) continue;
          failing = true;
          done = flip(kernel, c, i);
        }
        flipped |= done;
        if (failing && !done) stuck.push_back({c, 0});
      }
      flip_queue_.swap(stuck);  // again, once others have flipped
    }
    return flip_queue_.empty();
  }

  bool flip(Kernel& kernel, Index c, int i) {
    auto& cells = t_.cells_;
    const Index nb = cells[c].n[i], e = cells[nb].v[t_.mirror_index(c, i)];
    const auto& cv = cells[c].v;
    const Index a = cv[kFacet[i][0]], b = cv[kFacet[i][1]], cc = cv[kFacet[i][2]], d = cv[i];
    // Where the line de crosses the plane abc, against each edge (< 0: inside).
    const int s_ab = kernel.orient3d(a, b, d, e), s_bc = kernel.orient3d(b, cc, d, e), s_ca = kernel.orient3d(cc, a, d, e);
    if (s_ab < 0 && s_bc < 0 && s_ca < 0) {
      const Index old[] = {c, nb};
      const std::array<Index, 4> made[] = {{a, b, e, d}, {b, cc, e, d}, {cc, a, e, d}};
      ++flips23_;
      return replace(old, made);
    }
    // Outside across one edge xy only: the third cell xyde around it.
    Index x, y, z;
    if (s_ab > 0 && s_bc < 0 && s_ca < 0) x = a, y = b, z = cc;
    else if (s_bc > 0 && s_ab < 0 && s_ca < 0) x = b, y = cc, z = a;
    else if (s_ca > 0 && s_ab < 0 && s_bc < 0) x = cc, y = a, z = b;
    else if (s_ab > 0 && s_ca > 0 && s_bc < 0) return flip41(kernel, c, nb, a, b, cc, d, e);
    else if (s_ab > 0 && s_bc > 0 && s_ca < 0) return flip41(kernel, c, nb, b, cc, a, d, e);
    else if (s_bc > 0 && s_ca > 0 && s_ab < 0) return flip41(kernel, c, nb, cc, a, b, d, e);
    else return false;
    const Index third = cells[c].n[t_.index_of(c, z)];
    if (t_.index_of(third, e) < 0 || cells[nb].n[t_.index_of(nb, z)] != third) return false;  // degree above 3
    std::array<Index, 4> made[2];
    for (int k = 0; k < 2; ++k) {
      const Index w = k ? y : x;
      const int o = kernel.orient3d(z, d, e, w);
      if (o == 0) return false;
      made[k] = o > 0 ? std::array<Index, 4>{z, d, e, w} : std::array<Index, 4>{d, z, e, w};
    }
    const Index old[] = {c, nb, third};
    ++flips32_;
    return replace(old, made);
  }

  // The facet xyz between cells c = xyzd and nb = xyze, where the line de
  // passes beyond x: mended only when x has just the four cells xyzd, xyze,
  // xzde, xyde (weighted points: x's ball is then redundant), which become
  // the one cell yzde; x is hidden, and tested again with the hidden points.
  bool flip41(Kernel& kernel, Index c, Index nb, Index x, Index y, Index z, Index d, Index e) {
    if (!t_.weighted()) return false;  // unweighted points are never redundant
    auto& cells = t_.cells_;
    const Index across_y = cells[c].n[t_.index_of(c, y)], across_z = cells[c].n[t_.index_of(c, z)];
    if (t_.index_of(across_y, e) < 0 || t_.index_of(across_z, e) < 0 ||
        cells[nb].n[t_.index_of(nb, y)] != across_y || cells[nb].n[t_.index_of(nb, z)] != across_z)
      return false;  // x has more than four cells
    const int o = kernel.orient3d(y, z, d, e);
    if (o == 0) return false;
    const Index old[] = {c, nb, across_y, across_z};
    const std::array<Index, 4> made[] = {o > 0 ? std::array<Index, 4>{y, z, d, e} : std::array<Index, 4>{z, y, d, e}};
    ++flips41_;
    replace(old, made);
    t_.status_[x] = PointStatus::hidden, t_.vertex_cell_[x] = kNone;
    return true;
  }

  // Replaces the cells `old` by cells with the vertices `made` (positively
  // oriented, the same region), joined to each other and to old's outside.
  bool replace(std::span<const Index> old, std::span<const std::array<Index, 4>> made) {
    auto& cells = t_.cells_;
    struct Outside {
      std::array<Index, 3> key;
      Index cell;
      int mirror;
    };
    const auto key_of = [](const std::array<Index, 4>& v, int k) {  // the facet's vertices sorted
      Index a = v[kFacet[k][0]], b = v[kFacet[k][1]], c = v[kFacet[k][2]];
      if (a > b) std::swap(a, b);
      if (b > c) std::swap(b, c);
      if (a > b) std::swap(a, b);
      return std::array<Index, 3>{a, b, c};
    };
    std::array<Outside, 16> outside;  // 2 to 4 cells, 4 facets each
    std::size_t outsides = 0;
    for (Index o : old)
      for (int k = 0; k < 4; ++k)
        if (const Index nb = cells[o].n[k]; std::find(old.begin(), old.end(), nb) == old.end())
          outside[outsides++] = {key_of(cells[o].v, k), nb, t_.mirror_index(o, k)};
    std::array<Index, 4> ids;
    std::copy(old.begin(), old.end(), ids.begin());
    for (Index o : old) cell_stamp_[o] = kDead;
    for (std::size_t j = old.size(); j < made.size(); ++j) {
      if (!free_.empty()) {
        ids[j] = free_.back();
        free_.pop_back();
      } else {
        ids[j] = Index(cells.size());
        cells.push_back({});
        cell_stamp_.push_back(0);
      }
    }
    for (std::size_t j = made.size(); j < old.size(); ++j) free_.push_back(ids[j]);
    t_.num_finite_cells_ = t_.num_finite_cells_ + made.size() - old.size();  // flips join finite cells only
    for (std::size_t j = 0; j < made.size(); ++j) {
      cells[ids[j]].v = made[j];
      cell_stamp_[ids[j]] = 0;
      for (Index u : made[j]) t_.vertex_cell_[u] = ids[j];
    }
    std::array<std::array<Index, 3>, 12> keys;  // of made[j]'s facet k at 4 j + k
    for (std::size_t j = 0; j < made.size(); ++j)
      for (int k = 0; k < 4; ++k) keys[4 * j + k] = key_of(made[j], k);
    // The facets between made cells are regular: of the two ways to fill
    // the flip's five points, the other one failed, and in general position
    // (the perturbation) one of them is regular. Their values do not change
    // before flip_all reads the queue.
    for (std::size_t j = 0; j < made.size(); ++j) {
      std::uint8_t regular = 0;
      for (int k = 0; k < 4; ++k) {
        const auto& key = keys[4 * j + k];
        Index nb = kNone;
        for (std::size_t l = 0; l < made.size() && nb == kNone; ++l)
          for (int m = 0; m < 4; ++m)
            if (l != j && keys[4 * l + m] == key) nb = ids[l];
        if (nb != kNone) regular |= std::uint8_t(1u << k);
        else
          for (std::size_t o = 0; o < outsides; ++o)
            if (outside[o].key == key) nb = outside[o].cell, cells[nb].n[outside[o].mirror] = ids[j];
        cells[ids[j]].n[k] = nb;
      }
      flip_queue_.push_back({ids[j], regular});
    }
    return true;
  }
  // One moved vertex of a failing cell (or facet) goes back at a time: a
  // vertex already on its way back is checked around again, else the first
  // still at its new values goes. None left: cannot happen (all old values
  // pass), but is never left as is.
  void take_moved(const std::array<Index, 4>& v, Index far) {
    if (pending_mark_.empty()) assign_huge(pending_mark_, t_.points_.size(), char(0));
    Index next = kNone;
    for (Index u : {v[0], v[1], v[2], v[3], far})
      if (u != kInfinite && is_moved_[u] && !reverted_[u]) {
        if (pending_mark_[u] & kPending) return;
        if (next == kNone) next = u;
      }
    if (next == kNone) stuck_ = true;
    else pending_mark_[next] |= kPending, pending_.push_back(next);
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

  // Takes the vertices vs out with the values at_: the cells holding them
  // become the cells of the regular triangulation of their other vertices
  // (and the hidden points within their box) that lie inside that region.
  // Cells of Reg(P \ vs) inside the region are empty for any subset of
  // P \ vs holding their vertices, so they are cells of that triangulation
  // too. Each part of the region (its cells joined across facets) is refilled
  // on its own: one sub-triangulation of all parts would mostly build cells
  // between far parts, to be thrown away.
  bool take_out(const std::vector<Index>& vs) {
    if (vs.empty()) return true;
    std::vector<Index> stars, star;
    for (Index v : vs) {
      removed_[v] = 1;
      if (t_.status_[v] != PointStatus::vertex) continue;  // hidden by a 4-1 flip
      star_of(v, star);
      stars.insert(stars.end(), star.begin(), star.end());
    }
    const std::uint32_t in = ++stamp_;
    for (Index c : stars) cell_stamp_[c] = in;
    std::vector<Index> part;
    for (Index c : stars) {
      if (cell_stamp_[c] != in) continue;  // in a part already
      const std::uint32_t mark = ++stamp_;
      cell_stamp_[c] = mark;
      part.assign(1, c);
      for (std::size_t k = 0; k < part.size(); ++k)
        for (Index nb : t_.cells_[part[k]].n)
          if (cell_stamp_[nb] == in) cell_stamp_[nb] = mark, part.push_back(nb);
      if (!refill(part, mark)) return false;
    }
    for (Index v : vs) t_.status_[v] = PointStatus::hidden, t_.vertex_cell_[v] = kNone;
    relocated_ += vs.size();
    return true;
  }

  // Refills the region `region` (its cells stamped `in`, no other cell of
  // it across a facet) with the regular triangulation of its vertices left.
  bool refill(const std::vector<Index>& region, std::uint32_t in) {
    auto& cells = t_.cells_;
    // The boundary facets, as the region sees them (from inside).
    struct Boundary {
      FacetKey key;
      Index outside;
      int mirror;
      Index cell = kNone;  // the sub-triangulation's cell on the region's side
      int facet = 0;
    };
    std::vector<Boundary> boundary;
    std::vector<Index> ids;  // the sub-triangulation's points, as input ids
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (Index c : region) {
      const auto& cv = cells[c].v;
      for (int k = 0; k < 4; ++k) {
        const Index u = cv[k];
        if (u != kInfinite) {
          const Vec3& p = t_.points_[u];
          lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
          hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
          if (!removed_[u]) ids.push_back(u);
        }
        const Index nb = cells[c].n[k];
        if (cell_stamp_[nb] == in) continue;
        const auto& f = kFacet[k];
        boundary.push_back({facet_key(cv[f[0]], cv[f[1]], cv[f[2]]), nb, t_.mirror_index(c, k)});
      }
    }
    for (Index h : hidden_) {
      const Vec3& p = t_.points_[h];
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
      // Match each boundary facet with the sub cell on the region's side.
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
      // The sub cells inside the region: from the boundary, never across it.
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
      // Cell ids: the region's first, then unused ones, then new ones.
      for (Index c : region) {
        cell_stamp_[c] = kDead, free_.push_back(c);
        t_.num_finite_cells_ -= !t_.is_infinite(c);
      }
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
        t_.num_finite_cells_ += !t_.is_infinite(number[s]);
      }
      for (const Boundary& b : boundary) {
        cells[number[b.cell]].n[b.facet] = b.outside;
        cells[b.outside].n[b.mirror] = number[b.cell];
      }
    }
    return true;
  }

  // The regular triangulation of the points ids (with the old values), ids
  // sorted and unique: in increasing input order the perturbation orders
  // them as in the whole set. None when they span no 3D triangulation.
  std::optional<Triangulation> regular_of(std::vector<Index>& ids) const {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<Vec3> pts(ids.size());
    std::vector<double> ws(t_.weights_.empty() ? 0 : ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) {
      pts[k] = t_.points_[ids[k]];
      if (!ws.empty()) ws[k] = t_.weights_[ids[k]];
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
  const std::size_t n = points_.size();
  std::vector<Index> sorted(ids.begin(), ids.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k)
    if (sorted[k] >= n || (k > 0 && sorted[k] == sorted[k - 1]))
      fail("point id " + std::to_string(sorted[k]) + " is out of range or given twice", ErrorKind::Misuse);
  for (std::size_t k = 0; k < ids.size(); ++k) check_point(ids[k], to[k], weights.empty() ? nullptr : &weights[k]);
  // The new values in place, the old ones kept.
  std::vector<Index> moved;
  std::vector<Vec3> old_p;
  std::vector<double> old_w;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Index i = ids[k];
    if (points_[i] == to[k] && (weights.empty() || weights_[i] == weights[k])) continue;
    moved.push_back(i);
    old_p.push_back(points_[i]), points_[i] = to[k];
    if (!weights.empty()) old_w.push_back(weights_[i]), weights_[i] = weights[k];
  }
  UpdateReport report;
  if (moved.empty()) return report;
  const auto as_it_was = [&] {
    for (std::size_t k = 0; k < moved.size(); ++k) {
      points_[moved[k]] = old_p[k];
      if (!old_w.empty()) weights_[moved[k]] = old_w[k];
    }
  };
  // The points' span (see check_input): when the corners of a cell that
  // holds no moved point span enough, all do; else it is measured.
  bool spans = false;
  for (Index c = 0; c < cells_.size() && moved.size() * 8 < n; ++c) {
    const auto& v = cells_[c].v;
    if (is_infinite(c) || std::any_of(v.begin(), v.end(), [&](Index u) { return std::binary_search(sorted.begin(), sorted.end(), u); }))
      continue;
    double extent = 0;
    for (const auto axis : {&Vec3::x, &Vec3::y, &Vec3::z})
      for (Index a : v)
        for (Index b : v) extent = std::max(extent, points_[a].*axis - points_[b].*axis);
    spans = extent >= kMinExtent;
    break;
  }
  if (!spans) {
    try {
      check_input(points_, weights_);
    } catch (const Error&) {
      as_it_was();
      throw;
    }
  }
  Updater updater(*this);
  if (updater.move(moved, old_p, old_w)) {
    updater.tell(report);
    return report;
  }
  report.rebuilt = true, report.foretold = updater.foretold();
  std::vector<Vec3> now = points_;
  std::vector<double> now_w = weights_;
  try {
    *this = Triangulation(std::move(now), std::move(now_w));
  } catch (const Error&) {
    as_it_was();
    *this = Triangulation(points_, weights_);
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
  points_ = all, weights_ = w;
  status_.resize(all.size(), PointStatus::vertex);
  representative_.resize(all.size());
  std::iota(representative_.begin() + first, representative_.end(), first);
  vertex_cell_.resize(all.size(), kNone);
  Updater updater(*this);
  if (updater.insert(first)) {
    updater.tell(report);
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
  Updater updater(*this);
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
  updater.tell(report);
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
  Index hint = kNone;
  for (Index c = 0; c < cells_.size() && hint == kNone; ++c)
    if (!dead[c]) hint = c;
  insert_into({}, std::move(free_cells), hint);  // compacts the cells, counts the points again
  vertex_cell_.assign(points_.size(), kNone);     // the vertices were renumbered
  for (Index c = 0; c < cells_.size(); ++c)
    for (Index v : cells_[c].v)
      if (v != kInfinite) vertex_cell_[v] = c;
  return report;
}

}  // namespace alpha
