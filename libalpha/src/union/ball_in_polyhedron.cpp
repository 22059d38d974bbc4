// SPDX-License-Identifier: Apache-2.0
#include "union/ball_in_polyhedron.hpp"

#include <cmath>

namespace alpha {
namespace {

// The part of the ball in the pyramid over one edge's triangle (F, X_a, X_b)
// of a face at distance h < r, X_t = E + t u on the edge's line at distance
// a from F: the sphere's solid angle over the triangle outside D and the
// triangle's area inside D (radius rho). Over t's where X_t is outside D
// the ray from the apex meets the sphere first: its solid angle there is
// the triangle's (at F: the angle less an asin) less the sector's (the
// angle times 1 - h / r); where X_t is inside D the triangle is in D.
struct EdgeTriangle {
  double h, r, rho2, a;
  double sphere = 0, disc = 0;  // solid angle outside D, area inside D

  void add(double ta, double tb) {
    const double rho2_a = rho2 - a * a;  // the line crosses the circle at +-y0
    if (rho2_a <= 0) return outside(ta, tb);
    const double y0 = std::sqrt(rho2_a);
    if (ta < -y0) outside(ta, std::min(tb, -y0));
    if (tb > y0) outside(std::max(ta, y0), tb);
    const double lo = std::max(ta, -y0), hi = std::min(tb, y0);
    if (hi > lo) disc += a * (hi - lo) / 2;
  }

  void outside(double ta, double tb) {
    // Differences of atan2(t, a) and of atan2(h t, a R_t) (R_t: distance
    // from the apex to X_t), each in (-pi/2, pi/2), as one atan2.
    const double ra = std::sqrt(a * a + ta * ta + h * h), rb = std::sqrt(a * a + tb * tb + h * h);
    const double angle = std::atan2(a * (tb - ta), a * a + ta * tb);
    const double lift = std::atan2(h * a * (tb * ra - ta * rb), a * a * ra * rb + h * h * ta * tb);
    sphere += angle * h / r - lift;
    disc += rho2 * angle / 2;
  }
};

}  // namespace

BallPart ball_in_polyhedron(const ConvexPolyhedron& q, double r) {
  BallPart total;
  for (std::size_t f = 0; f < q.num_faces(); ++f) {
    const Vec3& normal = q.normal(f);
    const std::span<const std::uint32_t> loop = q.loop(f);
    const std::size_t m = loop.size();
    const double h = dot(normal, q.vertex(loop[0]));
    if (std::fabs(h) >= r) {
      // The plane misses the ball: the sphere's part in the pyramid is its
      // solid angle, signed (Van Oosterom and Strackee on a fan of the loop;
      // positive seen from the face's inner side).
      double angle = 0;
      const Vec3& a = q.vertex(loop[0]);
      const double la = norm(a);
      for (std::size_t k = 1; k + 1 < m; ++k) {
        const Vec3 &b = q.vertex(loop[k]), &c = q.vertex(loop[k + 1]);
        const double lb = norm(b), lc = norm(c);
        angle += 2 * std::atan2(dot(a, cross(b, c)), la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la);
      }
      total.volume += r * r * r * angle / 3;
      total.area += r * r * angle;
      continue;
    }
    if (h == 0) continue;
    const Vec3 foot = h * normal;
    EdgeTriangle face{std::fabs(h), r, (r - std::fabs(h)) * (r + std::fabs(h)), 0};
    double sphere = 0, disc = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const Vec3 &p0 = q.vertex(loop[k]), &p1 = q.vertex(loop[(k + 1) % m]);
      const double length = norm(p1 - p0);
      if (length == 0) continue;
      const Vec3 u = (1 / length) * (p1 - p0);
      // The edge's line, E (foot of F) at t = 0, the edge from t0 to t0 + length.
      const double t0 = dot(p0 - foot, u);
      const Vec3 to_line = (p0 - t0 * u) - foot;
      face.a = norm(to_line);
      if (face.a == 0) continue;
      face.sphere = face.disc = 0;
      face.add(t0, t0 + length);
      // Counter-clockwise about the normal when F sees the line run that way.
      const double turn = dot(normal, cross(to_line, u)) > 0 ? 1 : -1;
      sphere += turn * face.sphere;
      disc += turn * face.disc;
    }
    // Signed by the side of the face the centre is on.
    const double area = (h > 0 ? 1 : -1) * r * r * sphere;
    total.area += area;
    total.volume += (r * area + h * disc) / 3;
  }
  return total;
}

}  // namespace alpha
