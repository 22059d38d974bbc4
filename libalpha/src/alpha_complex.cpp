#include "alpha/alpha_complex.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <tuple>

#include "alpha/error.hpp"

namespace alpha {
namespace {

Simplex cell_simplex(const Triangulation& t, Index c) {
  const auto& v = t.cell(c).v;
  return Simplex(v[0], v[1], v[2], v[3]);
}

double tetra_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z,
               wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  return std::fabs(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6;
}

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  return std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
}

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

AlphaComplex::AlphaComplex(const Triangulation& t) : t_(&t), simplices_(t) {
  const Simplices& s = simplices_;
  ids_ = {Index(t.num_points()), Index(t.num_points() + s.num_edges()),
          Index(t.num_points() + s.num_edges() + s.num_triangles())};
  if (std::size_t(ids_.cells) + t.num_cells() >= kNever) fail("too many simplices for 32-bit ids");
  const std::size_t num_ids = ids_.cells + t.num_cells();
  SizeKernel sizes = size_kernel();
  auto simplex_of = [&](Index g) { return simplex(g); };

  // Top-down interval records, first as global ids of the simplices whose
  // sizes bound them; translated to ranks once the sizes are sorted.
  constexpr Index kInf = kNever;
  // Filtered sizes of all simplices, computed in id order (cells, and the
  // edges and triangles numbered by cell, are stored in spatial order).
  std::vector<Size> size_of(num_ids);
  for (Index g = 0; g < num_ids; ++g)
    if (g < ids_.cells || !t.is_infinite(g - ids_.cells)) size_of[g] = sizes.size(simplex_of(g));
  auto size = [&](Index g) -> const Size& { return size_of[g]; };
  std::uint64_t filtered_compares = 0;
  auto less = [&](Index a, Index b) {  // exact, kInf last
    if (a == b) return false;
    if (a == kInf || b == kInf) return b == kInf;
    const int f = compare_filtered(size(a), size(b));  // decides almost always
    if (f != kUndecided) return ++filtered_compares, f < 0;
    return sizes.compare(simplex_of(a), size(a), simplex_of(b), size(b)) < 0;
  };
  auto min_of = [&](Index a, Index b) { return less(b, a) ? b : a; };
  auto max_of = [&](Index a, Index b) { return (a == kInf || b == kInf) ? kInf : less(a, b) ? b : a; };
  struct Record {
    Index entry = kInf, low = kInf, high = kInf;
    bool attached = false;
  };
  std::vector<Record> tri(s.num_triangles()), edg(s.num_edges()), ver(t.num_points());
  // A face stops being singular when its first coface enters, and becomes
  // interior with its last one.
  auto absorb = [&](Record& r, const Record& coface, bool& first) {
    r.low = first ? coface.entry : min_of(r.low, coface.entry);
    r.high = first ? coface.high : max_of(r.high, coface.high);
    first = false;
  };

  for (Index f = 0; f < s.num_triangles(); ++f) {
    const Simplex sf(s.triangle(f)[0], s.triangle(f)[1], s.triangle(f)[2]);
    Record& r = tri[f];
    bool hull = false, first = true;
    for (Index c : s.triangle_cells(f)) {
      if (t.is_infinite(c)) {
        hull = true;
        continue;
      }
      const Index g = ids_.cells + c;
      r.low = min_of(r.low, g);
      r.high = first ? g : max_of(r.high, g);
      first = false;
      const auto& cv = t.cell(c).v;  // the vertex of c off the triangle (sums wrap exactly)
      const Index q = cv[0] + cv[1] + cv[2] + cv[3] - sf.v[0] - sf.v[1] - sf.v[2];
      r.attached = r.attached || sizes.attached(sf, q);
    }
    if (hull) r.high = kInf;
    r.entry = r.attached ? r.low : ids_.triangles + f;
  }
  for (Index e = 0; e < s.num_edges(); ++e) {
    const auto& ev = s.edge(e);
    const Simplex se(ev[0], ev[1]);
    Record& r = edg[e];
    bool first = true;
    for (Index f : s.edge_triangles(e)) {
      absorb(r, tri[f], first);
      const auto& fv = s.triangle(f);
      const Index q = fv[0] + fv[1] + fv[2] - ev[0] - ev[1];
      r.attached = r.attached || sizes.attached(se, q);
    }
    r.entry = r.attached ? r.low : ids_.edges + e;
  }
  for (Index v = 0; v < t.num_points(); ++v) {
    if (t.status(v) != PointStatus::vertex) continue;
    Record& r = ver[v];
    bool first = true;
    for (Index e : s.vertex_edges(v)) {
      absorb(r, edg[e], first);
      const Index q = s.edge(e)[0] == v ? s.edge(e)[1] : s.edge(e)[0];
      r.attached = r.attached || sizes.attached(Simplex(v), q);
    }
    r.entry = r.attached ? r.low : v;
  }

  // The spectrum: sort the referenced sizes by their double value, then
  // exactly within runs of overlapping error intervals.
  std::vector<char> critical(num_ids, 0);
  auto mark = [&](Index g) {
    if (g != kInf) critical[g] = 1;
  };
  for (const auto* records : {&tri, &edg, &ver})
    for (const Record& r : *records) mark(r.entry), mark(r.low), mark(r.high);
  for (Index c = 0; c < t.num_cells(); ++c)
    if (!t.is_infinite(c)) mark(ids_.cells + c);
  std::vector<std::pair<double, Index>> by_value;
  for (Index g = 0; g < num_ids; ++g)
    if (critical[g]) by_value.emplace_back(size(g).value, g);
  std::sort(by_value.begin(), by_value.end());
  std::vector<Index> order(by_value.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = by_value[k].second;
  by_value = {};
  std::vector<Index> rank_of(num_ids, kNever);
  for (std::size_t b = 0; b < order.size();) {
    std::size_t e = b + 1;
    double reach = size(order[b]).value + size(order[b]).error;
    while (e < order.size() && size(order[e]).value - size(order[e]).error <= reach)
      reach = std::max(reach, size(order[e]).value + size(order[e]).error), ++e;
    if (e - b > 1) std::stable_sort(order.begin() + b, order.begin() + e, less);
    for (std::size_t k = b; k < e; ++k) {
      if (k == b || less(order[k - 1], order[k])) spectrum_.push_back(order[k]);
      rank_of[order[k]] = Index(spectrum_.size() - 1);
    }
    b = e;
  }

  auto to_interval = [&](const Record& r) {
    auto rk = [&](Index g) { return g == kInf ? kNever : rank_of[g]; };
    return Interval{rk(r.entry), rk(r.low), rk(r.high), r.attached};
  };
  std::transform(ver.begin(), ver.end(), std::back_inserter(vertex_), to_interval);
  std::transform(edg.begin(), edg.end(), std::back_inserter(edge_), to_interval);
  std::transform(tri.begin(), tri.end(), std::back_inserter(triangle_), to_interval);
  cell_.resize(t.num_cells(), kNever);
  for (Index c = 0; c < t.num_cells(); ++c)
    if (!t.is_infinite(c)) cell_[c] = rank_of[ids_.cells + c];
  size_stats_ = sizes.stats();
  size_stats_.compare.filtered += filtered_compares;
  pairs_ = persistence_pairs(t, s, filtration());
}

Simplex AlphaComplex::simplex(Index g) const {
  const Simplices& s = simplices_;
  if (g < ids_.edges) return Simplex(g);
  if (g < ids_.triangles) return Simplex(s.edge(g - ids_.edges)[0], s.edge(g - ids_.edges)[1]);
  if (g < ids_.cells) {
    const auto& f = s.triangle(g - ids_.triangles);
    return Simplex(f[0], f[1], f[2]);
  }
  return cell_simplex(*t_, g - ids_.cells);
}

double AlphaComplex::spectrum_value(Index rank) const { return size_kernel().rounded_size(simplex(spectrum_[rank])); }

Index AlphaComplex::level(double alpha_sq) const {
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

ClassCounts AlphaComplex::counts(Index level) const {
  ClassCounts n{};
  for (Index v = 0; v < vertex_.size(); ++v)
    if (t_->status(v) == PointStatus::vertex) ++n[0][int(classify(vertex_[v], level))];
  for (const Interval& i : edge_) ++n[1][int(classify(i, level))];
  for (const Interval& i : triangle_) ++n[2][int(classify(i, level))];
  for (Index c = 0; c < cell_.size(); ++c)
    if (!t_->is_infinite(c)) ++n[3][int(classify_cell(c, level))];
  return n;
}

FiltrationRanks AlphaComplex::filtration() const {
  FiltrationRanks r;
  auto entries = [](const std::vector<Interval>& in, std::vector<Index>& out) {
    out.reserve(in.size());
    for (const Interval& i : in) out.push_back(i.entry);
  };
  entries(vertex_, r.vertex);
  entries(edge_, r.edge);
  entries(triangle_, r.triangle);
  r.cell = cell_;
  return r;
}

std::array<std::size_t, 3> AlphaComplex::betti(Index level) const {
  return level == 0 ? std::array<std::size_t, 3>{0, 0, 0} : betti_at(pairs_, level - 1);
}

Index AlphaComplex::optimal_level() const {
  Index last = 0;
  for (Index v = 0; v < vertex_.size(); ++v)
    if (t_->status(v) == PointStatus::vertex) last = std::max(last, vertex_[v].entry);
  for (const PersistencePair& p : pairs_)
    if (p.dim == 0 && p.death != kNever) last = std::max(last, p.death);
  return last + 1;
}

double AlphaComplex::volume(Index level) const {
  double v = 0;
  for (Index c = 0; c < cell_.size(); ++c) {
    if (cell_[c] >= level) continue;
    const auto& cv = t_->cell(c).v;
    v += tetra_volume(t_->point(cv[0]), t_->point(cv[1]), t_->point(cv[2]), t_->point(cv[3]));
  }
  return v;
}

double AlphaComplex::area(Index level) const {
  double a = 0;
  for (Index f = 0; f < triangle_.size(); ++f) {
    const Classification k = classify(triangle_[f], level);
    if (k != Classification::regular && k != Classification::singular) continue;
    const auto& fv = simplices_.triangle(f);
    a += triangle_area(t_->point(fv[0]), t_->point(fv[1]), t_->point(fv[2]));
  }
  return a;
}

ShapeBoundary AlphaComplex::boundary(Index level) const {
  ShapeBoundary b;
  for (Index f = 0; f < triangle_.size(); ++f) {
    const Classification k = classify(triangle_[f], level);
    auto fv = simplices_.triangle(f);  // its normal points into triangle_cells(f)[0]
    if (k == Classification::singular) b.singular_triangles.push_back(fv);
    if (k != Classification::regular) continue;
    const Index inside = simplices_.triangle_cells(f)[0];
    if (!t_->is_infinite(inside) && cell_[inside] < level) std::swap(fv[1], fv[2]);
    b.triangles.push_back(fv);
  }
  for (Index e = 0; e < edge_.size(); ++e)
    if (classify(edge_[e], level) == Classification::singular) b.singular_edges.push_back(simplices_.edge(e));
  for (Index v = 0; v < vertex_.size(); ++v)
    if (t_->status(v) == PointStatus::vertex && classify(vertex_[v], level) == Classification::singular)
      b.singular_vertices.push_back(v);
  return b;
}

std::size_t AlphaComplex::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return simplices_.memory_bytes() + bytes(vertex_) + bytes(edge_) + bytes(triangle_) + bytes(cell_) +
         bytes(spectrum_) + bytes(pairs_);
}

}  // namespace alpha
