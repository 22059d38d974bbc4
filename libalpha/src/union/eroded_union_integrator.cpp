// SPDX-License-Identifier: Apache-2.0
// ErodedUnion's integrals and nearest-point queries, through its
// Integrator (eroded_union_integrator.hpp): the whole layer, the cells'
// shares, Nearby.
#include "union/eroded_union_integrator.hpp"

#include <cmath>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace alpha {

LayerShare ErodedUnion::layer() const { return measure(nullptr); }

LayerShare ErodedUnion::layer(std::vector<LayerShare>& per_ball) const {
  per_ball.assign(shell_factor_.size(), {});
  return measure(&per_ball);
}

LayerShare ErodedUnion::measure(std::vector<LayerShare>* per_ball) const {
  const AlphaComplex& ac = balls_->complex();
  const Simplices& s = ac.simplices();
  const Integrator in(*this);
  LayerSum sum;
  for (std::size_t i = 0; i < shell_factor_.size(); ++i) {
    sum.add({shell_factor_[i] * balls_->ball_areas()[i], contact_factor_[i] * balls_->ball_areas()[i]});
    if (per_ball) in.shell_shares(Index(i), *per_ball);
  }
  for (Index e = 0; e < s.num_edges(); ++e)
    if (arc_start_[e] != arc_start_[e + 1]) sum.add(in.all_arcs(e, per_ball));
  for (std::size_t v = 0; v < vertices_.size(); ++v) sum.add(in.cone(v, per_ball));
  return sum.value();
}

LayerShare ErodedUnion::cell_share(Index c) const { return share(Integrator(*this), c); }

LayerShare ErodedUnion::cells_share(std::span<const Index> cells) const {
  const Integrator in(*this);
  LayerShare out;
  for (Index c : cells) {
    const LayerShare x = share(in, c);
    out.volume += x.volume;
    out.area += x.area;
  }
  return out;
}

LayerShare ErodedUnion::share(const Integrator& in, Index c) const {
  const AlphaComplex& ac = balls_->complex();
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  if (t.is_infinite(c)) return {};
  LayerSum sum;
  const auto& v = t.cell(c).v;
  for (int k = 0; k < 4; ++k)
    if (shell_factor_[v[k]] > 0 || contact_factor_[v[k]] > 0) {
      const double patch = patch_area(c, k);
      sum.add({shell_factor_[v[k]] * patch, contact_factor_[v[k]] * patch});
    }
  for (int x = 0; x < 4; ++x)
    for (int y = x + 1; y < 4; ++y) {
      const Index e = s.find_edge(v[x], v[y]);
      if (arc_start_[e] != arc_start_[e + 1]) sum.add(in.cell_arcs(c, x, y, e));
    }
  for (int k = 0; k < 4; ++k) {
    const Index f = s.cell_triangle(c, k);
    for (std::size_t p = vertex_start_[f]; p < vertex_start_[f + 1]; ++p)
      if (vertices_[p].cell == c) sum.add(in.cone(p));
  }
  return sum.value();
}


ErodedUnion::Nearby::Nearby(std::shared_ptr<const Integrator> in, std::unique_ptr<Hood> hood)
    : in_(std::move(in)), hood_(std::move(hood)) {}
ErodedUnion::Nearby::Nearby(Nearby&&) noexcept = default;
ErodedUnion::Nearby& ErodedUnion::Nearby::operator=(Nearby&&) noexcept = default;
ErodedUnion::Nearby::~Nearby() = default;

ErodedUnion::Nearby ErodedUnion::nearby(const Vec3& center, double reach) const {
  auto hood = std::make_unique<Nearby::Hood>();
  auto in = std::make_shared<const Integrator>(*this);
  in->gather(center, reach, *hood);
  return Nearby(std::move(in), std::move(hood));
}

ErodedUnion::Nearby ErodedUnion::Nearby::narrowed(const Vec3& center, double reach) const {
  auto hood = std::make_unique<Hood>();
  in_->narrow(*hood_, center, reach, *hood);
  for (const auto& [c, w] : hood_->buried)
    if (in_->buried_near(c, w, center, reach)) hood->buried.emplace_back(c, w);
  return Nearby(in_, std::move(hood));
}

ErodedUnion::Nearest ErodedUnion::Nearby::nearest(const Vec3& x, double limit) const {
  return in_->nearest(*hood_, x, limit);
}

double ErodedUnion::Nearby::outside_by(const Vec3& x) const {
  double d = HUGE_VAL;
  for (const Hood::Ball& b : hood_->balls) d = std::min(d, norm(x - b.c) - b.radius);
  for (const auto& [c, w] : hood_->buried) d = std::min(d, norm(x - c) - std::sqrt(w));
  return d;
}
}  // namespace alpha
