// SPDX-License-Identifier: Apache-2.0
// The surface job (molecule::measure_surface, measure_balls) on closed
// forms, flat and tiny inputs, and its error kinds; analyse's error kinds.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "alpha/error.hpp"
#include "alpha/input_file.hpp"
#include "molecule/analysis.hpp"
#include "molecule/surface.hpp"

namespace {

using std::numbers::pi;

molecule::Atom atom(double x, double y, double z, double radius) {
  molecule::Atom a;
  a.name = "C";
  a.element = "C";
  a.residue_name = "UNK";
  a.position = {x, y, z};
  a.radius = radius;
  return a;
}

template <class F>
alpha::ErrorKind kind_of(F&& f) {
  try {
    f();
  } catch (const alpha::Error& e) {
    return e.kind();
  }
  FAIL("no alpha::Error thrown");
  return alpha::ErrorKind::Internal;
}

}  // namespace

TEST_CASE("surface job: one ball and two overlapping balls in closed form") {
  const molecule::Surface one = molecule::measure_surface({atom(1, 2, 3, 1.5)}, {.probe = 0.5});
  CHECK(one.balls == 1);
  CHECK(one.sa_area == Approx(4 * pi * 4).epsilon(1e-12));
  CHECK(one.sa_volume == Approx(4.0 / 3 * pi * 8).epsilon(1e-12));
  CHECK(*one.ms_volume == Approx(4.0 / 3 * pi * 1.5 * 1.5 * 1.5).epsilon(1e-12));  // one ball: its own MS
  CHECK(*one.ms_area == Approx(4 * pi * 1.5 * 1.5).epsilon(1e-12));
  // Two unit balls 1 apart (no probe): each loses a cap of height 1/2.
  const molecule::Surface two = molecule::measure_balls({{0, 0, 0}, {1, 0, 0}}, {1, 1});
  CHECK(two.sa_area == Approx(2 * (4 * pi - 2 * pi * 0.5)).epsilon(1e-12));
  CHECK(two.sa_volume == Approx(2 * (4.0 / 3 * pi) - 2 * pi * 0.25 * (1 - 0.5 / 3)).epsilon(1e-12));
  CHECK(two.ball_areas.size() == 2);
  CHECK(two.ball_areas[0] == Approx(3 * pi).epsilon(1e-12));
  CHECK_FALSE(two.ms_area.has_value());  // bare balls: no probe, no MS surface
  // Radii 2 and 1, 2 apart: the power plane x = (d^2 + r1^2 - r2^2) / 2d =
  // 7/4 cuts a cap of height 1/4 off the first ball and 3/4 off the second;
  // each ball keeps the rest as its volume.
  const auto cap = [](double h, double r) { return pi * h * h * (3 * r - h) / 3; };
  const molecule::Surface unequal = molecule::measure_balls({{0, 0, 0}, {2, 0, 0}}, {4, 1});
  REQUIRE(unequal.ball_volumes.size() == 2);
  CHECK(unequal.ball_volumes[0] == Approx(4.0 / 3 * pi * 8 - cap(0.25, 2)).epsilon(1e-12));
  CHECK(unequal.ball_volumes[1] == Approx(4.0 / 3 * pi - cap(0.75, 1)).epsilon(1e-12));
  CHECK(unequal.ball_volumes[0] + unequal.ball_volumes[1] == Approx(unequal.sa_volume).epsilon(1e-12));
}

TEST_CASE("surface job: flat molecules, --sa-only, independent of the atom order") {
  // Three atoms in a line: far points make them span 3D; areas per atom only.
  const std::vector<molecule::Atom> line{atom(0, 0, 0, 1.7), atom(1.5, 0, 0, 1.7), atom(3, 0, 0, 1.7)};
  const molecule::Surface s = molecule::measure_surface(line, {.probe = 1.4, .excluded = false});
  CHECK(s.ball_areas.size() == 3);
  CHECK(s.ball_areas[0] + s.ball_areas[1] + s.ball_areas[2] == Approx(s.sa_area).epsilon(1e-12));
  CHECK(s.ball_areas[0] == s.ball_areas[2]);
  REQUIRE(s.ball_volumes.size() == 3);  // the far points' balls are not the atoms'
  CHECK(s.ball_volumes[0] + s.ball_volumes[1] + s.ball_volumes[2] == Approx(s.sa_volume).epsilon(1e-12));
  CHECK_FALSE(s.ms_area.has_value());
  // Unequal atoms in a line, in both orders: the same measures, per atom too.
  const std::vector<molecule::Atom> uneven{atom(0, 0, 0, 1.7), atom(1.5, 0, 0, 1.5), atom(3.2, 0, 0, 1.2)};
  const std::vector<molecule::Atom> reversed(uneven.rbegin(), uneven.rend());
  const molecule::Surface forward = molecule::measure_surface(uneven, {.probe = 1.4, .excluded = false}),
                          backward = molecule::measure_surface(reversed, {.probe = 1.4, .excluded = false});
  CHECK(backward.sa_area == Approx(forward.sa_area).epsilon(1e-12));
  CHECK(backward.sa_volume == Approx(forward.sa_volume).epsilon(1e-12));
  REQUIRE(backward.ball_areas.size() == 3);
  CHECK(forward.ball_areas[0] != Approx(forward.ball_areas[2]).epsilon(1e-3));
  for (std::size_t i = 0; i < 3; ++i)
    CHECK(backward.ball_areas[2 - i] == Approx(forward.ball_areas[i]).epsilon(1e-12));
}

TEST_CASE("surface job: error kinds, and the file named") {
  CHECK(kind_of([] { molecule::measure_surface({atom(0, 0, 0, 1)}, {.probe = -1}); }) == alpha::ErrorKind::Misuse);
  CHECK(kind_of([] { molecule::measure_balls({{0, 0, 0}}, {1, 2}); }) == alpha::ErrorKind::Misuse);
  CHECK(kind_of([] { molecule::measure_balls({}, {}); }) == alpha::ErrorKind::BadInput);
  CHECK(kind_of([] { molecule::measure_balls({{0, 0, 0}, {1, 0, 0}}, {1, -1}); }) == alpha::ErrorKind::BadInput);
  const std::string missing = std::string(ALPHAPOCKET_TEST_DATA) + "/missing.pdb";
  try {
    molecule::surface_of_file(missing, {});
    FAIL("no error");
  } catch (const alpha::Error& e) {
    CHECK(e.kind() == alpha::ErrorKind::BadInput);
    CHECK(std::string(e.what()).starts_with(missing + ": "));
  }
  // A file's bytes measure as the file does; errors name the given name.
  const std::string file = std::string(ALPHAPOCKET_TEST_DATA) + "/1fkgA.pdb";
  const molecule::Surface from_file = molecule::surface_of_file(file, {}, {.excluded = false});
  const molecule::Surface from_content =
      molecule::surface_of_content("x.pdb", alpha::read_input_file(file), {}, {.excluded = false});
  CHECK(from_content.sa_area == from_file.sa_area);
  CHECK(from_content.ball_areas == from_file.ball_areas);
  try {
    molecule::surface_of_content("x.pdb", "HETATM", {});
    FAIL("no error");
  } catch (const alpha::Error& e) {
    CHECK(e.kind() == alpha::ErrorKind::BadInput);
    CHECK(std::string(e.what()).starts_with("x.pdb: "));
  }
}

TEST_CASE("analyse: atoms in one plane are bad input naming the structure, a negative probe misuse") {
  molecule::Structure flat;
  for (int i = 0; i < 25; ++i) flat.atoms.push_back(atom(3 * (i % 5), 3 * (i / 5), 0, 1.7));
  try {
    molecule::analyse_structure("flat", flat, {});
    FAIL("no error");
  } catch (const molecule::AnalysisError& e) {
    CHECK(e.kind() == alpha::ErrorKind::BadInput);
    CHECK(std::string(e.what()).starts_with("flat: "));
    CHECK(std::string(e.what()).find("coplanar") != std::string::npos);
  }
  molecule::Structure ball = flat;
  ball.atoms.push_back(atom(6, 6, 5, 1.7));
  molecule::AnalysisOptions options;
  options.cavities.probe = -1;
  CHECK(kind_of([&] { molecule::analyse_structure("ball", ball, options); }) == alpha::ErrorKind::Misuse);
}
