// SPDX-License-Identifier: Apache-2.0
// molecule::find_tunnels (tunnels, pores and the ways through cycles with radius profiles) on
// configurations with closed forms, every profile radius against a scan of
// all atoms, and gramicidin A against HOLE; molecule::radius_file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "alpha/point_set_complex.hpp"
#include "molecule/atom_balls.hpp"
#include "molecule/cavities.hpp"
#include "molecule/pocket_search.hpp"
#include "molecule/radius_file.hpp"
#include "molecule/structure.hpp"
#include "molecule/tunnel_paths.hpp"
#include "point_sets.hpp"

using alpha::Vec3;
using molecule::TunnelOptions;
using molecule::TunnelPath;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Atoms {
  std::vector<Vec3> points;
  std::vector<double> radii;
  double probe = 1.4;
  std::optional<alpha::PointSetComplex> shape;
  void add(const std::vector<Vec3>& ps, double r) {
    for (const Vec3& p : ps) points.push_back(p), radii.push_back(r);
  }
  const alpha::AlphaComplex& complex() {
    std::vector<double> w;
    for (const double r : radii) w.push_back(molecule::ball_weight(r, probe));
    return shape.emplace(points, std::move(w)).complex();
  }
  // Distance to the nearest sphere, by a scan of all atoms.
  double radius_at(const Vec3& x) const {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < points.size(); ++i) d = std::min(d, norm(x - points[i]) - radii[i]);
    return d;
  }
};

// Properties every path has: exact radii, the sampling, the bottleneck,
// length and curvature, lining atoms.
void check_path(const Atoms& a, const TunnelPath& p, const TunnelOptions& o) {
  REQUIRE(p.profile.size() >= 2);
  double min_radius = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < p.profile.size(); ++k) {
    const auto& q = p.profile[k];
    REQUIRE(q.radius == a.radius_at(q.x));
    min_radius = std::min(min_radius, q.radius);
    if (k > 0) {
      REQUIRE(q.distance > p.profile[k - 1].distance);
      REQUIRE(q.distance - p.profile[k - 1].distance <= o.step + 1e-9);
      // Points follow the line: no farther apart than along it.
      REQUIRE(norm(q.x - p.profile[k - 1].x) <= q.distance - p.profile[k - 1].distance + 1e-9);
    }
    REQUIRE(q.radius >= o.probe - 1e-9);  // every edge passes the probe, so does every point on it (equal radii)
  }
  REQUIRE(p.profile.front().distance == 0);
  REQUIRE(p.profile.back().distance == Approx(p.length).margin(1e-9));
  REQUIRE(p.bottleneck_radius == min_radius);
  REQUIRE(p.curvature == Approx(p.length / norm(p.mouth - p.start_point)));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    bool near = false;
    for (const auto& q : p.profile) near = near || norm(q.x - a.points[i]) - a.radii[i] <= q.radius + o.contact;
    REQUIRE(near == std::binary_search(p.lining_atoms.begin(), p.lining_atoms.end(), alpha::Index(i)));
  }
}

}  // namespace

TEST_CASE("tunnel paths: a straight channel of rings is one pore of bottleneck R - r", "[tunnels]") {
  // 20 rings of 8 balls (radius 1.6, circle radius 3, 1.5 apart: a closed
  // wall), staggered: a channel 28.5 A long whose narrowest points are the
  // ring centres, 3 - 1.6 = 1.4 A from the balls.
  Atoms a;
  for (int k = 0; k < 20; ++k) a.add(testing::ring_points(8, 3, 1.5 * k, k % 2 ? kPi / 8 : 0), 1.6);
  TunnelOptions o;
  o.pores = true;
  const std::vector<TunnelPath> paths = molecule::find_tunnel_paths(a.complex(), a.radii, {}, o);
  REQUIRE(paths.size() == 1);
  const TunnelPath& p = paths.front();
  REQUIRE(p.pore);
  CHECK(std::abs(p.bottleneck_radius - 1.4) < 1e-9);
  CHECK(std::hypot(p.bottleneck.x, p.bottleneck.y) < 1e-9);  // on the axis
  check_path(a, p, o);
  // It runs along the axis from one end to the other.
  CHECK(std::abs(p.start_point.z - p.mouth.z) > 15);
  for (const auto& q : p.profile) CHECK(std::hypot(q.x.x, q.x.y) < 1e-6);
  // A probe wider than the channel finds no pore.
  o.probe = 1.41;
  CHECK(molecule::find_tunnel_paths(a.shape->complex(), a.radii, {}, o).empty());
}

TEST_CASE("tunnel paths: the way through a cycle crosses its killing triangle, from end to end", "[tunnels]") {
  // A channel of rings as above, 0.2 A wider (the probe-grown balls leave
  // it open at alpha 0) but for the middle ring: its 1-cycle
  // (find_cavities) dies there, at R - r = 1.5 A; the way through runs
  // along the axis to the solvent at both ends.
  Atoms a;
  for (int k = 0; k < 20; ++k) a.add(testing::ring_points(8, k == 10 ? 3.1 : 3.2, 1.5 * k, k % 2 ? kPi / 8 : 0), 1.6);
  const alpha::AlphaComplex& ac = a.complex();
  const molecule::Cavities cavities = molecule::find_cavities(ac, a.radii, {});
  REQUIRE(!cavities.tunnels.empty());
  const TunnelOptions o;
  const molecule::TunnelNetwork network = molecule::find_tunnels(ac, a.radii, {}, cavities.tunnels, o);
  CHECK(network.paths.empty());  // no start, no pores asked for
  REQUIRE(network.cycles.size() == cavities.tunnels.size());
  for (std::size_t k = 0; k < cavities.tunnels.size(); ++k) {
    const molecule::Tunnel& c = cavities.tunnels[k];
    const TunnelPath& p = network.cycles[k];
    check_path(a, p, o);
    CHECK(std::find(p.triangles.begin(), p.triangles.end(), c.bottleneck_triangle) != p.triangles.end());
    CHECK(std::abs(c.bottleneck_center.z - 15) < 1e-9);
    CHECK(std::abs(p.bottleneck_radius - 1.5) < 1e-9);
    CHECK(norm(p.bottleneck - c.bottleneck_center) < 1e-9);
    CHECK(std::min(p.start_point.z, p.mouth.z) < 6);  // out of the 28.5 A channel at both ends
    CHECK(std::max(p.start_point.z, p.mouth.z) > 22.5);
    for (const auto& q : p.profile) CHECK(std::hypot(q.x.x, q.x.y) < 1e-6);
  }
  // A probe wider than the channel: no way through, no profile.
  TunnelOptions wide = o;
  wide.probe = 1.51;
  for (const TunnelPath& p : molecule::find_tunnels(ac, a.radii, {}, cavities.tunnels, wide).cycles)
    CHECK(p.profile.empty());
  // A cycle without a killing triangle has no way through.
  const std::vector<molecule::Tunnel> none(1);
  CHECK(molecule::find_tunnels(ac, a.radii, {}, none, o).cycles.at(0).profile.empty());
}

TEST_CASE("tunnel paths: from inside a cage with one window, the tunnel leaves through it", "[tunnels]") {
  Atoms a;
  const double cap = kPi / 6;
  a.add(testing::cage_points(200, 6, cap, 8), 1.6);
  const TunnelOptions o;
  const std::vector<molecule::TunnelStart> starts{{"centre", {}, {0, 0, 0}}};
  const std::vector<TunnelPath> paths = molecule::find_tunnel_paths(a.complex(), a.radii, starts, o);
  REQUIRE(!paths.empty());
  const TunnelPath& p = paths.front();  // the widest
  CHECK(!p.pore);
  CHECK(std::abs(p.bottleneck_radius - (6 * std::sin(cap) - 1.6)) < 1e-9);
  CHECK(norm(p.bottleneck - Vec3{0, 0, 6 * std::cos(cap)}) < 1e-9);
  CHECK(p.mouth.z >= 6 * std::cos(cap) - 1e-9);  // the window (or beyond)
  check_path(a, p, o);
  for (const TunnelPath& q : paths) CHECK(q.bottleneck_radius <= p.bottleneck_radius + 1e-12);
  // A start point is taken to the nearest node the probe fits in, however
  // far it lies: the same widest tunnel.
  const std::vector<molecule::TunnelStart> far{{"far", {}, {1e6, 0, 0}}};
  const std::vector<TunnelPath> from_far = molecule::find_tunnel_paths(a.shape->complex(), a.radii, far, o);
  REQUIRE(!from_far.empty());
  CHECK(from_far.front().bottleneck_radius == p.bottleneck_radius);
  // A probe wider than the window (1.4): no tunnel, no error.
  TunnelOptions wide = o;
  wide.probe = 3;
  CHECK(molecule::find_tunnel_paths(a.shape->complex(), a.radii, starts, wide).empty());
  // Closed (the window's ring moved into the sphere's points): no tunnel.
  Atoms closed;
  closed.add(testing::cage_points(200, 6, 0, 0), 1.6);
  CHECK(molecule::find_tunnel_paths(closed.complex(), closed.radii, starts, o).empty());
}

TEST_CASE("tunnel paths: bad input is refused", "[tunnels]") {
  Atoms a;
  a.add(testing::ring_points(8, 3, 0), 1.6);
  a.add(testing::ring_points(8, 3, 1.5), 1.6);
  const alpha::AlphaComplex& ac = a.complex();
  CHECK_THROWS_AS(molecule::find_tunnel_paths(ac, {1.0, 2.0}, {}, {}), alpha::Error);
  TunnelOptions o;
  o.probe = 0;
  CHECK_THROWS_AS(molecule::find_tunnel_paths(ac, a.radii, {}, o), alpha::Error);
}

TEST_CASE("radius file: HOLE's simple.rad and the native format", "[tunnels][radii]") {
  const molecule::RadiusFile hole = molecule::read_radius_file(ALPHAPOCKET_TEST_DATA "/channels/simple.rad");
  CHECK(hole.rules.size() == 9);
  std::vector<molecule::Atom> atoms(6);
  const char* names[][3] = {{"VAL", "CA", "C"}, {"TRP", "NE1", "N"}, {"GLN", "E2A", "X"},
                            {"HOH", "O", "O"},  {"MET", "SD", "S"},   {"ZN", "ZN", "Zn"}};
  for (std::size_t i = 0; i < atoms.size(); ++i)
    atoms[i].residue_name = names[i][0], atoms[i].name = names[i][1], atoms[i].element = names[i][2];
  CHECK(molecule::apply_radius_file(hole, atoms) == 1);  // the zinc: no rule
  CHECK(atoms[0].radius == 1.85);
  CHECK(atoms[1].radius == 1.75);
  CHECK(atoms[2].radius == 1.00);  // E2? GLN, more specific than any general rule
  CHECK(atoms[3].radius == 1.65);
  CHECK(atoms[4].radius == 2.00);
  CHECK(atoms[5].radius == 1.39);  // built-in element radius
  const molecule::RadiusFile own = molecule::parse_radius_file(
      "# mine\n* C* 1.7\nALA CB 1.9\n* ?D? 2.2\nelement ZN 0.74\n", "own.txt");
  CHECK(molecule::apply_radius_file(own, atoms) == 3);  // NE1, the glutamine's X and the water's O
  CHECK(atoms[0].radius == 1.7);
  CHECK(atoms[4].radius == 2.2);  // SD: "?D?" padded to 4
  CHECK(atoms[5].radius == 0.74);
  atoms[0].residue_name = "ALA", atoms[0].name = "CB";
  molecule::apply_radius_file(own, atoms);
  CHECK(atoms[0].radius == 1.9);
  CHECK_THROWS_WITH(molecule::parse_radius_file("ALA CB\n", "r.txt"), Catch::Contains("r.txt: line 1"));
  CHECK_THROWS_WITH(molecule::parse_radius_file("\nALA CB x\n", "r.txt"), Catch::Contains("line 2"));
  CHECK_THROWS_WITH(molecule::parse_radius_file("ALA CB -1\n", "r.txt"), Catch::Contains(">= 0"));
  CHECK_THROWS_WITH(molecule::read_radius_file("/nonexistent.rad"), Catch::Contains("/nonexistent.rad"));
}

TEST_CASE("tunnel paths: gramicidin A has one pore, as HOLE finds it (1.198 A)", "[tunnels]") {
  molecule::StructureOptions so;
  so.keep_hetero = true;  // HOLE uses every atom (the ethanolamine caps)
  molecule::Structure s = molecule::read_structure(ALPHAPOCKET_TEST_DATA "/channels/1grm_single.pdb", so);
  const molecule::RadiusFile rad = molecule::read_radius_file(ALPHAPOCKET_TEST_DATA "/channels/simple.rad");
  REQUIRE(molecule::apply_radius_file(rad, s.atoms) == 0);
  const molecule::PocketSearch search = molecule::search_pockets(s, {});
  std::vector<double> radii;
  for (const auto& atom : s.atoms) radii.push_back(atom.radius);
  TunnelOptions o;
  o.pores = true;
  const std::vector<TunnelPath> paths = molecule::find_tunnel_paths(search.shape->complex(), radii, {}, o);
  REQUIRE(paths.size() == 1);
  const TunnelPath& p = paths.front();
  CHECK(std::abs(p.bottleneck_radius - 1.198) < 0.15);
  // Along the channel (HOLE: radius < 1.6 A over 24 A about its middle),
  // within 10 A of the midpoint of the pore's mouths along their line.
  const Vec3 mid = 0.5 * (p.start_point + p.mouth), axis = (1 / norm(p.mouth - p.start_point)) * (p.mouth - p.start_point);
  std::size_t inside = 0;
  for (const auto& q : p.profile)
    if (std::abs(dot(q.x - mid, axis)) <= 10) {
      ++inside;
      CHECK(q.radius >= 1.1);
      CHECK(q.radius <= 1.6);
    }
  CHECK(inside >= 35);  // 20 A at 0.5 A
}
