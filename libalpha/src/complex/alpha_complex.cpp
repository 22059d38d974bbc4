// SPDX-License-Identifier: Apache-2.0
#include "alpha/alpha_complex.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <iterator>
#include <numeric>
#include <optional>
#include <tuple>

#include "alpha/error.hpp"
#include "alpha/uninitialized_allocator.hpp"
#include "numerics/exact_size.hpp"
#include "util/huge_pages.hpp"
#include "util/parallel.hpp"
#include "util/prefetch.hpp"
#include "util/radix_sort.hpp"

namespace alpha {
namespace {

Simplex cell_simplex(const Triangulation& t, Index c) {
  const auto& v = t.cell(c).v;
  return Simplex(v[0], v[1], v[2], v[3]);
}

// The points (and weights) copied in the order in which the cells first use
// them. Cells are stored in spatial order but vertex ids are input indices,
// which may be random in space; the size and attachment tests read points
// at every step, and local copies keep those reads in cache.
class LocalPoints {
public:
  explicit LocalPoints(const Triangulation& t) : local_(t.num_points(), kNone) {
    points_.reserve(t.num_vertices());
    if (t.weighted()) weights_.reserve(t.num_vertices());
    const auto cells = t.cells();
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (c + kAhead < cells.size())
        for (const Index v : cells[c + kAhead].v)
          if (v != kInfinite) alpha::prefetch(&local_[v]), alpha::prefetch(&t.point(v));
      for (const Index v : cells[c].v)
        if (v != kInfinite && local_[v] == kNone) {
          local_[v] = Index(points_.size());
          points_.push_back(t.point(v));
          if (t.weighted()) weights_.push_back(t.weight(v));
        }
    }
    small_integers_ = all_small_integers(points_.data(), weights(), points_.size());
    in_filter_range_ = all_in_filter_range(points_.data(), weights(), points_.size());
  }
  SizeKernel kernel() const { return SizeKernel(points_.data(), weights(), small_integers_, in_filter_range_); }
  Index operator[](Index v) const { return local_[v]; }
  // The local indices are read by input index, at random places.
  void prefetch(Index v) const {
    if (v != kInfinite) alpha::prefetch(&local_[v]);
  }
  template <class Vertices>
  void prefetch_all(const Vertices& vs) const {
    for (const Index v : vs) prefetch(v);
  }
  Simplex operator()(Simplex s) const {
    for (int i = 0; i < s.n; ++i) s.v[i] = local_[s.v[i]];
    return s;
  }

private:
  std::vector<Index> local_;  // by input index
  std::vector<Vec3> points_;
  std::vector<double> weights_;
  bool small_integers_ = false;  // grids: their ties decided in doubles
  bool in_filter_range_ = false;  // the filter checks no value
  const double* weights() const { return weights_.empty() ? nullptr : weights_.data(); }
};

}  // namespace

const char* to_string(Classification c) {
  switch (c) {
    case Classification::exterior: return "exterior";
    case Classification::singular: return "singular";
    case Classification::regular: return "regular";
    case Classification::interior: return "interior";
  }
  return "?";
}

SizeKernel AlphaComplex::size_kernel() const {
  return SizeKernel(t_->points().data(), t_->weighted() ? t_->weights().data() : nullptr);
}

AlphaComplex::AlphaComplex(const Triangulation& t, unsigned threads)
    : t_(&t),
      threads_(t.num_vertices() < kThreadsFrom ? 1 : std::clamp(threads, 1u, kMaxThreads)),
      simplices_(t, threads_) {
  const Simplices& s = simplices_;
  ids_ = {Index(t.num_points()), Index(t.num_points() + s.num_edges()),
          Index(t.num_points() + s.num_edges() + s.num_triangles())};
  if (std::size_t(ids_.cells) + t.num_cells() >= kNever) fail("too many simplices for 32-bit ids", ErrorKind::LimitExceeded);
  rank_critical();
  bound_faces();
}

const std::vector<PersistencePair>& AlphaComplex::persistence() const {
  std::call_once(pairs_->once,
                 [this] { pairs_->pairs = persistence_pairs(*t_, simplices_, ranks_, false, threads_); });
  return pairs_->pairs;
}

void AlphaComplex::rank_critical() {
  const Triangulation& t = *t_;
  const Simplices& s = simplices_;
  const LocalPoints local(t);
  // A kernel for each thread, its counters on cache lines of its own (they
  // change at every test), summed at the end.
  struct alignas(64) ThreadKernel {
    SizeKernel sizes;
  };
  std::vector<ThreadKernel> kernels(threads_, {local.kernel()});

  // Attachment depends on no size: a face is attached when the vertex of a
  // coface opposite to it lies inside its smallest orthogonal sphere. (Sums
  // of vertex ids wrap exactly: they give the one vertex not in the face.)
  // Edges and vertices are tested from their cofaces, walked in id order;
  // triangles below, with their sizes. Without weights no vertex is
  // attached: its sphere is the point itself.
  vertex_attached_.resize(t.num_points());
  edge_attached_.resize(s.num_edges());
  triangle_attached_.resize(s.num_triangles());
  // Flags set by tests of items [0, n) on the threads: test(sizes, flags,
  // item) with the thread's kernel and flags.
  const auto mark = [&](std::vector<bool>& flags, std::size_t n, auto test) {
    ThreadFlags marked(flags, threads_);
    in_parallel(threads_, n, [&](unsigned k, std::size_t begin, std::size_t end) {
      for (Index i = Index(begin); i < end; ++i) test(kernels[k].sizes, marked.of(k), i);
    });
    marked.merge();
  };
  mark(edge_attached_, s.num_triangles(), [&](SizeKernel& sizes, std::vector<bool>& attached, Index f) {
    if (f + kAhead < s.num_triangles()) local.prefetch_all(s.triangle(f + kAhead));
    const auto fv = s.triangle(f);
    for (int k = 0; k < 3; ++k) {  // edge k is opposite vertex k
      const Index e = s.triangle_edges(f)[k];
      if (!attached[e])
        attached[e] = sizes.attached(local(Simplex(fv[(k + 1) % 3], fv[(k + 2) % 3])), local[fv[k]]);
    }
  });
  if (t.weighted())
    mark(vertex_attached_, s.num_edges(), [&](SizeKernel& sizes, std::vector<bool>& attached, Index e) {
      if (e + kAhead < s.num_edges()) local.prefetch_all(s.edge(e + kAhead));
      for (int k = 0; k < 2; ++k) {
        const Index v = s.edge(e)[k];
        if (!attached[v]) attached[v] = sizes.attached(local(Simplex(v)), local[s.edge(e)[1 - k]]);
      }
    });

  // The critical values are the sizes of the finite cells and of the
  // unattached faces (an attached face enters with a coface, and mu_low,
  // mu_high are entries of cofaces). Sorted by the lower ends of their
  // error intervals (in global id order among equal ones), then exactly
  // within each run of overlapping intervals. By lower ends, not values:
  // then no later interval can reach back into a run already closed (one
  // with a large error could, sorted by value). An interval is kept as its
  // lower end, ordered as an unsigned integer (the sort's key, read in
  // place), and its width as a float rounded up.
  struct Critical {
    std::uint64_t low;
    float width;
    Index id;  // global
  };
  // Doubles ordered as unsigned integers: flip all bits of negatives, the
  // sign bit of the others.
  const auto ordered = [](double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    return bits ^ (bits >> 63 ? ~std::uint64_t(0) : std::uint64_t(1) << 63);
  };
  const auto low = [](const Critical& c) {
    return std::bit_cast<double>(c.low >> 63 ? c.low ^ std::uint64_t(1) << 63 : ~c.low);
  };
  // The next float up from a finite x >= +0 (std::nextafter's result, from
  // the bits: no library call for each of tens of millions of values).
  const auto next_up = [](float x) { return std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) + 1); };
  const auto high = [&](const Critical& c) {
    const double x = low(c) + double(c.width);
    return std::isnan(x) ? HUGE_VAL : x;
  };
  const auto critical = [&](SizeKernel& sizes, Index g, Size z) {
    // Where the filter fails (nearly flat simplices) its value says nothing
    // about the place in the order: take the exact size's nearest double,
    // within half an ulp (an unbounded error if it overflows).
    if (!std::isfinite(z.error) || !std::isfinite(z.value)) {
      const double v = sizes.rounded_size(local(simplex(g)));
      const double gap = std::nextafter(std::fabs(v), HUGE_VAL) - std::fabs(v);
      z = {v, std::isfinite(gap) ? gap : HUGE_VAL};
    }
    float error = float(z.error);
    if (double(error) < z.error) error = next_up(error);
    // The ends; an unbounded error (inf - inf) reaches everywhere.
    double lo = z.value - double(error), hi = z.value + double(error);
    lo = std::isnan(lo) ? -HUGE_VAL : lo + 0.0;  // + 0.0: -0 sorts as 0
    hi = std::isnan(hi) ? HUGE_VAL : hi;
    float width = HUGE_VALF;
    if (std::isfinite(lo) && std::isfinite(hi)) {
      width = float(hi - lo);
      while (lo + double(width) < hi) width = next_up(width);
    }
    return Critical{ordered(lo), width, g};
  };
  // Room for every simplex of a kind at once (below), never touched where
  // not written. The order of the values does not matter: they are sorted
  // on (lower end, id), distinct keys.
  std::vector<Critical, UninitializedAllocator<Critical>> order;
  const std::size_t room = t.num_points() + s.num_edges() + s.num_triangles() + t.num_cells();
  reserve_huge(order, room);
  order.resize(room);
  std::size_t filled = 0;
  // The values of items [0, n) of one kind, on the threads: each share is
  // written from the slot of its first item on, then moved down to follow
  // the previous share; the pages left behind go back. add(k, item, out)
  // writes item's value, if it has one, at out and advances it.
  const auto add_all = [&](std::size_t n, auto add) {
    std::vector<std::array<std::size_t, 2>> written(threads_);
    in_parallel(threads_, n, [&](unsigned k, std::size_t begin, std::size_t end) {
      Critical* const first = order.data() + filled + begin;
      Critical* out = first;
      for (std::size_t i = begin; i < end; ++i) add(k, Index(i), out);
      written[k] = {begin, std::size_t(out - first)};
    });
    const std::size_t base = filled;
    for (const auto& [begin, count] : written) {
      std::memmove(order.data() + filled, order.data() + base + begin, count * sizeof(Critical));
      filled += count;
    }
    discard_unused(order, filled, base + n);
  };
  add_all(t.num_points(), [&](unsigned k, Index v, Critical*& out) {
    if (t.status(v) == PointStatus::vertex && !vertex_attached_[v])
      *out++ = critical(kernels[k].sizes, v, kernels[k].sizes.size(local(Simplex(v))));
  });
  add_all(s.num_edges(), [&](unsigned k, Index e, Critical*& out) {
    if (e + kAhead < s.num_edges()) local.prefetch_all(s.edge(e + kAhead));
    if (!edge_attached_[e])
      *out++ = critical(kernels[k].sizes, ids_.edges + e,
                        kernels[k].sizes.size(local(Simplex(s.edge(e)[0], s.edge(e)[1]))));
  });
  {
    ThreadFlags attached(triangle_attached_, threads_);
    add_all(s.num_triangles(), [&](unsigned k, Index f, Critical*& out) {
      // The other cell may lie anywhere.
      if (f + 2 * kAhead < s.num_triangles()) prefetch(&t.cell(s.triangle_cells(f + 2 * kAhead)[1]));
      if (f + kAhead < s.num_triangles())
        for (const Index c : s.triangle_cells(f + kAhead)) local.prefetch_all(t.cell(c).v);
      const auto fv = s.triangle(f);
      std::array<Index, 2> others;
      std::size_t n = 0;
      for (const Index c : s.triangle_cells(f)) {
        if (t.is_infinite(c)) continue;
        const auto& cv = t.cell(c).v;
        others[n++] = local[cv[0] + cv[1] + cv[2] + cv[3] - fv[0] - fv[1] - fv[2]];
      }
      const std::optional<Size> z =
          kernels[k].sizes.size_unless_attached(local(Simplex(fv[0], fv[1], fv[2])), std::span(others.data(), n));
      attached.of(k)[f] = !z;
      if (z) *out++ = critical(kernels[k].sizes, ids_.triangles + f, *z);
    });
    attached.merge();
  }
  add_all(t.num_cells(), [&](unsigned k, Index c, Critical*& out) {
    if (c + kAhead < t.num_cells()) local.prefetch_all(t.cell(c + kAhead).v);
    if (!t.is_infinite(c))
      *out++ = critical(kernels[k].sizes, ids_.cells + c, kernels[k].sizes.size(local(cell_simplex(t, c))));
  });
  order.resize(filled);
  radix_sort_in_place(std::span(order), [](const Critical& c) { return c.low; },
                      [](const Critical& c) { return c.id; });
  // Entry ranks of the critical simplices (faces: their own size's rank).
  assign_huge(ranks_.vertex, t.num_points(), kNever);
  assign_huge(ranks_.edge, s.num_edges(), kNever);
  assign_huge(ranks_.triangle, s.num_triangles(), kNever);
  assign_huge(ranks_.cell, t.num_cells(), kNever);
  auto set_rank = [&](Index g, Index rank) {
    if (g < ids_.edges) ranks_.vertex[g] = rank;
    else if (g < ids_.triangles) ranks_.edge[g - ids_.edges] = rank;
    else if (g < ids_.cells) ranks_.triangle[g - ids_.triangles] = rank;
    else ranks_.cell[g - ids_.cells] = rank;
  };
  // A run (equal values of symmetric copies, lattices; near ties) is
  // sorted on each member's exact size computed once: k exact evaluations
  // instead of O(k log k) exact comparisons, each evaluating two. Same
  // order: a stable sort by exact value. `value_of` gives order[k]'s size
  // (or nothing: then sort_run returns false and has changed nothing),
  // `values` holds them, `compare` orders two exactly.
  StageCounts run_compares;
  std::vector<std::size_t> by_value;
  std::vector<Critical> run;
  auto count = [&](int c) {
    ++(c != 0 ? run_compares.exact : run_compares.perturbed);
    return c;
  };
  auto sort_run = [&](std::size_t b, std::size_t e, auto& values, auto value_of, auto compare) {
    // One value throughout (a grid's runs): already in order, one rank,
    // and no value kept.
    const auto first = value_of(b);
    if (!first) return false;
    std::size_t same = b + 1;
    for (; same < e; ++same) {
      const auto next = value_of(same);
      if (!next) return false;
      if (count(compare(*first, *next)) != 0) break;
    }
    if (same == e) {
      spectrum_.push_back(order[b].id);
      for (std::size_t k = b; k < e; ++k) set_rank(order[k].id, Index(spectrum_.size() - 1));
      return true;
    }
    // The members before `same` equal `first`: no need to evaluate them again.
    values.assign(same - b, *first);
    for (std::size_t k = same; k < e; ++k) {
      const auto next = value_of(k);
      if (!next) return false;
      values.push_back(*next);
    }
    by_value.resize(e - b);
    std::iota(by_value.begin(), by_value.end(), std::size_t(0));
    auto order_of = [&](std::size_t x, std::size_t y) { return count(compare(values[x], values[y])); };
    std::stable_sort(by_value.begin(), by_value.end(), [&](std::size_t x, std::size_t y) { return order_of(x, y) < 0; });
    run.assign(order.begin() + std::ptrdiff_t(b), order.begin() + std::ptrdiff_t(e));
    for (std::size_t k = b; k < e; ++k) {
      order[k] = run[by_value[k - b]];
      if (k == b || order_of(by_value[k - b - 1], by_value[k - b]) != 0) spectrum_.push_back(order[k].id);
      set_rank(order[k].id, Index(spectrum_.size() - 1));
    }
    return true;
  };
  // Integer input (grids) has its exact sizes in doubles: no GMP for its runs.
  std::vector<SmallFraction> small;
  std::vector<ExactSize> exact;
  auto sort_exactly = [&](std::size_t b, std::size_t e) {
    auto simplex_at = [&](std::size_t k) { return local(simplex(order[k].id)); };
    SizeKernel& sizes = kernels[0].sizes;
    if (sort_run(b, e, small, [&](std::size_t k) { return small_fraction(sizes, simplex_at(k)); }, compare_small))
      return;
    sort_run(b, e, exact, [&](std::size_t k) { return std::optional(exact_fraction(sizes, simplex_at(k))); },
             compare_exact);
  };
  // A run of exact sizes (width 0: integer input whose sizes doubles hold)
  // is one value: already in order, one rank.
  auto exact_run = [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k)
      if (order[k].width != 0) return false;
    spectrum_.push_back(order[b].id);
    for (std::size_t k = b; k < e; ++k) set_rank(order[k].id, Index(spectrum_.size() - 1));
    return true;
  };
  // The spectrum grows as the critical values are read for the last time:
  // their pages go back as it goes (it would otherwise add 4 bytes a value
  // to the peak, 69 MiB at 1e6 points).
  reserve_huge(spectrum_, order.size());
  constexpr std::size_t kDiscardStep = std::size_t(1) << 12;
  for (std::size_t b = 0, read = 0; b < order.size();) {
    if (b - read >= kDiscardStep) discard_read(order, read, b), read = b;
    std::size_t e = b + 1;
    double reach = high(order[b]);
    while (e < order.size() && low(order[e]) <= reach) reach = std::max(reach, high(order[e])), ++e;
    if (e - b > 1) {
      if (!exact_run(b, e)) sort_exactly(b, e);
    } else {
      spectrum_.push_back(order[b].id);
      set_rank(order[b].id, Index(spectrum_.size() - 1));
    }
    b = e;
  }
  release(order);
  spectrum_.shrink_to_fit();

  for (const ThreadKernel& k : kernels) size_stats_ += k.sizes.stats();
  size_stats_.compare += run_compares;
}

void AlphaComplex::bound_faces() {
  const Triangulation& t = *t_;
  const Simplices& s = simplices_;
  // Intervals top-down, in ranks: a face stops being singular when its
  // first coface enters and becomes interior with the last one (never for
  // a hull face: infinite cells have rank kNever); an attached face enters
  // with its first coface. The faces' bounds gather from their cofaces,
  // walked in id order.
  auto absorb = [](Bounds& b, Index entry, Index high) { b.low = std::min(b.low, entry), b.high = std::max(b.high, high); };
  assign_huge(edge_bounds_, s.num_edges(), {kNever, 0});
  for (Index f = 0; f < s.num_triangles(); ++f) {
    Interval i = triangle_interval(f);
    if (i.attached) ranks_.triangle[f] = i.entry = i.mu_low;
    for (const Index e : s.triangle_edges(f)) absorb(edge_bounds_[e], i.entry, i.mu_high);
  }
  assign_huge(vertex_bounds_, t.num_points(), {kNever, 0});
  for (Index e = 0; e < s.num_edges(); ++e) {
    if (edge_attached_[e]) ranks_.edge[e] = edge_bounds_[e].low;
    for (const Index v : s.edge(e)) absorb(vertex_bounds_[v], ranks_.edge[e], edge_bounds_[e].high);
  }
  for (Index v = 0; v < t.num_points(); ++v) {
    if (t.status(v) != PointStatus::vertex) vertex_bounds_[v] = {};
    else if (vertex_attached_[v]) ranks_.vertex[v] = vertex_bounds_[v].low;
  }
}

Simplex AlphaComplex::simplex(Index g) const {
  const Simplices& s = simplices_;
  if (g < ids_.edges) return Simplex(g);
  if (g < ids_.triangles) return Simplex(s.edge(g - ids_.edges)[0], s.edge(g - ids_.edges)[1]);
  if (g < ids_.cells) {
    const auto f = s.triangle(g - ids_.triangles);
    return Simplex(f[0], f[1], f[2]);
  }
  return cell_simplex(*t_, g - ids_.cells);
}

double AlphaComplex::spectrum_value(Index rank) const { return size_kernel().rounded_size(simplex(spectrum_[rank])); }

void AlphaComplex::spectrum_values(std::span<const Index> ranks, std::span<double> values) const {
  assert(values.size() == ranks.size());
  // Each value reads the spectrum, a simplex record (an edge's, a triangle's
  // facet code, a cell) and then its points: one phase over a block for
  // each read, prefetching ahead (prefetch.hpp).
  constexpr std::size_t kBlock = 256;
  const Triangulation& t = *t_;
  const Simplices& s = simplices_;
  const auto prefetch_points = [&](const Simplex& x) {
    for (int i = 0; i < x.n; ++i) {
      prefetch(&t.point(x.v[i]));
      if (t.weighted()) prefetch(&t.weights()[x.v[i]]);
    }
  };
  // The record a simplex's vertices are read from first.
  const auto prefetch_record = [&](Index g) {
    if (g < ids_.edges) prefetch(&t.point(g));
    else if (g < ids_.triangles) prefetch(&s.edge(g - ids_.edges));
    else if (g < ids_.cells) prefetch(s.triangle_record(g - ids_.triangles));
    else prefetch(&t.cell(g - ids_.cells));
  };
  const SizeKernel sizes = size_kernel();
  std::array<Index, kBlock> id;
  std::array<Simplex, kBlock> simplex_of;
  for (std::size_t first = 0; first < ranks.size(); first += kBlock) {
    const std::size_t n = std::min(kBlock, ranks.size() - first);
    const Index* r = ranks.data() + first;
    for (std::size_t j = 0; j < n; ++j) {
      if (j + kAhead < n) prefetch(&spectrum_[r[j + kAhead]]);
      id[j] = spectrum_[r[j]];
    }
    for (std::size_t j = 0; j < n + kAhead; ++j) {
      if (j < n) prefetch_record(id[j]);
      // A triangle's vertices are read from its cell, a record further.
      if (j >= kAhead && id[j - kAhead] >= ids_.triangles && id[j - kAhead] < ids_.cells)
        prefetch(&t.cell(s.triangle_cell(id[j - kAhead] - ids_.triangles)));
    }
    for (std::size_t j = 0; j < n + kAhead; ++j) {
      if (j < n) prefetch_points(simplex_of[j] = simplex(id[j]));
      if (j >= kAhead) values[first + j - kAhead] = sizes.rounded_size(simplex_of[j - kAhead]);
    }
  }
}

Index AlphaComplex::level(double alpha_sq) const {
  if (std::isnan(alpha_sq)) fail("alpha complex: alpha_sq is not a number", ErrorKind::Misuse);
  SizeKernel sizes = size_kernel();
  // First rank whose value exceeds alpha_sq.
  Index lo = 0, hi = Index(spectrum_.size());
  while (lo < hi) {
    const Index mid = lo + (hi - lo) / 2;
    if (sizes.compare(simplex(spectrum_[mid]), alpha_sq) <= 0) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

Classification AlphaComplex::classify(const Interval& i, Index level) {
  if (i.entry == kNever || i.entry >= level) return Classification::exterior;
  if (!i.attached && (i.mu_low == kNever || i.mu_low >= level)) return Classification::singular;
  if (i.mu_high == kNever || i.mu_high >= level) return Classification::regular;
  return Classification::interior;
}

Interval AlphaComplex::triangle_interval(Index f) const {
  const auto c = simplices_.triangle_cells(f);
  const Index a = ranks_.cell[c[0]], b = ranks_.cell[c[1]];
  return {ranks_.triangle[f], std::min(a, b), std::max(a, b), triangle_attached_[f]};
}

ClassCounts AlphaComplex::counts(Index level) const {
  ClassCounts n{};
  for (Index v = 0; v < t_->num_points(); ++v)
    if (t_->status(v) == PointStatus::vertex) ++n[0][int(classify(vertex_interval(v), level))];
  for (Index e = 0; e < simplices_.num_edges(); ++e) ++n[1][int(classify(edge_interval(e), level))];
  for (Index f = 0; f < simplices_.num_triangles(); ++f) ++n[2][int(classify(triangle_interval(f), level))];
  for (Index c = 0; c < t_->num_cells(); ++c)
    if (!t_->is_infinite(c)) ++n[3][int(classify_cell(c, level))];
  return n;
}

FiltrationRanks AlphaComplex::filtration() const { return ranks_; }

std::array<std::size_t, 3> AlphaComplex::betti(Index level) const {
  return level == 0 ? std::array<std::size_t, 3>{0, 0, 0} : betti_at(persistence(), level - 1);
}

Index AlphaComplex::optimal_level() const {
  Index last = 0;
  for (Index v = 0; v < t_->num_points(); ++v)
    if (t_->status(v) == PointStatus::vertex) last = std::max(last, ranks_.vertex[v]);
  for (const PersistencePair& p : persistence())
    if (p.dim == 0 && p.death != kNever) last = std::max(last, p.death);
  return last + 1;
}

double AlphaComplex::volume(Index level) const {
  double v = 0;
  for (Index c = 0; c < t_->num_cells(); ++c) {
    if (ranks_.cell[c] >= level) continue;
    const auto& cv = t_->cell(c).v;
    v += tetrahedron_volume(t_->point(cv[0]), t_->point(cv[1]), t_->point(cv[2]), t_->point(cv[3]));
  }
  return v;
}

double AlphaComplex::area(Index level) const {
  double a = 0;
  for (Index f = 0; f < simplices_.num_triangles(); ++f) {
    const Classification k = classify(triangle_interval(f), level);
    if (k != Classification::regular && k != Classification::singular) continue;
    const auto& fv = simplices_.triangle(f);
    a += triangle_area(t_->point(fv[0]), t_->point(fv[1]), t_->point(fv[2]));
  }
  return a;
}

ShapeBoundary AlphaComplex::boundary(Index level) const {
  ShapeBoundary b;
  for (Index f = 0; f < simplices_.num_triangles(); ++f) {
    const Classification k = classify(triangle_interval(f), level);
    auto fv = simplices_.triangle(f);  // its normal points into triangle_cells(f)[0]
    if (k == Classification::singular) b.singular_triangles.push_back(fv);
    if (k != Classification::regular) continue;
    const Index inside = simplices_.triangle_cells(f)[0];
    if (!t_->is_infinite(inside) && ranks_.cell[inside] < level) std::swap(fv[1], fv[2]);
    b.triangles.push_back(fv);
  }
  for (Index e = 0; e < simplices_.num_edges(); ++e)
    if (classify(edge_interval(e), level) == Classification::singular) b.singular_edges.push_back(simplices_.edge(e));
  for (Index v = 0; v < t_->num_points(); ++v)
    if (t_->status(v) == PointStatus::vertex && classify(vertex_interval(v), level) == Classification::singular)
      b.singular_vertices.push_back(v);
  return b;
}

std::size_t AlphaComplex::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  auto bits = [](const std::vector<bool>& v) { return v.capacity() / 8; };
  return simplices_.memory_bytes() + bytes(ranks_.vertex) + bytes(ranks_.edge) + bytes(ranks_.triangle) +
         bytes(ranks_.cell) + bytes(vertex_bounds_) + bytes(edge_bounds_) + bits(vertex_attached_) +
         bits(edge_attached_) + bits(triangle_attached_) + bytes(spectrum_) + bytes(pairs_->pairs);
}

}  // namespace alpha
