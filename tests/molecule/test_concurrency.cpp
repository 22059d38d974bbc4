// SPDX-License-Identifier: Apache-2.0
// The library keeps no global mutable state: searches on different
// structures run in parallel threads give bit-for-bit the results of a
// sequential run, and one alpha complex shared by threads computes its
// persistence pairs once; a search measuring its cavities on threads
// gives bit-for-bit the sequential search's cavities; a triangulation
// built on threads has the sequential one's cells, numbered the same way
// for any thread count, and so do its edges and triangles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/simplices.hpp"
#include "alpha/spatial_sort.hpp"
#include "alpha/triangulation.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/structure.hpp"
#include "point_sets.hpp"

namespace {

// Everything a pocket search reports that depends on the computation.
struct Digest {
  std::vector<double> values;
  std::vector<alpha::Index> cells;
  bool operator==(const Digest&) const = default;
};

Digest digest(const molecule::Structure& s, const molecule::CavityOptions& options = {}) {
  const molecule::PocketSearch r = molecule::search_pockets(s, options);
  Digest d;
  d.values = {r.cavities.sa_area, r.cavities.sa_volume, double(r.shape->complex().spectrum_size()),
              double(r.shape->complex().persistence().size())};
  for (const auto* list : {&r.cavities.pockets, &r.cavities.voids})
    for (const molecule::Cavity& c : *list) {
      d.values.insert(d.values.end(), {c.sa_volume, c.sa_area, c.ms_volume, c.ms_area, c.depth, c.score, c.center.x,
                                       c.center.y, c.center.z, c.max_alpha_sq, c.close_alpha_sq, c.mouth_area,
                                       c.buriedness, c.max_probe_radius, double(c.burial_atoms)});
      for (const auto* ids : {&c.cells, &c.lining_atoms, &c.sinks}) {
        d.cells.insert(d.cells.end(), ids->begin(), ids->end());
        d.cells.push_back(alpha::kNone);  // the lists' ends
      }
      for (const molecule::Mouth& m : c.mouths) {
        d.values.insert(d.values.end(), {m.area, double(m.to_outside)});
        d.cells.insert(d.cells.end(), m.triangles.begin(), m.triangles.end());
        d.cells.push_back(alpha::kNone);
      }
    }
  for (const molecule::Tunnel& t : r.cavities.tunnels) d.values.push_back(t.bottleneck_radius);
  return d;
}

}  // namespace

TEST_CASE("Pocket searches in parallel threads equal the sequential ones", "[concurrency]") {
  const std::vector<std::string> files = {ALPHAPOCKET_EXAMPLES_DATA "/1a26A.pdb", ALPHAPOCKET_TEST_DATA "/1ytjA.pdb",
                                          ALPHAPOCKET_TEST_DATA "/1fkgA.pdb", ALPHAPOCKET_TEST_DATA "/1UYD.pdb"};
  std::vector<molecule::Structure> structures;
  std::vector<Digest> sequential;
  for (const std::string& f : files) {
    structures.push_back(molecule::read_structure(f));
    sequential.push_back(digest(structures.back()));
  }
  // Two rounds over every structure, all at once.
  const std::size_t jobs = 2 * files.size();
  std::vector<Digest> parallel(jobs);
  std::vector<std::thread> threads;
  for (std::size_t j = 0; j < jobs; ++j)
    threads.emplace_back([&, j] { parallel[j] = digest(structures[j % files.size()]); });
  for (std::thread& t : threads) t.join();
  for (std::size_t j = 0; j < jobs; ++j) {
    INFO(files[j % files.size()]);
    CHECK(parallel[j] == sequential[j % files.size()]);
  }
}

TEST_CASE("An alpha complex shared by threads computes its persistence once", "[concurrency]") {
  const alpha::Triangulation t(testing::random_points(3000, 91));
  const alpha::AlphaComplex shared(t);
  const alpha::AlphaComplex alone(t);
  const auto& expected = alone.persistence();
  std::vector<const std::vector<alpha::PersistencePair>*> seen(4, nullptr);
  std::vector<std::array<std::size_t, 3>> betti(4);
  std::vector<std::thread> threads;
  const alpha::Index level = shared.level(0.001);
  for (std::size_t j = 0; j < seen.size(); ++j)
    threads.emplace_back([&, j] {
      betti[j] = shared.betti(level);
      seen[j] = &shared.persistence();
    });
  for (std::thread& th : threads) th.join();
  for (std::size_t j = 0; j < seen.size(); ++j) {
    CHECK(seen[j] == seen[0]);  // one vector: computed once
    CHECK(betti[j] == alone.betti(level));
  }
  REQUIRE(seen[0]->size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const alpha::PersistencePair &a = (*seen[0])[k], &b = expected[k];
    CHECK((a.dim == b.dim && a.birth == b.birth && a.death == b.death && a.birth_simplex == b.birth_simplex &&
           a.death_simplex == b.death_simplex));
  }
}

TEST_CASE("A search measuring its cavities on threads equals the sequential one", "[concurrency]") {
  // 1fbl: a chain with many pockets of all sizes (basins of split regions).
  for (const std::string f : {ALPHAPOCKET_TEST_DATA "/1fbl.pdb", ALPHAPOCKET_TEST_DATA "/1UYD.pdb"}) {
    INFO(f);
    const molecule::Structure s = molecule::read_structure(f);
    const Digest sequential = digest(s);
    REQUIRE(sequential.cells.size() > 100);
    for (unsigned threads : {2u, 3u}) {
      INFO(threads << " threads");
      molecule::CavityOptions options;
      options.threads = threads;
      CHECK(digest(s, options) == sequential);
    }
  }
}

namespace {

// The cells as sorted vertex lists, sorted: the same for any numbering.
std::vector<std::array<alpha::Index, 4>> cell_set(const alpha::Triangulation& t) {
  std::vector<std::array<alpha::Index, 4>> cells;
  for (const alpha::Cell& c : t.cells()) {
    auto v = c.v;
    std::sort(v.begin(), v.end());
    cells.push_back(v);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

// Neighbours that share the facet, finite cells positively oriented, a
// vertex's incident cell holding it, none for other points.
void check_valid(const alpha::Triangulation& t) {
  alpha::Kernel kernel = t.kernel();
  std::size_t bad_links = 0, bad_orientation = 0, bad_incident = 0;
  for (alpha::Index c = 0; c < t.num_cells(); ++c) {
    const alpha::Cell& cell = t.cell(c);
    for (int k = 0; k < 4; ++k) {
      const alpha::Index n = cell.n[k];
      bool shared = t.mirror_index(c, k) >= 0;
      for (int j = 0; j < 4; ++j) shared = shared && (j == k || t.index_of(n, cell.v[j]) >= 0);
      bad_links += !shared;
    }
    if (!t.is_infinite(c)) bad_orientation += kernel.orient3d(cell.v[0], cell.v[1], cell.v[2], cell.v[3]) <= 0;
  }
  for (alpha::Index v = 0; v < t.num_points(); ++v)
    bad_incident += t.status(v) == alpha::PointStatus::vertex ? t.index_of(t.incident_cell(v), v) < 0
                                                              : t.incident_cell(v) != alpha::kNone;
  CHECK(bad_links == 0);
  CHECK(bad_orientation == 0);
  CHECK(bad_incident == 0);
}

}  // namespace

TEST_CASE("The insertion order sorted on threads is the sequential one", "[concurrency][triangulation]") {
  // 150,000 points: the two longest rounds are sorted on threads. Half of
  // them twice, so that equal curve keys are ordered by index.
  std::vector<alpha::Vec3> points = testing::random_points(100000, 16);
  points.insert(points.end(), points.begin(), points.begin() + 50000);
  std::vector<alpha::Index> indices(points.size());
  std::iota(indices.begin(), indices.end(), alpha::Index(0));
  const std::vector<alpha::Index> sequential = alpha::brio_order(points, indices);
  CHECK(std::is_permutation(sequential.begin(), sequential.end(), indices.begin()));
  for (unsigned threads : {2u, 3u}) {
    INFO(threads << " threads");
    CHECK(alpha::brio_order(points, indices, threads) == sequential);
  }
}

TEST_CASE("A triangulation built on threads has the sequential one's cells", "[concurrency][triangulation]") {
  using alpha::Vec3;
  // 2^15 points or more take the parallel construction. Random; a grid
  // (cospherical cubes, decided by perturbation); duplicates; weighted
  // with hidden points; and two skew lines above a random cloud, whose
  // 360 x 360 cells between them outgrow the cells set aside for the
  // threads (the builders defer the rest to the sequential pass).
  std::vector<Vec3> duplicated = testing::random_points(34000, 11);
  for (int i = 0; i < 6000; ++i) duplicated.push_back(duplicated[std::size_t(i) * 5]);
  std::vector<Vec3> lines = testing::random_points(33000, 12);
  for (int i = 0; i < 360; ++i) {
    const double s = (i + 0.5) / 360;
    lines.push_back({s, 0.5, 2.0});
    lines.push_back({0.5, s, 3.0});
  }
  for (int kind = 0; kind < 5; ++kind) {
    INFO("kind " << kind);
    const std::vector<Vec3> points = kind == 0   ? testing::random_points(40000, 10)
                                     : kind == 1 ? testing::grid_points(33)
                                     : kind == 2 ? duplicated
                                     : kind == 3 ? testing::random_points(40000, 13, 34.0)
                                                 : lines;
    const std::vector<double> weights = kind == 3 ? testing::random_weights(40000, 14, 0.0, 1.0) : std::vector<double>{};
    const alpha::Triangulation sequential(points, weights);
    const alpha::Triangulation two(points, weights, 2), again(points, weights, 2), three(points, weights, 3);
    if (kind == 2) CHECK(two.num_duplicates() == 6000);
    if (kind == 3) CHECK(two.num_hidden() > 0);
    CHECK(cell_set(two) == cell_set(sequential));
    for (alpha::Index i = 0; i < points.size(); ++i) {
      if (two.status(i) != sequential.status(i) || two.representative(i) != sequential.representative(i)) {
        FAIL("point " << i << ": status or representative differs");
      }
    }
    check_valid(two);
    // The canonical numbering: the same cells in the same order, each with
    // the same vertex and neighbour lists, and the same incident cells, for
    // 2 and 3 threads and on every run.
    bool same_numbers = two.num_cells() == again.num_cells() && two.num_cells() == three.num_cells();
    for (alpha::Index c = 0; same_numbers && c < two.num_cells(); ++c) {
      same_numbers = two.cell(c).v == again.cell(c).v && two.cell(c).n == again.cell(c).n &&
                     two.cell(c).v == three.cell(c).v && two.cell(c).n == three.cell(c).n;
    }
    for (alpha::Index i = 0; same_numbers && i < points.size(); ++i)
      same_numbers = two.incident_cell(i) == again.incident_cell(i) && two.incident_cell(i) == three.incident_cell(i);
    CHECK(same_numbers);
    CHECK(two.num_finite_cells() == sequential.num_finite_cells());
    CHECK(two.predicate_stats().power.calls() > 0);
  }
}

TEST_CASE("Persistence of a triangulation built on threads equals the sequential one's", "[concurrency][triangulation]") {
  // The diagram does not depend on how ties between equal values are
  // ordered, so not on the cells' numbers: the 33^3 grid (five distinct
  // sizes, runs of tens of thousands of ties) and random points.
  for (int kind = 0; kind < 2; ++kind) {
    INFO("kind " << kind);
    const auto points = kind == 0 ? testing::grid_points(33) : testing::random_points(40000, 15);
    const alpha::Triangulation sequential(points), two(points, {}, 2);
    const alpha::AlphaComplex a(sequential), b(two);
    CHECK(a.spectrum_size() == b.spectrum_size());
    auto diagram = [](const alpha::AlphaComplex& complex) {  // (dim, birth, death) ranks, sorted
      std::vector<std::array<alpha::Index, 3>> pairs;
      for (const auto& p : complex.persistence()) pairs.push_back({alpha::Index(p.dim), p.birth, p.death});
      return pairs;
    };
    CHECK(diagram(a) == diagram(b));
  }
}

namespace {

// Every table of a Simplices, as one list of numbers: edges, the
// triangles of each edge (read from its stored cell), each triangle's
// vertices, edges and cells, each cell's triangles and each vertex's edges.
std::vector<alpha::Index> simplex_tables(const alpha::Triangulation& t, const alpha::Simplices& s) {
  std::vector<alpha::Index> list{alpha::Index(s.num_edges()), alpha::Index(s.num_triangles()),
                                 alpha::Index(s.num_hull_triangles())};
  for (alpha::Index e = 0; e < s.num_edges(); ++e) {
    list.insert(list.end(), s.edge(e).begin(), s.edge(e).end());
    for (const alpha::Index f : s.edge_triangles(e)) list.push_back(f);
  }
  for (alpha::Index f = 0; f < s.num_triangles(); ++f) {
    for (const alpha::Index v : s.triangle(f)) list.push_back(v);
    list.insert(list.end(), s.triangle_edges(f).begin(), s.triangle_edges(f).end());
    for (const alpha::Index c : s.triangle_cells(f)) list.push_back(c);
  }
  for (alpha::Index c = 0; c < t.num_cells(); ++c)
    for (int i = 0; i < 4; ++i) list.push_back(s.cell_triangle(c, i));
  for (alpha::Index v = 0; v < t.num_points(); ++v) {
    list.push_back(alpha::Index(s.vertex_edges(v).size()));
    list.insert(list.end(), s.vertex_edges(v).begin(), s.vertex_edges(v).end());
  }
  return list;
}

}  // namespace

TEST_CASE("Edges and triangles numbered on threads are the sequential ones", "[concurrency][simplices]") {
  using alpha::Vec3;
  // Rings that cross from one thread's cells into another's. Random points;
  // a grid (cospherical cubes); weighted points with hidden ones;
  // duplicates; and five points, fewer cells than threads.
  std::vector<Vec3> duplicated = testing::random_points(3000, 31);
  for (int i = 0; i < 500; ++i) duplicated.push_back(duplicated[std::size_t(i) * 3]);
  for (int kind = 0; kind < 5; ++kind) {
    INFO("kind " << kind);
    const std::vector<Vec3> points = kind == 0   ? testing::random_points(4000, 32)
                                     : kind == 1 ? testing::grid_points(12)
                                     : kind == 2 ? testing::random_points(4000, 33, 16.0)
                                     : kind == 3 ? duplicated
                                                 : testing::random_points(5, 34);
    const std::vector<double> weights = kind == 2 ? testing::random_weights(4000, 35, 0.0, 1.0) : std::vector<double>{};
    const alpha::Triangulation t(points, weights);
    if (kind == 2) CHECK(t.num_hidden() > 0);
    const alpha::Simplices one(t);
    const auto tables = simplex_tables(t, one);
    CHECK(one.num_edges() == alpha::count_simplices(t).edges);
    for (unsigned threads : {2u, 3u, 4u, 64u}) {
      INFO(threads << " threads");
      CHECK(simplex_tables(t, alpha::Simplices(t, threads)) == tables);
    }
  }
}

TEST_CASE("An alpha complex built on threads equals the sequential one", "[concurrency][alpha]") {
  using alpha::Vec3;
  // From AlphaComplex::kThreadsFrom vertices on the tests run on threads.
  // Random points; a grid (runs of tens of thousands of equal values, and
  // attached faces decided exactly); weighted points with hidden ones;
  // duplicates.
  std::vector<Vec3> duplicated = testing::random_points(34000, 21);
  for (int i = 0; i < 3000; ++i) duplicated.push_back(duplicated[std::size_t(i) * 7]);
  for (int kind = 0; kind < 4; ++kind) {
    INFO("kind " << kind);
    const std::vector<Vec3> points = kind == 0   ? testing::random_points(40000, 22)
                                     : kind == 1 ? testing::grid_points(33)
                                     : kind == 2 ? testing::random_points(40000, 23, 34.0)
                                                 : duplicated;
    const std::vector<double> weights =
        kind == 2 ? testing::random_weights(40000, 24, 0.0, 1.0) : std::vector<double>{};
    const alpha::Triangulation t(points, weights);
    REQUIRE(t.num_vertices() >= alpha::AlphaComplex::kThreadsFrom);
    if (kind == 2) CHECK(t.num_hidden() > 0);
    const alpha::AlphaComplex one(t), two(t, 2), three(t, 3);
    for (const alpha::AlphaComplex* other : {&two, &three}) {
      REQUIRE(other->spectrum_size() == one.spectrum_size());
      bool same = true;
      auto same_interval = [](const alpha::Interval& a, const alpha::Interval& b) {
        return a.entry == b.entry && a.mu_low == b.mu_low && a.mu_high == b.mu_high && a.attached == b.attached;
      };
      for (alpha::Index v = 0; same && v < t.num_points(); ++v)
        same = same_interval(one.vertex_interval(v), other->vertex_interval(v));
      for (alpha::Index e = 0; same && e < one.simplices().num_edges(); ++e)
        same = same_interval(one.edge_interval(e), other->edge_interval(e));
      for (alpha::Index f = 0; same && f < one.simplices().num_triangles(); ++f)
        same = same_interval(one.triangle_interval(f), other->triangle_interval(f));
      for (alpha::Index c = 0; same && c < t.num_cells(); ++c) same = one.cell_entry(c) == other->cell_entry(c);
      for (alpha::Index r = 0; same && r < one.spectrum_size(); ++r)
        same = one.spectrum_value(r) == other->spectrum_value(r);
      CHECK(same);
      auto pairs = [](const alpha::AlphaComplex& complex) {
        std::vector<std::array<alpha::Index, 5>> list;
        for (const auto& p : complex.persistence())
          list.push_back({alpha::Index(p.dim), p.birth, p.death, p.birth_simplex, p.death_simplex});
        return list;
      };
      CHECK(pairs(one) == pairs(*other));
      // The sizes are computed once each, whatever the threads.
      CHECK(other->size_stats().compare.calls() == one.size_stats().compare.calls());
    }
  }
}
