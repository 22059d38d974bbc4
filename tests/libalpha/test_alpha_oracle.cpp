// SPDX-License-Identifier: Apache-2.0
// CGAL and GUDHI as independent oracles of the alpha complex itself:
//
//  1. CGAL's Alpha_shape_3 in GENERAL mode on an exact kernel (Epeck: every
//     alpha value and every comparison is exact) must classify the simplices
//     exactly as we do, at many alpha values, and have the same spectrum.
//  2. GUDHI's Alpha_complex (its own filtration code on CGAL's dD Epeck_d
//     triangulation, not Alpha_shape_3) with Z/2 persistent cohomology must
//     give the same persistence diagram (pairs of positive length, and the
//     infinite ones) as ours.
//  3. GUDHI's Betti numbers (from its intervals) must equal ours at many alpha.
//
// Generic inputs (random doubles, random weights) have a unique Delaunay /
// regular triangulation, so everything is compared simplex count by simplex
// count. Degenerate inputs (integer grid, points on a sphere) do not: there
// only triangulation-independent quantities are compared (see the comments
// in `compare_with_cgal`); persistence diagrams and Betti numbers are
// triangulation-independent anyway (the alpha complex is homotopy equivalent
// to the union of balls, by the nerve theorem, whatever the triangulation).
#include <catch2/catch.hpp>

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Epeck_d.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <gudhi/Alpha_complex.h>
#include <gudhi/Persistent_cohomology.h>
#include <gudhi/Simplex_tree.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/triangulation.hpp"
#include "point_sets.hpp"

using alpha::AlphaComplex;
using alpha::ClassCounts;
using alpha::Index;
using alpha::Vec3;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------- inputs

struct Input {
  std::string name;
  std::vector<Vec3> points;
  std::vector<double> weights;  // empty: unweighted
  bool generic;                 // the triangulation is unique
};

std::vector<Input> generic_inputs() {
  std::vector<Input> in;
  in.push_back({"random 200", testing::random_points(200, 71), {}, true});
  in.push_back({"random 2000", testing::random_points(2000, 72), {}, true});
  // About one point per unit volume and weights (squared radii) up to 1:
  // enough overlap that some points are hidden.
  for (std::size_t n : {200, 2000}) {
    in.push_back({"weighted random " + std::to_string(n), testing::random_points(n, 80 + n, std::cbrt(double(n))),
                  testing::random_weights(n, 90 + n, 0.0, 1.0), true});
  }
  // Negative weights too: sizes (vertices' -w included) of both signs.
  in.push_back({"weighted random 500, weights in [-0.5, 1)", testing::random_points(500, 75, std::cbrt(500.0)),
                testing::random_weights(500, 76, -0.5, 1.0), true});
  // Integer grid with random weights: degenerate coordinates, but generic
  // weights make the regular triangulation unique again; weights up to 1.5
  // for unit spacing hide some points.
  in.push_back({"grid 5^3, random weights in [0, 1.5)", testing::grid_points(5), testing::random_weights(125, 77, 0.0, 1.5),
                true});
  // A weighted random set and its copy turned by 90 degrees about z,
  // (x, y, z) -> (-y, x, z), exact in doubles: every size of the copy ties
  // exactly with the original's, with full-precision coordinates (GMP, not
  // 128-bit), as in a symmetric assembly. Still generic: a sphere through
  // five points is not forced by the symmetry.
  {
    Input twin{"weighted random 300 and its copy turned 90 degrees", testing::random_points(300, 78, std::cbrt(300.0)),
               testing::random_weights(300, 79, 0.0, 1.0), true};
    for (std::size_t i = 0; i < 300; ++i) {
      const Vec3 p = twin.points[i];
      twin.points.push_back({-p.y, p.x, p.z});
      twin.weights.push_back(twin.weights[i]);
    }
    in.push_back(std::move(twin));
  }
  return in;
}

std::vector<Input> degenerate_inputs() {
  std::vector<Input> in;
  in.push_back({"grid 5^3", testing::grid_points(5), {}, false});
  in.push_back({"sphere r^2 = 50", testing::sphere_points(50), {}, false});  // 84 cospherical points
  // Equal weights: the power diagram is the Voronoi diagram, as degenerate
  // as the grid's, and every size is shifted by -0.3 (negative ones too).
  in.push_back({"grid 5^3, equal weights 0.3", testing::grid_points(5), std::vector<double>(125, 0.3), false});
  return in;
}

std::vector<Input> all_inputs() {
  auto in = generic_inputs();
  for (auto& d : degenerate_inputs()) in.push_back(std::move(d));
  return in;
}

// Ours, built once per input.
struct Ours {
  alpha::Triangulation t;
  AlphaComplex a;
  explicit Ours(const Input& in) : t(in.points, in.weights), a(t) {}
};

// Probe values of alpha^2: below and above everything, every sampled
// critical value (its nearest double: exactly AT it when representable) and
// a value between it and the next one.
std::vector<double> probe_alphas(const AlphaComplex& a, std::size_t samples) {
  const std::size_t m = a.spectrum_size();
  std::vector<std::size_t> ranks;
  for (std::size_t k = 0; k < std::min<std::size_t>(m, 4); ++k) ranks.push_back(k);
  for (std::size_t i = 0; i < samples && m > 1; ++i) ranks.push_back(i * (m - 1) / (samples - 1));
  for (std::size_t k = m - std::min<std::size_t>(m, 4); k < m; ++k) ranks.push_back(k);
  std::sort(ranks.begin(), ranks.end());
  ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());

  std::vector<double> alphas{a.spectrum_value(0) - 1};
  for (std::size_t k : ranks) {
    const double v = a.spectrum_value(Index(k));
    alphas.push_back(v);
    if (k + 1 < m) alphas.push_back(v + (a.spectrum_value(Index(k + 1)) - v) / 2);
  }
  alphas.push_back(a.spectrum_value(Index(m - 1)) + 1);
  return alphas;
}

std::string counts_string(const ClassCounts& n) {
  std::ostringstream s;
  for (int d = 0; d < 4; ++d) {
    s << "dim " << d << " [ext sing reg int] =";
    for (int k = 0; k < 4; ++k) s << ' ' << n[d][k];
    s << (d < 3 ? "; " : "");
  }
  return s.str();
}

// Euler characteristic of the alpha complex (the non-exterior simplices).
long euler(const ClassCounts& n) {
  long chi = 0;
  for (int d = 0; d < 4; ++d) chi += (d % 2 ? -1L : 1L) * long(n[d][1] + n[d][2] + n[d][3]);
  return chi;
}

// Connected components of the interior cells, adjacent through triangles
// (CGAL's number_of_solid_components).
std::size_t solid_components(const AlphaComplex& a, Index level) {
  const auto& t = a.triangulation();
  std::vector<Index> parent(t.num_cells());
  std::iota(parent.begin(), parent.end(), Index(0));
  auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto inside = [&](Index c) { return !t.is_infinite(c) && a.cell_entry(c) < level; };
  std::size_t components = 0;
  for (Index c = 0; c < t.num_cells(); ++c) {
    if (!inside(c)) continue;
    ++components;
    for (Index n : t.cell(c).n)
      if (inside(n) && find(n) != find(c)) parent[find(n)] = find(c), --components;
  }
  return components;
}

// ------------------------------------------------------------------ CGAL

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using NT = EK::FT;  // exact (lazy GMP rationals): CGAL's alpha values are exact
using DelaunayAS = CGAL::Alpha_shape_3<CGAL::Delaunay_triangulation_3<
    EK, CGAL::Triangulation_data_structure_3<CGAL::Alpha_shape_vertex_base_3<EK>, CGAL::Alpha_shape_cell_base_3<EK>>>>;
using RegularAS = CGAL::Alpha_shape_3<CGAL::Regular_triangulation_3<
    EK, CGAL::Triangulation_data_structure_3<
            CGAL::Alpha_shape_vertex_base_3<EK, CGAL::Regular_triangulation_vertex_base_3<EK>>,
            CGAL::Alpha_shape_cell_base_3<EK, CGAL::Regular_triangulation_cell_base_3<EK>>>>>;
static_assert(std::is_same_v<DelaunayAS::NT, NT> && std::is_same_v<RegularAS::NT, NT>);

EK::Point_3 bare(const EK::Point_3& p) { return p; }
EK::Point_3 bare(const EK::Weighted_point_3& p) { return p.point(); }

// CGAL's counts with the same layout as ours (the enums agree:
// EXTERIOR, SINGULAR, REGULAR, INTERIOR).
template <class AS>
ClassCounts cgal_counts(const AS& as, const NT& alpha) {
  static_assert(AS::EXTERIOR == 0 && AS::SINGULAR == 1 && AS::REGULAR == 2 && AS::INTERIOR == 3);
  ClassCounts n{};
  for (auto v : as.finite_vertex_handles()) ++n[0][as.classify(v, alpha)];
  for (const auto& e : as.finite_edges()) ++n[1][as.classify(e, alpha)];
  for (const auto& f : as.finite_facets()) ++n[2][as.classify(f, alpha)];
  for (auto c : as.finite_cell_handles()) ++n[3][as.classify(c, alpha)];
  return n;
}

template <class AS>
double cgal_volume(const AS& as, const NT& alpha) {
  double v = 0;
  for (auto c : as.finite_cell_handles())
    if (as.classify(c, alpha) == AS::INTERIOR)
      v += CGAL::to_double(CGAL::volume(bare(c->vertex(0)->point()), bare(c->vertex(1)->point()),
                                        bare(c->vertex(2)->point()), bare(c->vertex(3)->point())));
  return v;
}

// Whether d is a double nearest to the exact x (either one on a tie).
bool is_nearest_double(const NT& x, double d) {
  const NT e = CGAL::abs(x - NT(d));
  return e <= CGAL::abs(x - NT(std::nextafter(d, kInf))) && e <= CGAL::abs(x - NT(std::nextafter(d, -kInf)));
}

// The spectra must agree value by value. On degenerate inputs too: every
// critical value is the size of a Delaunay polytope or of one of its faces
// (a cell or a Gabriel simplex of a triangulated polytope P has P's size, an
// internal attached one enters with P), so the set is independent of the
// triangulation.
template <class AS>
void check_spectrum(const AS& as, const AlphaComplex& a) {
  const std::vector<NT> cgal(as.alpha_begin(), as.alpha_end());
  CHECK(cgal.size() == a.spectrum_size());
  if (cgal.size() != a.spectrum_size()) return;
  std::size_t bad = 0;
  for (std::size_t k = 0; k < cgal.size(); ++k) {
    if (is_nearest_double(cgal[k], a.spectrum_value(Index(k)))) continue;
    if (bad++ < 5)
      UNSCOPED_INFO("spectrum[" << k << "]: ours " << a.spectrum_value(Index(k)) << ", CGAL "
                                << CGAL::to_double(cgal[k]));
  }
  CHECK(bad == 0);
}

template <class AS>
void compare_with_cgal(const Input& in, const AS& as) {
  const Ours ours(in);
  const AlphaComplex& a = ours.a;
  REQUIRE(as.number_of_vertices() == ours.t.num_vertices());
  if (in.generic) {
    REQUIRE(as.number_of_finite_cells() == ours.t.num_finite_cells());
    REQUIRE(as.number_of_finite_facets() == a.simplices().num_triangles());
    REQUIRE(as.number_of_finite_edges() == a.simplices().num_edges());
  }
  check_spectrum(as, a);

  ClassCounts seen{};  // the most simplices of each class at one probe
  std::size_t at_value = 0;
  for (double alpha_sq : probe_alphas(a, 40)) {
    const NT alpha(alpha_sq);  // exact: both sides see the same double
    const Index level = a.level(alpha_sq);
    const ClassCounts ours_n = a.counts(level), cgal_n = cgal_counts(as, alpha);
    for (int d = 0; d < 4; ++d)
      for (int k = 0; k < 4; ++k) seen[d][k] = std::max(seen[d][k], ours_n[d][k]);
    at_value += as.alpha_find(alpha) != as.alpha_end();
    INFO("alpha^2 = " << alpha_sq << " (level " << level << ")\n ours: " << counts_string(ours_n)
                      << "\n CGAL: " << counts_string(cgal_n));
    // level = number of critical values <= alpha^2, counted exactly by CGAL.
    CHECK(level == std::size_t(as.alpha_upper_bound(alpha) - as.alpha_begin()));
    if (in.generic) {
      CHECK(ours_n == cgal_n);
    } else {
      // Invariants of a degenerate input (P: Delaunay polytopes, Q: their
      // polygon faces; all simplices inside one P or Q enter together, see
      // check_spectrum). The underlying space of the complex is the union of
      // the present P, Q and Delaunay edges, whatever the triangulation, so:
      //  - vertices: all four classes (exterior: not present; singular: no
      //    incident Delaunay edge present; interior: all incident P present);
      //  - edges: singular ones are Delaunay edges; regular ones are the
      //    Delaunay edges on the boundary plus the |Q| - 3 diagonals of each
      //    regular or singular polygon Q: both counts are invariant (exterior
      //    and interior counts depend on how each P is cut into cells);
      //  - triangles: singular and regular ones come |Q| - 2 per singular or
      //    regular polygon Q;
      //  - cells: only their union (volume, solid components).
      for (int k = 0; k < 4; ++k) CHECK(ours_n[0][k] == cgal_n[0][k]);
      for (int d = 1; d <= 2; ++d)
        for (int k = 1; k <= 2; ++k) CHECK(ours_n[d][k] == cgal_n[d][k]);
    }
    CHECK(euler(ours_n) == euler(cgal_n));
    const auto b = a.betti(level);
    CHECK(long(b[0]) - long(b[1]) + long(b[2]) == euler(cgal_n));
    CHECK(solid_components(a, level) == as.number_of_solid_components(alpha));
    CHECK(a.volume(level) == Approx(cgal_volume(as, alpha)).epsilon(1e-12).margin(1e-12));
  }
  // The probes did exercise what they compare: some hit a critical value
  // exactly (vertices' 0 or -w at least) and, on generic inputs, every class
  // of vertices, edges and triangles occurs at some probe.
  CHECK(at_value > 0);
  if (in.generic)
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 4; ++k) CHECK(seen[d][k] > 0);
}

void compare_with_cgal(const Input& in) {
  if (in.weights.empty()) {
    std::vector<EK::Point_3> pts;
    for (const auto& p : in.points) pts.emplace_back(p.x, p.y, p.z);
    const DelaunayAS as(pts.begin(), pts.end(), 0, DelaunayAS::GENERAL);
    compare_with_cgal(in, as);
  } else {
    std::vector<EK::Weighted_point_3> pts;
    for (std::size_t i = 0; i < in.points.size(); ++i)
      pts.emplace_back(EK::Point_3(in.points[i].x, in.points[i].y, in.points[i].z), in.weights[i]);
    const RegularAS as(pts.begin(), pts.end(), 0, RegularAS::GENERAL);
    compare_with_cgal(in, as);
  }
}

// ----------------------------------------------------------------- GUDHI

// One pair of a persistence diagram, values as doubles (kInf: never dies).
using Bar = std::pair<double, double>;
using Diagram = std::array<std::vector<Bar>, 3>;  // by dimension, sorted

Diagram our_diagram(const AlphaComplex& a) {
  Diagram d;
  for (const auto& p : a.persistence()) {
    if (p.birth == p.death) continue;  // zero length: GUDHI drops them too
    d[p.dim].emplace_back(a.spectrum_value(p.birth), p.death == alpha::kNever ? kInf : a.spectrum_value(p.death));
  }
  for (auto& bars : d) std::sort(bars.begin(), bars.end());
  return d;
}

// GUDHI's diagram (Z/2, intervals of positive length): its Alpha_complex on
// the dD exact kernel, values computed exactly then converted to double.
Diagram gudhi_diagram(const Input& in) {
  using Kd = CGAL::Epeck_d<CGAL::Dimension_tag<3>>;
  using Tree = Gudhi::Simplex_tree<>;
  Tree st;
  std::vector<Kd::Point_d> pts;
  for (const auto& p : in.points) pts.emplace_back(p.x, p.y, p.z);
  if (in.weights.empty()) {
    Gudhi::alpha_complex::Alpha_complex<Kd, false> ac(pts);
    REQUIRE(ac.create_complex(st, kInf, /*exact=*/true));
  } else {
    std::vector<Kd::FT> w(in.weights.begin(), in.weights.end());
    Gudhi::alpha_complex::Alpha_complex<Kd, true> ac(pts, w);
    REQUIRE(ac.create_complex(st, kInf, /*exact=*/true));
  }
  Gudhi::persistent_cohomology::Persistent_cohomology<Tree, Gudhi::persistent_cohomology::Field_Zp> pcoh(st);
  pcoh.init_coefficients(2);
  pcoh.compute_persistent_cohomology(0.0);  // drops intervals of length <= 0
  Diagram d;
  for (int dim = 0; dim < 3; ++dim) {
    d[dim] = pcoh.intervals_in_dimension(dim);
    std::sort(d[dim].begin(), d[dim].end());
  }
  CHECK(pcoh.intervals_in_dimension(3).empty());
  return d;
}

// GUDHI is memoized per input: tests 2 and 3 share it.
const Diagram& gudhi_diagram_cached(const Input& in) {
  static std::map<std::string, Diagram> cache;
  auto it = cache.find(in.name);
  if (it == cache.end()) it = cache.emplace(in.name, gudhi_diagram(in)).first;
  return it->second;
}

// Ours is the nearest double to the exact value; GUDHI's is the exact value
// converted by GMP or an exact interval (rounded either way): the two are
// equal or neighbours.
bool same_value(double ours, double gudhi) { return ours == gudhi || std::nextafter(ours, gudhi) == gudhi; }

std::size_t betti_of(const std::vector<Bar>& bars, double alpha_sq) {
  return std::size_t(std::count_if(bars.begin(), bars.end(),
                                   [&](const Bar& b) { return b.first <= alpha_sq && alpha_sq < b.second; }));
}

}  // namespace

// One section per input: a failed REQUIRE ends only that input's section.
TEST_CASE("classification counts and spectrum equal CGAL's Alpha_shape_3, generic inputs", "[cgal][oracle]") {
  for (const auto& in : generic_inputs()) {
    DYNAMIC_SECTION(in.name) {
      if (!in.weights.empty() && in.name.rfind("weighted random", 0) == 0) {
        const alpha::Triangulation t(in.points, in.weights);
        REQUIRE(t.num_hidden() > 0);  // otherwise hiding would go untested
      }
      compare_with_cgal(in);
    }
  }
}

TEST_CASE("triangulation-independent invariants equal CGAL's Alpha_shape_3, degenerate inputs",
          "[cgal][oracle][degenerate]") {
  for (const auto& in : degenerate_inputs()) DYNAMIC_SECTION(in.name) { compare_with_cgal(in); }
}

TEST_CASE("persistence diagrams equal GUDHI's", "[gudhi][oracle]") {
  for (const auto& in : all_inputs()) DYNAMIC_SECTION(in.name) {
    const Ours ours(in);
    const Diagram mine = our_diagram(ours.a);
    const Diagram& theirs = gudhi_diagram_cached(in);
    for (int dim = 0; dim < 3; ++dim) {
      INFO("dimension " << dim);
      CHECK(mine[dim].size() == theirs[dim].size());
      std::size_t bad = 0, infinite = 0;
      for (std::size_t i = 0; i < std::min(mine[dim].size(), theirs[dim].size()); ++i) {
        const Bar &m = mine[dim][i], &g = theirs[dim][i];
        infinite += m.second == kInf;
        if (same_value(m.first, g.first) && same_value(m.second, g.second)) continue;
        if (bad++ < 5)
          UNSCOPED_INFO("pair " << i << ": ours [" << m.first << ", " << m.second << "), GUDHI [" << g.first << ", "
                                << g.second << ")");
      }
      CHECK(bad == 0);
      CHECK(infinite == (dim == 0 ? 1 : 0));  // the full complex (the hull) is contractible
      if (dim < 2) CHECK(!mine[dim].empty());  // something to compare
    }
  }
}

TEST_CASE("Betti numbers equal GUDHI's", "[gudhi][oracle]") {
  for (const auto& in : all_inputs()) DYNAMIC_SECTION(in.name) {
    const Ours ours(in);
    const AlphaComplex& a = ours.a;
    const Diagram& theirs = gudhi_diagram_cached(in);
    // Probes strictly between two critical values, far enough (in ulps) from
    // both that GUDHI's rounding of them cannot matter.
    std::vector<double> alphas{a.spectrum_value(0) - 1, a.spectrum_value(Index(a.spectrum_size() - 1)) + 1};
    const std::size_t m = a.spectrum_size(), samples = 60;
    for (std::size_t i = 0; i < samples; ++i) {
      const Index k = Index(i * (m - 2) / (samples - 1));
      const double lo = a.spectrum_value(k), hi = a.spectrum_value(k + 1);
      const double mid = lo + (hi - lo) / 2;
      if (std::nextafter(std::nextafter(lo, kInf), kInf) < mid && mid < std::nextafter(std::nextafter(hi, -kInf), -kInf))
        alphas.push_back(mid);
    }
    REQUIRE(alphas.size() > samples / 2);
    bool nontrivial = false;
    for (double alpha_sq : alphas) {
      const auto b = a.betti(a.level(alpha_sq));
      const std::array<std::size_t, 3> g{betti_of(theirs[0], alpha_sq), betti_of(theirs[1], alpha_sq),
                                         betti_of(theirs[2], alpha_sq)};
      INFO("alpha^2 = " << alpha_sq << ": ours " << b[0] << ' ' << b[1] << ' ' << b[2] << ", GUDHI " << g[0] << ' '
                        << g[1] << ' ' << g[2]);
      CHECK(b == g);
      nontrivial = nontrivial || b[1] > 0 || b[2] > 0;
    }
    if (in.generic) CHECK(nontrivial);  // the probes saw some holes or voids
  }
}
