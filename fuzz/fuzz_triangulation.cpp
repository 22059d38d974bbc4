// SPDX-License-Identifier: Apache-2.0
// The triangulation and alpha complex on adversarial coordinates decoded
// from the fuzzer's bytes: small integer grids (duplicates, coplanar and
// cospherical subsets), grids nudged by a few ulps of their scale
// (near-degenerate), raw doubles (NaN, infinity, huge, subnormal), points
// on a plane or a line with a few off it; at scales from 1e-120 to 1e16;
// unweighted, or with weights (some negative).
//
// Properties: unusable input is an alpha::Error, never an Internal one, and
// input that is usable is not refused: for the small-integer encodings at
// scales within the limits, 4 affinely independent points, decided here in
// exact integers, must give a triangulation. Otherwise the
// triangulation passes the exact validator, the spectrum is sorted, the
// full complex (the convex hull) has the Betti numbers of a point (1 0 0),
// and with non-negative weights the union of balls has a finite area and a
// volume between the largest ball's and the sum of the balls'.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "alpha/triangulation.hpp"
#include "alpha/union_of_balls.hpp"
#include "alpha/validation.hpp"
#include "fuzz_check.hpp"

namespace {

constexpr std::size_t kMaxPoints = 64;  // enough for every degeneracy, fast per input

// Around the triangulation's limits: 1e-100 (smallest extent), 1e15
// (largest coordinate).
constexpr std::array<double, 16> kScale{1,     0.5,    1e-3,  1e-8,   1e-50, 1e-99, 1e-101, 1e-120,
                                        3.125, 1e3,    1e8,   1e12,   1e14,  7.8e12, 7.9e12, 1e16};

class Bytes {
public:
  explicit Bytes(std::span<const std::uint8_t> b) : b_(b) {}
  bool empty() const { return b_.empty(); }
  std::uint8_t byte() {
    if (b_.empty()) return 0;
    const std::uint8_t v = b_[0];
    b_ = b_.subspan(1);
    return v;
  }
  int small() { return int(std::int8_t(byte())); }
  double raw() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = bits << 8 | byte();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

private:
  std::span<const std::uint8_t> b_;
};

struct Input {
  std::vector<alpha::Vec3> points;
  std::vector<double> weights;
  // For encodings 0 and 3 at a scale well within the limits (coordinates
  // below 1e15, weights below 1e30, distinct points more than 1e-100
  // apart): the points in units of the scale, exact integers. Empty otherwise.
  std::vector<std::array<long long, 3>> units;
};

// Whether 4 of the integer points are affinely independent (exact: the
// coordinates are below 2^9, the products below 2^33).
bool spans_3d(const std::vector<std::array<long long, 3>>& q) {
  const auto d = [&](std::size_t i, std::size_t j, int k) { return q[j][k] - q[i][k]; };
  std::size_t b = 1;
  while (b < q.size() && q[b] == q[0]) ++b;
  for (std::size_t c = b + 1; c < q.size(); ++c) {
    const long long cx = d(0, b, 1) * d(0, c, 2) - d(0, b, 2) * d(0, c, 1),
                    cy = d(0, b, 2) * d(0, c, 0) - d(0, b, 0) * d(0, c, 2),
                    cz = d(0, b, 0) * d(0, c, 1) - d(0, b, 1) * d(0, c, 0);
    if (cx == 0 && cy == 0 && cz == 0) continue;  // c on the line of 0 and b
    for (std::size_t e = c + 1; e < q.size(); ++e)
      if (cx * d(0, e, 0) + cy * d(0, e, 1) + cz * d(0, e, 2) != 0) return true;
    return false;  // every point on the plane of 0, b and c
  }
  return false;
}

Input decode(Bytes in) {
  const std::uint8_t mode = in.byte();
  const int encoding = mode & 3;
  const bool weighted = mode & 4;
  const double scale = kScale[(mode >> 3) & 15];
  const bool plane_only = mode & 128;  // encoding 3: a line instead of a plane
  const bool integer = (encoding == 0 || encoding == 3) && scale >= 1e-50 && scale <= 1e12;
  Input out;
  while (!in.empty() && out.points.size() < kMaxPoints) {
    alpha::Vec3 p;
    switch (encoding) {
      case 0: {
        const int x = in.small(), y = in.small(), z = in.small();
        p = {x * scale, y * scale, z * scale};
        if (integer) out.units.push_back({x, y, z});
        break;
      }
      case 1: {
        const double ulp = scale * 0x1p-44;
        p = {in.small() * scale + in.small() * ulp, in.small() * scale + in.small() * ulp,
             in.small() * scale + in.small() * ulp};
        break;
      }
      case 2:
        p = {in.raw(), in.raw(), in.raw()};
        break;
      default: {
        // z = x + 2y (or the line y = 2x, z = 3x), a point off it when
        // the selector byte says so.
        const int ix = in.small(), iy = plane_only ? 2 * ix : in.small(), off = (in.byte() & 31) == 0;
        const double x = ix * scale, y = plane_only ? 2 * x : iy * scale;
        p = {x, y, (plane_only ? 3 * x : x + 2 * y) + off * scale};
        if (integer) out.units.push_back({ix, iy, (plane_only ? 3 * ix : ix + 2 * iy) + off});
      }
    }
    out.points.push_back(p);
    if (weighted) {
      const double r = in.small() * scale / 16;
      out.weights.push_back(in.byte() & 1 ? -r * r : r * r);
    }
  }
  return out;
}

void check_union(const alpha::AlphaComplex& complex, std::span<const double> weights) {
  double largest = 0, sum = 0;
  for (double w : weights) {
    const double v = 4.0 / 3.0 * std::numbers::pi * w * std::sqrt(w);
    largest = std::max(largest, v);
    sum += v;
  }
  const alpha::UnionOfBalls u(complex);
  fuzz::check(std::isfinite(u.area()) && u.area() >= 0, "the union's area is not finite and >= 0");
  const double slack = 1e-9 * sum;
  fuzz::check(u.volume() >= largest * (1 - 1e-9) - slack && u.volume() <= sum + slack,
              "the union's volume is outside [largest ball, sum of balls]",
              std::to_string(u.volume()) + " not in [" + std::to_string(largest) + ", " + std::to_string(sum) + "]");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input input = decode(Bytes({data, size}));
  const bool nonnegative = !input.weights.empty() &&
                           std::all_of(input.weights.begin(), input.weights.end(), [](double w) { return w >= 0; });
  std::unique_ptr<alpha::Triangulation> t;
  try {
    t = std::make_unique<alpha::Triangulation>(input.points, input.weights);
  } catch (const alpha::Error& e) {
    fuzz::check(std::string_view(e.what()).find('\n') == std::string_view::npos, "the message is not one line",
                e.what());
    fuzz::check(e.kind() != alpha::ErrorKind::Internal, "an internal error", e.what());
    // Scaling rounds each coordinate by at most half an ulp: an independent
    // integer configuration stays independent (its determinant is >= 1 in
    // units, the rounding moves it by about 1e-12).
    fuzz::check(!spans_3d(input.units), "usable input refused", e.what());
    return 0;
  }
  const alpha::ValidationReport report = alpha::validate(*t);
  if (!report.valid) fuzz::violated("invalid triangulation", report.problems.front());

  const alpha::AlphaComplex complex(*t);
  for (alpha::Index r = 1; r < complex.spectrum_size(); ++r)
    fuzz::check(complex.spectrum_value(r - 1) <= complex.spectrum_value(r), "the spectrum is not sorted");
  const auto betti = complex.betti(alpha::Index(complex.spectrum_size()));
  fuzz::check(betti == std::array<std::size_t, 3>{1, 0, 0}, "the full complex is not contractible",
              std::to_string(betti[0]) + " " + std::to_string(betti[1]) + " " + std::to_string(betti[2]));
  if (nonnegative) check_union(complex, input.weights);
  return 0;
}
