// SPDX-License-Identifier: Apache-2.0
// The point-file parser on arbitrary text, unweighted and weighted.
// Properties: an error is a std::runtime_error with a one-line message
// naming the file; a result has finite points within 1e15, one
// non-negative finite weight per point when weighted.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "fuzz_check.hpp"
#include "point_file.hpp"

namespace {

void parse(std::string_view text, bool weighted) {
  static const std::string name = "fuzz.xyz";
  try {
    const alphapocket::PointSet set = alphapocket::parse_points(text, name, weighted);
    fuzz::check(!set.points.empty(), "no points and no error");
    fuzz::check(set.weights.size() == (weighted ? set.points.size() : 0), "weights do not match points");
    for (const alpha::Vec3& p : set.points)
      for (double v : {p.x, p.y, p.z}) fuzz::check(std::isfinite(v) && std::fabs(v) <= 1e15, "a coordinate out of range");
    for (double w : set.weights) fuzz::check(std::isfinite(w) && w >= 0 && w <= 1e30, "a weight out of range");
  } catch (const std::runtime_error& e) {
    fuzz::check_message(e.what(), name);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  parse(text, false);
  parse(text, true);
  return 0;
}
