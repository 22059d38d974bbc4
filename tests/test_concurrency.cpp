// SPDX-License-Identifier: Apache-2.0
// The library keeps no global mutable state: searches on different
// structures run in parallel threads give bit-for-bit the results of a
// sequential run, and one alpha complex shared by threads computes its
// persistence pairs once; a search measuring its cavities on threads
// gives bit-for-bit the sequential search's cavities.
#include <catch2/catch.hpp>

#include <array>
#include <string>
#include <thread>
#include <vector>

#include "alpha/alpha_complex.hpp"
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
  d.values = {r.cavities.sa_area, r.cavities.sa_volume, double(r.complex->spectrum_size()),
              double(r.complex->persistence().size())};
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
