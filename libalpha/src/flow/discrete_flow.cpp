// SPDX-License-Identifier: Apache-2.0
#include "alpha/discrete_flow.hpp"

namespace alpha {

DiscreteFlow::DiscreteFlow(const AlphaComplex& ac, Index level)
    : level_(level), state_(ac.triangulation().num_cells(), 0), region_(ac.triangulation().num_cells(), kNone) {
  const Triangulation& t = ac.triangulation();
  const Simplices& s = ac.simplices();
  SizeKernel sizes(t.points().data(), t.weighted() ? t.weights().data() : nullptr);
  const Index nc = Index(t.num_cells());
  auto facet_empty = [&](Index f) { return ac.triangle_interval(f).entry >= level; };

  for (Index c = 0; c < nc; ++c) {
    if (t.is_infinite(c)) {
      state_[c] = kEmpty | kOutside;
      continue;
    }
    if (ac.cell_entry(c) < level) continue;
    std::uint8_t st = kEmpty;
    for (int k = 0; k < 4; ++k) {
      const Index f = s.cell_triangle(c, k);
      // Only an attached triangle can separate a cell from its orthocenter.
      if (!facet_empty(f) || !ac.triangle_interval(f).attached) continue;
      const auto& fv = s.triangle(f);
      if (sizes.attached(Simplex(fv[0], fv[1], fv[2]), t.cell(c).v[k])) st |= std::uint8_t(1u << k);
    }
    state_[c] = st;
  }

  // Outside: everything that flows, possibly through other cells, into an
  // infinite cell. Walk the flow backwards from the infinite cells.
  std::vector<Index> stack;
  for (Index c = 0; c < nc; ++c)
    if (t.is_infinite(c)) stack.push_back(c);
  while (!stack.empty()) {
    const Index x = stack.back();
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const Index c = t.cell(x).n[k];
      if (state_[c] & kOutside) continue;
      if ((state_[c] & kEmpty) && (state_[c] & (1u << t.mirror_index(x, k)))) {
        state_[c] |= kOutside;
        stack.push_back(c);
      }
    }
  }

  // Regions: the remaining empty cells joined through empty facets.
  for (Index seed = 0; seed < nc; ++seed) {
    if ((state_[seed] & (kEmpty | kOutside)) != kEmpty || region_[seed] != kNone) continue;
    const Index id = Index(num_regions_++);
    region_[seed] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Index c = stack.back();
      stack.pop_back();
      for (int k = 0; k < 4; ++k) {
        const Index n = t.cell(c).n[k];
        if ((state_[n] & (kEmpty | kOutside)) != kEmpty || region_[n] != kNone) continue;
        if (!facet_empty(s.cell_triangle(c, k))) continue;
        region_[n] = id;
        stack.push_back(n);
      }
    }
  }
}

}  // namespace alpha
