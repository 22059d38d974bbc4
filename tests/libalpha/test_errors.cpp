// SPDX-License-Identifier: Apache-2.0
// Error kinds: what a caller acts on (alpha::ErrorKind), kept when the file
// name is added (alpha::in_file).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "alpha/triangulation.hpp"

namespace {

using alpha::ErrorKind;

template <class F>
ErrorKind kind_of(F&& f) {
  try {
    f();
  } catch (const alpha::Error& e) {
    return e.kind();
  }
  FAIL("no alpha::Error thrown");
  return ErrorKind::Internal;
}

const std::vector<alpha::Vec3> kTetrahedron{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

}  // namespace

TEST_CASE("errors: bad input, misuse and limits have their kinds") {
  // Bad input: what the data is.
  CHECK(kind_of([] { alpha::Triangulation({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}); }) == ErrorKind::BadInput);
  CHECK(kind_of([] { alpha::Triangulation({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1e300}}); }) ==
        ErrorKind::BadInput);
  // Misuse: what the caller passed.
  CHECK(kind_of([] { alpha::Triangulation(kTetrahedron, {1.0, 2.0}); }) == ErrorKind::Misuse);
  const alpha::Triangulation t(kTetrahedron);
  const alpha::AlphaComplex ac(t);
  CHECK(kind_of([&] { ac.level(std::nan("")); }) == ErrorKind::Misuse);
  CHECK(kind_of([] { alpha::fail("x", ErrorKind::LimitExceeded); }) == ErrorKind::LimitExceeded);
  CHECK(alpha::error_kind_name(ErrorKind::BadInput) == "bad_input");
  CHECK(alpha::error_kind_name(ErrorKind::LimitExceeded) == "limit_exceeded");
  CHECK(alpha::error_kind_name(ErrorKind::Misuse) == "misuse");
  CHECK(alpha::error_kind_name(ErrorKind::Internal) == "internal");
}

TEST_CASE("errors: in_file names the file and keeps the kind") {
  for (const ErrorKind k : {ErrorKind::BadInput, ErrorKind::LimitExceeded, ErrorKind::Misuse, ErrorKind::Internal}) {
    const alpha::Error e = alpha::in_file("x.pdb", alpha::Error("all points are coplanar", k));
    CHECK(e.kind() == k);
    CHECK(std::string(e.what()) == "x.pdb: all points are coplanar");
  }
}
