// SPDX-License-Identifier: Apache-2.0
#include "alpha/triangulation.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <exception>
#include <memory>
#include <thread>
#include <utility>

#include <cmath>
#include <numeric>
#include <string>

#include "alpha/error.hpp"
#include "alpha/spatial_sort.hpp"
#include "triangulation/triangulation_input.hpp"
#include "util/huge_pages.hpp"
#include "util/parallel.hpp"

namespace alpha {
namespace {

// Far beyond any physical coordinate, yet squares and products of
// differences stay well inside double range for the filters.
constexpr double kMaxCoordinate = 1e15;
constexpr double kMaxWeight = 1e30;

}  // namespace

void check_point(std::size_t i, const Vec3& p, const double* weight) {
  for (double v : {p.x, p.y, p.z})
    if (!std::isfinite(v) || std::fabs(v) > kMaxCoordinate)
      fail("point " + std::to_string(i) + ": coordinate " + std::to_string(v) +
               (std::isfinite(v) ? " is out of range (|x| > 1e15)" : " is not a finite number"),
           ErrorKind::BadInput);
  if (weight && (!std::isfinite(*weight) || std::fabs(*weight) > kMaxWeight))
    fail("point " + std::to_string(i) + ": weight " + std::to_string(*weight) + " is not a finite number within 1e30",
         ErrorKind::BadInput);
}

void check_input(const std::vector<Vec3>& points, const std::vector<double>& weights) {
  if (!weights.empty() && weights.size() != points.size())
    fail("got " + std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) +
         " points", ErrorKind::Misuse);
  if (points.size() >= kInfinite) fail("too many points: " + std::to_string(points.size()), ErrorKind::LimitExceeded);
  for (std::size_t i = 0; i < points.size(); ++i) check_point(i, points[i], weights.empty() ? nullptr : &weights[i]);
  // Sizes scale as the squared extent: below this, the doubles that report
  // them (spectrum values, alpha_sq) would round to 0 or subnormals.
  double extent = 0;
  for (const auto axis : {&Vec3::x, &Vec3::y, &Vec3::z}) {
    const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                              [&](const Vec3& a, const Vec3& b) { return a.*axis < b.*axis; });
    if (lo != points.end()) extent = std::max(extent, (*hi).*axis - (*lo).*axis);
  }
  if (extent > 0 && extent < kMinExtent)
    fail("the points span only " + std::to_string(extent) + " (below 1e-100): their sizes would underflow",
         ErrorKind::BadInput);
}

namespace {

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

// The points in insertion order, shared by the builders of one triangulation:
// a vertex id is a position in that order (input[id] is its input index,
// which also orders the perturbation) until finish() writes the input
// indices into the cells.
struct InsertionOrder {
  std::vector<Index> input;
  std::vector<Vec3> points;
  std::vector<double> weights;  // weighted input only
};

// What the builders of a parallel construction share: a cell array of fixed
// size, whose unused ids are handed out in chunks, and a lock per cell.
struct SharedCells {
  static constexpr std::uint8_t kFree = 0, kDead = 255;  // else 1 + the holder's number
  std::unique_ptr<std::atomic<std::uint8_t>[]> lock;
  std::atomic<std::size_t> next{0};  // the first id not handed out
  std::size_t capacity = 0;
};

// The last round of a parallel construction (7/8 of the points) in pieces:
// each builder takes its own stretch's from the front and, once done, the
// others' from the back, so that the builders finish together even when
// one runs slower (a busy core). Points of a piece are consecutive in the
// round's curve order, so a piece's walks stay short.
class Pieces {
public:
  static constexpr std::size_t kPoints = 1024;  // per piece

  Pieces(std::size_t begin, std::size_t end, unsigned builders)
      : begin_(begin), end_(end), left_(std::make_unique<Left[]>(builders)) {
    const std::uint64_t count = (end - begin + kPoints - 1) / kPoints;
    for (unsigned w = 0; w < builders; ++w) left_[w].range = (count * w / builders) << 32 | count * (w + 1) / builders;
  }
  // Builder w's next piece of its own stretch, false when none is left.
  bool front(unsigned w, std::size_t& first, std::size_t& last) { return take(w, true, first, last); }
  // The last piece left of builder w's stretch, for another builder.
  bool back(unsigned w, std::size_t& first, std::size_t& last) { return take(w, false, first, last); }

private:
  struct alignas(64) Left {  // a cache line each: the owner changes it often
    std::atomic<std::uint64_t> range;  // the pieces left: first << 32 | end
  };
  bool take(unsigned w, bool from_front, std::size_t& first, std::size_t& last) {
    std::uint64_t range = left_[w].range.load(std::memory_order_relaxed);
    std::uint64_t piece;
    do {
      const std::uint64_t front = range >> 32, back = range & 0xffffffffu;
      if (front >= back) return false;
      piece = from_front ? front : back - 1;
    } while (!left_[w].range.compare_exchange_weak(range, from_front ? range + (std::uint64_t(1) << 32) : range - 1,
                                                   std::memory_order_relaxed));
    first = begin_ + piece * kPoints;
    last = std::min(first + kPoints, end_);
    return true;
  }
  std::size_t begin_, end_;
  std::unique_ptr<Left[]> left_;
};

// Arrays that a parallel construction fills later, allocated and faulted
// in on the core left idle while the points are sorted: on a fresh page
// the first write costs about as much as the work done there.
struct Scratch {
  template <class T>
  using Array = std::vector<T, UninitializedAllocator<T>>;
  std::vector<Array<std::uint32_t>> marks;  // each builder's cell marks
  std::vector<Array<Index>> count;          // canonical_numbers's, per thread
  Array<Cell> numbered;                     // the cells in canonical order
  // Two builders' marks, once they are done (no faults left to take).
  Array<Index> remap, sorted;

  void prepare(std::size_t cells, std::size_t points, unsigned threads) {
    marks.resize(threads);
    for (auto& m : marks) assign_huge(m, cells);
    count.resize(threads);
    for (auto& c : count) assign_huge(c, points);
    assign_huge(numbered, cells);
  }
};

// The incremental construction; lives only while the triangulation is built.
// It works on a copy of the points in insertion order, so that consecutive
// insertions read nearby memory.
//
// With threads, the coarse rounds of the insertion order (about n/64 points,
// whose cavities span the whole set) are inserted sequentially, then each
// later round is cut into as many stretches of its curve order as there are
// threads, one builder each (the last round in pieces, which a builder done
// with its own takes from the others: see Pieces). A builder locks every
// cell it reads (the walk hand over hand, the cavity and its boundary all
// at once) with a non-blocking try: when another builder holds one, the
// point is left for a sequential pass at the end. So each insertion sees
// and replaces a valid triangulation, and the result is the unique regular
// triangulation of the perturbed points, numbered in a canonical order
// (finish()): the same for any thread count and timing.
class Triangulation::Builder {
public:
  Builder(Triangulation& t, InsertionOrder& o) : t_(t), o_(o) {}

  void run(unsigned threads) {
    // A Delaunay triangulation of n random points has about 6.7 n cells;
    // reserving avoids repeated copies and page faults while growing.
    const auto expected_cells = [](std::size_t points) { return points * 27 / 4 + 64; };
    if (threads > 1 && t_.points_.size() >= kMinParallel) {
      // Sized for all points: duplicates are not known yet.
      const std::size_t points = t_.points_.size();
      capacity_ = expected_cells(points) + points / 8 + kChunk * 4 * threads;
      prefault_ = std::jthread([this, points, threads] {
        try {
          scratch_.prepare(capacity_, points, threads);
        } catch (...) {
          prefault_error_ = std::current_exception();
        }
      });
    }
    const std::vector<Index> reps = merge_duplicates();
    if (reps.size() < 4)
      fail("need at least 4 distinct points, got " + std::to_string(reps.size()), ErrorKind::BadInput);
    const std::size_t expected = expected_cells(reps.size());
    const bool parallel = threads > 1 && reps.size() >= kMinParallel;
    // The cell array is written at random places as it fills.
    reserve_huge(cells_, expected);
    cell_mark_.assign(parallel ? expected / 16 : expected, 0);  // threads: for the coarse rounds
    const unsigned setup_threads = parallel ? threads : 1;
    o_.input = brio_order(t_.points_, reps, setup_threads);
    o_.points.resize(o_.input.size());
    if (t_.weighted()) o_.weights.resize(o_.input.size());
    in_parallel(setup_threads, o_.input.size(), [&](unsigned, std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) o_.points[k] = t_.points_[o_.input[k]];
      if (t_.weighted())
        for (std::size_t k = begin; k < end; ++k) o_.weights[k] = t_.weights_[o_.input[k]];
    });
    in_doubles_ = Kernel::exact_in_doubles(o_.points, o_.weights);
    kernel_ = order_kernel();
    first_ = initial_simplex();
    if (parallel) insert_parallel(threads);
    else insert_range(0, o_.points.size(), 0);
    finish(parallel ? threads : 1);
  }

  // Inserts `order` (input ids) into the cells t_ already has, whose
  // unused ids are `free_cells`; vertex ids are input ids throughout. The
  // kernel reads the points in place (never exact_in_doubles: its answers
  // are the same, and checking that would read every point). The vertex
  // links and the finite cell count are kept up to date, and only the cells
  // above the new end move into the unused ids below it, so the cost
  // follows the cells that changed.
  void update(std::span<const Index> order, std::vector<Index> free_cells, Index hint) {
    const std::size_t n = t_.points_.size();
    reserve_huge(o_.input, n);
    o_.input.resize(n);
    std::iota(o_.input.begin(), o_.input.end(), Index(0));
    kernel_ = Kernel(t_.points_.data(), t_.weights_.empty() ? nullptr : t_.weights_.data());
    assign_huge(cell_mark_, cells_.size(), std::uint32_t(0));
    free_cells_ = std::move(free_cells);
    for (Index p : order) {
      infinite_conflicts_ = 0;
      hint = insert<false>(p, hint);
      if (t_.status_[p] != PointStatus::vertex) continue;  // hidden: nothing changed
      // The new cells (across each boundary facet from the cell that stayed) link their vertices.
      std::size_t made_finite = 0;
      for (const Facet& f : boundary_) {
        const Index c = cells_[f.outside].n[f.mirror];
        bool finite = true;
        for (Index v : cells_[c].v) {
          if (v == kInfinite) finite = false;
          else t_.vertex_cell_[v] = c;
        }
        made_finite += finite;
      }
      t_.num_finite_cells_ = t_.num_finite_cells_ + made_finite - (conflict_.size() - infinite_conflicts_);
      if (t_.weighted())
        for (Index v : cavity_vertices_)
          if (t_.status_[v] == PointStatus::hidden) t_.vertex_cell_[v] = kNone;
    }
    compact_locally();
    t_.num_vertices_ = t_.num_hidden_ = 0;
    for (PointStatus s : t_.status_) {  // bytes: far below the cost of any insertion
      t_.num_hidden_ += s == PointStatus::hidden;
      t_.num_vertices_ += s == PointStatus::vertex;
    }
    t_.stats_ = kernel_.stats();
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
  // Below this many points threads do not pay (and a point set has few
  // points beyond its coarse rounds).
  static constexpr std::size_t kMinParallel = 1 << 15;
  static constexpr std::size_t kChunk = 4096;  // cell ids a builder takes at a time

  Triangulation& t_;
  InsertionOrder& o_;
  Kernel kernel_{nullptr, nullptr};  // on o_.points, once they are copied
  bool in_doubles_ = false;          // o_'s points are Kernel::exact_in_doubles
  std::array<Index, 4> first_{};     // the initial simplex
  decltype(t_.cells_)& cells_ = t_.cells_;
  Scratch::Array<std::uint32_t> cell_mark_;  // == stamp_: conflict, == stamp_+1: tested, no conflict
  std::uint32_t stamp_ = 2;
  std::vector<Index> free_cells_, conflict_, stack_;
  std::vector<Facet> boundary_;
  std::vector<EdgeSlot> edges_;
  std::vector<std::uint32_t> vertex_mark_;
  std::vector<Index> cavity_vertices_;
  std::uint32_t walk_rng_ = 0x9e3779b9u;
  std::size_t infinite_conflicts_ = 0;  // infinite cells in conflict with the point being inserted
  // Parallel construction only.
  SharedCells* shared_ = nullptr;
  std::uint8_t me_ = 0;                 // this builder's lock value
  std::vector<Index> locked_;           // the cells it holds
  std::size_t chunk_next_ = 0, chunk_end_ = 0;  // its unused chunk of ids
  std::array<Index, 8> recent_{};       // cells it made lately: walks start there
  std::size_t made_count_ = 0;
  std::vector<Index> deferred_;         // points left for the sequential pass
  bool stopped_ = false;                // out of cell ids: defers the rest
  PredicateStats other_stats_;          // the other builders' counts
  std::size_t capacity_ = 0;            // the size of the shared cell array
  Scratch scratch_;
  std::jthread prefault_;               // fills scratch_
  std::exception_ptr prefault_error_;

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
    std::vector<Index> order(o_.points.size());
    std::iota(order.begin(), order.end(), Index(0));
    std::array<Index, 4> v;
    const int dimension = spanning_points(kernel_, o_.points, order, v);
    if (dimension == 1)
      fail("all points are collinear: a 3D triangulation needs 4 non-coplanar points", ErrorKind::BadInput);
    if (dimension == 2)
      fail("all points are coplanar: a 3D triangulation needs 4 non-coplanar points", ErrorKind::BadInput);
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

  // A kernel on the points in insertion order, with counts of its own.
  Kernel order_kernel() const {
    return Kernel(o_.points.data(), o_.weights.empty() ? nullptr : o_.weights.data(), o_.input.data(), in_doubles_);
  }

  bool is_first(Index p) const { return p == first_[0] || p == first_[1] || p == first_[2] || p == first_[3]; }

  // Inserts the points at positions [begin, end); returns the last hint.
  Index insert_range(std::size_t begin, std::size_t end, Index hint) {
    for (Index p = Index(begin); p < end; ++p)
      if (!is_first(p)) hint = insert<false>(p, hint);
    return hint;
  }

  void insert_parallel(unsigned threads) {
    const std::size_t n = o_.points.size();
    const std::vector<std::size_t> rounds = brio_rounds(n);
    std::size_t r0 = 1;  // the first round inserted in parallel
    while (rounds[r0] < n / 64) ++r0;
    const Index hint = insert_range(0, rounds[r0], 0);
    prefault_.join();
    if (prefault_error_) std::rethrow_exception(prefault_error_);

    SharedCells shared;
    // Room for the cells, the builders' unused chunks and free cells (the
    // capacity_ set in run()); a builder that finds none left defers its
    // other points.
    shared.capacity = std::max(capacity_, cells_.size() + kChunk * 4 * threads);
    reserve_huge(cells_, shared.capacity);
    shared.next = cells_.size();
    cells_.resize(shared.capacity);
    shared.lock = std::make_unique<std::atomic<std::uint8_t>[]>(shared.capacity);
    for (Index c : free_cells_) shared.lock[c].store(SharedCells::kDead, std::memory_order_relaxed);

    std::vector<std::unique_ptr<Builder>> workers;
    for (unsigned w = 0; w < threads; ++w) {
      auto b = std::make_unique<Builder>(t_, o_);
      b->kernel_ = order_kernel();
      b->first_ = first_;
      b->shared_ = &shared;
      b->me_ = std::uint8_t(w + 1);
      b->cell_mark_ = std::move(scratch_.marks[w]);
      b->cell_mark_.resize(shared.capacity, 0);
      b->recent_.fill(hint);
      workers.push_back(std::move(b));
    }
    workers[0]->free_cells_ = std::move(free_cells_);
    free_cells_.clear();

    Pieces last_round(rounds[rounds.size() - 2], n, threads);
    std::vector<std::exception_ptr> errors(threads);
    auto work = [&](unsigned w) {
      try {
        workers[w]->insert_share(rounds, r0, last_round, w, threads);
      } catch (...) {
        errors[w] = std::current_exception();
      }
    };
    {
      std::vector<std::jthread> pool;
      for (unsigned w = 1; w < threads; ++w) pool.emplace_back(work, w);
      work(0);
    }
    for (const auto& e : errors)
      if (e) std::rethrow_exception(e);

    // Back to one builder: the cells in use so far, the free ones, the points left.
    const std::size_t used = std::min(shared.next.load(), shared.capacity);
    std::vector<Index> left;
    for (const auto& b : workers) {
      for (Index c = Index(b->chunk_next_); c < b->chunk_end_; ++c) b->free_cells_.push_back(c);
      for (Index c : b->free_cells_) {
        free_cells_.push_back(c);
        shared.lock[c].store(SharedCells::kDead, std::memory_order_relaxed);
      }
      left.insert(left.end(), b->deferred_.begin(), b->deferred_.end());
      other_stats_ += b->kernel_.stats();
    }
    for (Index c = Index(used); c < shared.capacity; ++c) free_cells_.push_back(c);
    // Builder 0's marks cover the whole array (stamps only grow); builder
    // 1's become finish()'s remap (stamps are never kNone) and cell_mark_
    // its sorted list.
    cell_mark_ = std::move(workers[0]->cell_mark_);
    stamp_ = workers[0]->stamp_ + 2;
    scratch_.remap = std::move(workers[1]->cell_mark_);
    if (left.empty()) return;
    std::sort(left.begin(), left.end());
    // The walk starts from a live cell: one a builder made lately, else the first.
    const auto live = [&](Index c) { return shared.lock[c].load(std::memory_order_relaxed) != SharedCells::kDead; };
    Index start = kNone;
    for (const auto& b : workers)
      for (Index c : b->recent_)
        if (start == kNone && live(c)) start = c;
    for (Index c = 0; start == kNone && c < used; ++c)
      if (live(c)) start = c;
    for (Index p : left) start = insert<false>(p, start);
  }

  // A builder's share of the parallel rounds: stretch w of T of each but
  // the last, then pieces of the last (its own, then the others').
  void insert_share(const std::vector<std::size_t>& rounds, std::size_t r0, Pieces& last_round, unsigned w, unsigned T) {
    Index hint = recent_[0];
    const auto insert_points = [&](std::size_t begin, std::size_t end) {
      for (Index p = Index(begin); p < end; ++p) {
        if (is_first(p)) continue;
        if (stopped_) deferred_.push_back(p);
        else hint = insert<true>(p, hint);
      }
    };
    for (std::size_t r = r0; r + 2 < rounds.size(); ++r) {
      const std::size_t b = rounds[r], size = rounds[r + 1] - b;
      insert_points(b + size * w / T, b + size * (w + 1) / T);
    }
    std::size_t first, last;
    while (last_round.front(w, first, last)) insert_points(first, last);
    // A builder out of cell ids would only defer them.
    for (unsigned o = (w + 1) % T; o != w && !stopped_; o = (o + 1) % T)
      while (!stopped_ && last_round.back(o, first, last)) insert_points(first, last);
  }

  bool try_lock(Index c) {
    std::uint8_t expected = SharedCells::kFree;
    return shared_->lock[c].compare_exchange_strong(expected, me_, std::memory_order_acquire,
                                                    std::memory_order_relaxed);
  }
  void unlock(Index c) { shared_->lock[c].store(SharedCells::kFree, std::memory_order_release); }
  bool acquire(Index c) {
    if (!try_lock(c)) return false;
    locked_.push_back(c);
    return true;
  }
  // Lets go of every held cell; the cells freed by this insertion from
  // free_cells_[dead_from] on are dead (a walk must not start there).
  void release(std::size_t dead_from) {
    for (std::size_t k = dead_from; k < free_cells_.size(); ++k)
      shared_->lock[free_cells_[k]].store(SharedCells::kDead, std::memory_order_relaxed);
    for (Index c : locked_)
      if (shared_->lock[c].load(std::memory_order_relaxed) == me_) unlock(c);
    locked_.clear();
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
      const bool in = kernel_.hull_conflict(v[f[0]], v[f[1]], v[f[2]], p);
      infinite_conflicts_ += in;  // each cell is tested once per insertion
      return in;
    }
    return kernel_.power_conflict(v, p);
  }

  // Visibility walk from `start` to a cell whose closure holds p (for a point
  // outside the hull: an infinite cell whose hull facet sees p). Shared: the
  // walk holds the cell it reads and returns the located cell held, or kNone
  // (nothing held) where another builder holds the way.
  template <bool kShared>
  Index locate(Index p, Index start) {
    Index c = start, previous = kNone;
    if constexpr (kShared) {  // the hint, else a cell made lately (another builder may have replaced it)
      c = try_lock(start) ? start : kNone;
      for (std::size_t k = 0; c == kNone && k < recent_.size(); ++k)
        if (try_lock(recent_[k])) c = recent_[k];
      if (c == kNone) return kNone;
    }
    for (;;) {
      const Cell& cell = cells_[c];
      const int inf = index_of(c, kInfinite);
      Index next = kNone;
      if (inf >= 0) {
        const auto& f = kFacet[inf];
        if (kernel_.orient3d(cell.v[f[0]], cell.v[f[1]], cell.v[f[2]], p) > 0) return c;
        next = cell.n[inf];
      } else {
        walk_rng_ ^= walk_rng_ << 13, walk_rng_ ^= walk_rng_ >> 17, walk_rng_ ^= walk_rng_ << 5;
        const int r = static_cast<int>(walk_rng_ & 3u);
        for (int j = 0; j < 4 && next == kNone; ++j) {
          const int i = (r + j) & 3;
          if (cell.n[i] == previous) continue;
          const auto& f = kFacet[i];
          if (kernel_.orient3d(cell.v[f[0]], cell.v[f[1]], cell.v[f[2]], p) < 0) next = cell.n[i];
        }
        if (next == kNone) return c;
      }
      if constexpr (kShared) {
        const bool held = try_lock(next);
        unlock(c);
        if (!held) return kNone;
      }
      previous = c, c = next;
    }
  }

  // Inserts p; returns a live cell near p to start the next walk. Shared:
  // a point whose cells another builder holds is deferred.
  template <bool kShared>
  Index insert(Index p, Index hint) {
    if constexpr (!kShared)
      if (cell_mark_.size() < cells_.size()) cell_mark_.resize(cells_.size() * 2, 0);
    const Index start = locate<kShared>(p, hint);
    if constexpr (kShared) {
      if (start == kNone) return defer(p, hint);
      locked_.push_back(start);
    }
    stamp_ += 2;
    if (!conflict(cells_[start], p)) {
      t_.status_[o_.input[p]] = PointStatus::hidden;
      if constexpr (kShared) release(free_cells_.size());
      return start;
    }
    if (!find_cavity<kShared>(start, p)) return defer(p, start);  // never without kShared
    if (t_.weighted()) mark_cavity_vertices();
    const std::size_t dead_from = free_cells_.size();
    const Index made = fill_cavity<kShared>();
    if constexpr (kShared)
      if (made == kNone) {
        stopped_ = true;
        return defer(p, start);
      }
    if (t_.weighted()) hide_enclosed_vertices();
    if constexpr (kShared) {
      release(dead_from);
      recent_[made_count_++ % recent_.size()] = made;
    }
    return made;
  }

  Index defer(Index p, Index hint) {
    release(free_cells_.size());
    deferred_.push_back(p);
    return hint;
  }

  // Collects the cells in conflict with p and the cavity's boundary facets.
  // Shared: false (and nothing changed) if another builder holds one of them.
  template <bool kShared>
  bool find_cavity(Index start, Index p) {
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
        if (mark[n] != out) {
          if (kShared && !acquire(n)) return false;
          if (conflict(cells[n], p)) {
            mark[n] = in;
            stack_.push_back(n);
            continue;
          }
        }
        mark[n] = out;
        Facet f{cells[c].v, i, n, index_of_neighbor(n, c)};
        f.v[i] = p;
        boundary_.push_back(f);
      }
    }
    return true;
  }

  int index_of_neighbor(Index c, Index n) const {
    const auto& cn = cells_[c].n;
    for (int k = 0; k < 4; ++k)
      if (cn[k] == n) return k;
    return -1;
  }

  // Shared: makes sure free cells and the chunk hold `wanted` ids (the
  // rest of a too small chunk goes to the free cells); false when the
  // shared array has no more.
  bool reserve_ids(std::size_t wanted) {
    if (free_cells_.size() + conflict_.size() + (chunk_end_ - chunk_next_) >= wanted) return true;
    for (std::size_t c = chunk_next_; c < chunk_end_; ++c) free_cells_.push_back(Index(c));
    const std::size_t size = std::max(kChunk, wanted);
    const std::size_t base = shared_->next.fetch_add(size, std::memory_order_relaxed);
    if (base + size > shared_->capacity) {
      for (std::size_t c = base; c < shared_->capacity; ++c) free_cells_.push_back(Index(c));
      chunk_next_ = chunk_end_ = 0;
      return false;
    }
    chunk_next_ = base, chunk_end_ = base + size;
    return true;
  }

  // Replaces the conflict cells by p joined to each boundary facet: the
  // free cells first (last freed first), then new ids in increasing order.
  // Shared: kNone (nothing changed) when the shared array is full.
  template <bool kShared>
  Index fill_cavity() {
    if (kShared && !reserve_ids(boundary_.size())) return kNone;
    for (Index c : conflict_) free_cells_.push_back(c);
    Index next_new = static_cast<Index>(kShared ? chunk_next_ : cells_.size());
    if (!kShared && boundary_.size() > free_cells_.size()) {
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
        // A dead cell (or an unused id) is held from now on: a stale hint may name it.
        if (kShared && shared_->lock[c].load(std::memory_order_relaxed) != me_) {
          shared_->lock[c].store(me_, std::memory_order_relaxed);
          locked_.push_back(c);
        }
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
    if constexpr (kShared) chunk_next_ = next_new;
    return made;
  }

  // Weighted points only: a vertex of the conflict cells that no boundary
  // facet keeps lies inside the cavity, and the new point hides it.
  void mark_cavity_vertices() {
    if (vertex_mark_.size() < t_.points_.size()) vertex_mark_.assign(t_.points_.size(), 0);
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
      if (vertex_mark_[v] == stamp_) t_.status_[o_.input[v]] = PointStatus::hidden;
  }

  // The canonical order of a parallel construction, into scratch_.numbered:
  // each cell's vertices sorted (the first two swapped when that takes an
  // odd permutation, to keep the orientation), the cells by their last
  // finite vertex in insertion order (the point whose insertion made them,
  // so the order follows where the builders stored them), then by their
  // sorted vertex lists. The neighbours are left as they were; remap[c]
  // becomes c's number (it is kNone for unused cells). Returns the number
  // of cells.
  std::size_t canonical_order(Scratch::Array<Index>& remap, unsigned threads) {
    const std::size_t n = o_.points.size();
    const auto last = [](const Cell& cell) {  // kInfinite is the largest index
      Index m = 0;
      for (Index v : cell.v) m = std::max(m, v == kInfinite ? 0 : v);
      return m;
    };
    // Cells by their last vertex, counted per thread.
    std::vector<Scratch::Array<Index>>& count = scratch_.count;
    in_parallel(threads, cells_.size(), [&](unsigned t, std::size_t begin, std::size_t end) {
      for (std::size_t c = begin; c < end; ++c)
        if (remap[c] != kNone) ++count[t][last(cells_[c])];
    });
    Index total = 0;  // count[t][v]: where thread t's cells of vertex v go
    for (std::size_t v = 0; v < n; ++v)
      for (auto& c : count) total += std::exchange(c[v], total);
    // Each cell, its vertices sorted, to its run; sorted[k]: where the k-th came from.
    Scratch::Array<Cell>& numbered = scratch_.numbered;
    Scratch::Array<Index>& sorted = scratch_.sorted;
    numbered.resize(total);
    sorted.resize(total);
    in_parallel(threads, cells_.size(), [&](unsigned t, std::size_t begin, std::size_t end) {
      for (std::size_t c = begin; c < end; ++c) {
        if (remap[c] == kNone) continue;
        Cell cell = cells_[c];
        bool odd = false;
        const auto exchange = [&](int a, int b) {  // a sorting network, the neighbours along, no branches
          const bool swap = cell.v[a] > cell.v[b];
          const Index va = cell.v[a], vb = cell.v[b], na = cell.n[a], nb = cell.n[b];
          cell.v[a] = swap ? vb : va, cell.v[b] = swap ? va : vb;
          cell.n[a] = swap ? nb : na, cell.n[b] = swap ? na : nb;
          odd ^= swap;
        };
        exchange(0, 1), exchange(2, 3), exchange(0, 2), exchange(1, 3), exchange(1, 2);
        if (odd) std::swap(cell.v[0], cell.v[1]), std::swap(cell.n[0], cell.n[1]);
        const Index k = count[t][last(cell)]++;
        numbered[k] = cell;
        sorted[k] = Index(c);
      }
    });
    // count.back()[v] is now where v's cells end; sort each run by vertices.
    const Scratch::Array<Index>& ends = count.back();
    const auto sorted_vertices = [](const Cell& cell) {
      const auto& v = cell.v;
      return std::array<Index, 4>{std::min(v[0], v[1]), std::max(v[0], v[1]), v[2], v[3]};
    };
    // Split by cells, not vertices: the late vertices are the last ones of most.
    const auto first_run = [&](std::size_t k) {  // the first vertex whose run starts at k or later
      return k == 0 ? 0 : k == total ? n : std::size_t(std::lower_bound(ends.begin(), ends.end(), Index(k)) - ends.begin()) + 1;
    };
    in_parallel(threads, total, [&](unsigned, std::size_t begin, std::size_t end) {
      const std::size_t first = first_run(begin), stop = first_run(end);
      for (std::size_t v = first; v < stop; ++v)
        for (std::size_t i = v == 0 ? 0 : ends[v - 1], e = ends[v], j = i + 1; j < e; ++j) {
          const Cell cell = numbered[j];
          const Index from = sorted[j];
          const auto key = sorted_vertices(cell);
          std::size_t k = j;
          for (; k > i && key < sorted_vertices(numbered[k - 1]); --k) numbered[k] = numbered[k - 1], sorted[k] = sorted[k - 1];
          numbered[k] = cell, sorted[k] = from;
        }
      for (std::size_t k = first == 0 ? 0 : ends[first - 1]; k < (stop == 0 ? 0 : ends[stop - 1]); ++k)
        remap[sorted[k]] = Index(k);
    });
    return total;
  }

  // After an update: the live cells above the new end move into the unused
  // ids below it, their neighbours and vertices relinked.
  void compact_locally() {
    std::vector<Index>& unused = free_cells_;
    std::sort(unused.begin(), unused.end());
    const Index end = Index(cells_.size() - unused.size());
    const auto above = std::lower_bound(unused.begin(), unused.end(), end);
    std::vector<Index> moved_to(cells_.size() - end, kNone);  // of cell end + k
    std::vector<Index> holes(unused.begin(), above);
    auto skip = above;
    Index from = end;
    for (Index hole : holes) {
      for (; skip != unused.end() && *skip == from; ++skip) ++from;  // unused above the end
      moved_to[from - end] = hole;
      cells_[hole] = cells_[from++];
    }
    const auto now = [&](Index c) { return c >= end ? moved_to[c - end] : c; };
    for (Index hole : holes) {
      for (Index& nb : cells_[hole].n) nb = now(nb);
      for (Index v : cells_[hole].v)
        if (v != kInfinite) t_.vertex_cell_[v] = hole;
    }
    for (Index hole : holes)
      for (Index nb : cells_[hole].n)
        for (Index& back : cells_[nb].n) back = now(back);
    cells_.resize(end);
    unused.clear();
  }

  // Drops unused cell slots, gives the vertices their input indices and
  // fills in counts and vertex-to-cell links. With threads (a parallel
  // construction), in the canonical order.
  void finish(unsigned threads) {
    // Never kNone where given: builder 1's marks on threads, else ours
    // (their pages are in memory already; the marks are not needed again).
    Scratch::Array<Index> remap = std::move(threads > 1 ? scratch_.remap : cell_mark_);
    remap.resize(cells_.size(), 0);
    for (Index c : free_cells_) remap[c] = kNone;
    const auto renumbered = [&](Cell cell) {
      for (Index& n : cell.n) n = remap[n];
      for (Index& v : cell.v)
        if (v != kInfinite) v = o_.input[v];
      return cell;
    };
    // Each vertex links to the last cell holding it.
    t_.vertex_cell_.assign(t_.points_.size(), kNone);
    if (threads > 1) {
      scratch_.sorted = std::move(cell_mark_);
      Scratch::Array<Cell>& numbered = scratch_.numbered;
      const std::size_t total = canonical_order(remap, threads);
      // Per thread, in its count array: 1 + the last number of a cell
      // holding each vertex (insertion positions), 0 for none.
      std::vector<std::size_t> finite(threads, 0);
      in_parallel(threads, total, [&](unsigned t, std::size_t begin, std::size_t end) {
        Scratch::Array<Index>& last = scratch_.count[t];
        std::fill(last.begin(), last.end(), 0);
        for (std::size_t k = begin; k < end; ++k) {
          Cell& cell = numbered[k];
          finite[t] += cell.v[3] != kInfinite;  // canonical_order sorted kInfinite last
          for (Index v : cell.v)
            if (v != kInfinite) last[v] = Index(k + 1);
          cell = renumbered(cell);
        }
      });
      in_parallel(threads, o_.points.size(), [&](unsigned, std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v) {
          Index link = 0;
          for (const auto& last : scratch_.count) link = std::max(link, last[v]);
          if (link) t_.vertex_cell_[o_.input[v]] = link - 1;
        }
      });
      for (std::size_t f : finite) t_.num_finite_cells_ += f;
      cells_.swap(numbered);
    } else {
      Index next = 0;
      for (Index c = 0; c < cells_.size(); ++c)
        if (remap[c] != kNone) remap[c] = next++;
      // remap[c] <= c: each cell moves down, onto one already moved.
      for (Index c = 0; c < cells_.size(); ++c)
        if (remap[c] != kNone) cells_[remap[c]] = renumbered(cells_[c]);
      cells_.resize(next);
      for (Index c = 0; c < cells_.size(); ++c) {
        bool finite = true;
        for (Index v : cells_[c].v) {
          if (v == kInfinite) finite = false;
          else t_.vertex_cell_[v] = c;
        }
        t_.num_finite_cells_ += finite;
      }
    }
    for (PointStatus s : t_.status_) {
      t_.num_hidden_ += s == PointStatus::hidden;
      t_.num_vertices_ += s == PointStatus::vertex;
    }
    t_.stats_ = kernel_.stats();
    t_.stats_ += other_stats_;
  }
};

Triangulation::Triangulation(std::vector<Vec3> points, std::vector<double> weights, unsigned threads)
    : points_(std::move(points)), weights_(std::move(weights)) {
  check_input(points_, weights_);
  InsertionOrder order;
  Builder(*this, order).run(std::clamp(threads, 1u, 254u));  // a builder's lock value is a byte
}

void Triangulation::insert_into(std::span<const Index> order, std::vector<Index> free_cells, Index hint) {
  InsertionOrder identity;
  Builder(*this, identity).update(order, std::move(free_cells), hint);
}

std::size_t Triangulation::memory_bytes() const {
  return points_.capacity() * sizeof(Vec3) + weights_.capacity() * sizeof(double) +
         status_.capacity() * sizeof(PointStatus) + representative_.capacity() * sizeof(Index) +
         cells_.capacity() * sizeof(Cell) + vertex_cell_.capacity() * sizeof(Index);
}

}  // namespace alpha
